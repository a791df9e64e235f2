package io.concord.jade;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.content.AbsCompound;
import io.concord.core.content.AbsObject;
import io.concord.core.content.AbsPrimitive;
import io.concord.core.content.Action;
import io.concord.core.content.ContentException;
import io.concord.core.content.Done;
import io.concord.core.content.FipaAgentManagement;
import io.concord.core.content.FipaAgentManagement.AmsAgentDescription;
import io.concord.core.content.FipaAgentManagement.DfAgentDescription;
import io.concord.core.content.FipaAgentManagement.Deregister;
import io.concord.core.content.FipaAgentManagement.Property;
import io.concord.core.content.FipaAgentManagement.Register;
import io.concord.core.content.FipaAgentManagement.Search;
import io.concord.core.content.Ontology;
import io.concord.core.content.Result;
import io.concord.core.content.SlCodec;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.GatewayContext;
import io.concord.layers.platform.ServiceDescription;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;

/**
 * The platform's DF and AMS as JADE agents ask them, in FIPA-SL ({@code fipa-sl0} as JADE's
 * {@code DFService} writes it) with the ontology {@code FIPA-Agent-Management}, read and written
 * with Concord's content package ({@link SlCodec}, {@link FipaAgentManagement}): search (the
 * platform's lists, through the gateway context, and the foreign agents registered here), register
 * and deregister (foreign agents only: a Concord agent registers through its own container).
 * Called on the loop.
 */
final class AgentManagement {
    static final String ONTOLOGY = FipaAgentManagement.NAME;
    private static final Ontology ONTO = FipaAgentManagement.ontology();
    private static final SlCodec SL = new SlCodec();

    /** An agent of another platform registered in this platform's DF. */
    record ForeignEntry(AID aid, List<ServiceDescription> services) {
    }

    /**
     * What agents of other platforms may make the DF hold: registrations per sender (the agent
     * that asked) and in all, and the size of a search's answer (JADE's {@code max-results}, with
     * JADE's default when a search gives none).
     */
    record Limits(int perSender, int total, int defaultResults, int maxResults) {
        static final Limits DEFAULT = new Limits(64, 4_096, 100, 1_000);

        Limits {
            if (perSender < 1 || total < perSender || defaultResults < 1 || maxResults < defaultResults) {
                throw new IllegalArgumentException("DF limits must be positive and in order: " + perSender + " per sender, "
                        + total + " in all, " + defaultResults + " results by default, at most " + maxResults);
            }
        }
    }

    private final Map<String, ForeignEntry> foreignRegistrations = new LinkedHashMap<>();
    /** Who registered each entry (the sender's name, lower case), and until when (epoch ms; MAX_VALUE: no lease). */
    private final Map<String, String> registrant = new LinkedHashMap<>();
    private final Map<String, Long> leaseUntil = new LinkedHashMap<>();
    private final Map<String, Integer> perSender = new LinkedHashMap<>();
    private final Supplier<List<String>> acc;
    private final java.util.function.LongSupplier epochMs;
    private final Limits limits;
    private final java.util.function.BiConsumer<String, String> refused;

    /** @param acc the addresses of this platform's ACC: Concord agents are described as reached there */
    AgentManagement(Supplier<List<String>> acc) {
        this(acc, System::currentTimeMillis, Limits.DEFAULT, (r, w) -> { });
    }

    /**
     * @param epochMs the clock lease times are read on
     * @param refused told of each registration refused for a limit ({@code df-limit}) with why
     */
    AgentManagement(Supplier<List<String>> acc, java.util.function.LongSupplier epochMs, Limits limits,
                    java.util.function.BiConsumer<String, String> refused) {
        this.acc = acc;
        this.epochMs = epochMs;
        this.limits = limits;
        this.refused = refused;
    }

    /** Foreign registrations held now (after expiring the leases that ended). */
    int registrations() {
        expire(epochMs.getAsLong());
        return foreignRegistrations.size();
    }

    /** The answer to a REQUEST to this platform's DF ({@code df}) or AMS, to send back to its sender. */
    AclMessage answer(GatewayContext ctx, AclMessage m, boolean df) {
        AclMessage r = m.createReply();
        r.setSender(AID.local(df ? "df" : "ams", ctx.platformName()));
        r.setLanguage(m.getLanguage() == null ? "fipa-sl0" : m.getLanguage());
        r.setOntology(ONTOLOGY);
        String text = m.getContent() == null ? "" : m.getContent();
        AbsCompound actionAbs;
        try {
            if (m.getPerformative() != Performative.REQUEST) {
                throw new ContentException("the " + (df ? "DF" : "AMS") + " takes REQUESTs, not "
                        + m.getPerformative().wireName());
            }
            List<AbsObject> elements = SL.read(text);
            if (elements.size() != 1 || !(elements.get(0) instanceof AbsCompound a) || !a.name().equals("action")
                    || a.isNamed() || a.slots().size() != 2 || !(a.slots().get(1).value() instanceof AbsCompound)) {
                throw new ContentException("expected ((action <agent-identifier> (<function> ...)))");
            }
            actionAbs = a;
        } catch (ContentException e) {
            r.setPerformative(Performative.NOT_UNDERSTOOD);
            r.setContent(write(List.of(new AbsPrimitive(text), error("error", e.reason())),
                    List.of(error("error", e.reason()))));
            return r;
        }
        String function = ((AbsCompound) actionAbs.slots().get(1).value()).name();
        try {
            if (ONTO.schema(function) == null) {
                throw new UnsupportedOperationException(function);
            }
            Action action;
            try {
                action = (Action) ONTO.fromAbs(actionAbs);
            } catch (ContentException e) {
                r.setPerformative(Performative.NOT_UNDERSTOOD);
                r.setContent(write(List.of(new AbsPrimitive(text), error("error", e.reason())),
                        List.of(error("error", e.reason()))));
                return r;
            }
            Object content;
            if (action.action() instanceof Search s) {
                content = new Result(action, df ? searchDf(ctx, s) : searchAms(ctx, s));
            } else if (df && action.action() instanceof Register reg) {
                register(reg.description(), m.getSender(), ctx.platformName());
                content = new Done(action);
            } else if (df && action.action() instanceof Deregister d) {
                deregister(d.description(), m.getSender());
                content = new Done(action);
            } else if (action.action() instanceof Register || action.action() instanceof Deregister) {
                throw new UnsupportedOperationException(function + " with the AMS");
            } else {
                throw new UnsupportedOperationException(function);
            }
            r.setPerformative(Performative.INFORM);
            r.setContent(SL.write(ONTO.toAbs(content)));
        } catch (UnsupportedOperationException e) {
            r.setPerformative(Performative.FAILURE);
            r.setContent(write(List.of(actionAbs, error("unsupported-function", e.getMessage())), List.of(actionAbs)));
        } catch (IllegalArgumentException | ContentException e) {
            r.setPerformative(Performative.FAILURE);
            String why = e instanceof ContentException c ? c.reason() : e.getMessage();
            r.setContent(write(List.of(actionAbs, error("internal-error", why)), List.of(actionAbs)));
        }
        return r;
    }

    private static AbsCompound error(String name, String why) {
        return AbsCompound.positional(name, new AbsPrimitive(why));
    }

    /** The elements in SL, or the fallback's when the writer refuses one (a string it cannot quote). */
    private static String write(List<AbsObject> elements, List<AbsObject> fallback) {
        try {
            return SL.write(elements);
        } catch (ContentException e) {
            try {
                return SL.write(fallback);
            } catch (ContentException again) {
                return "((internal-error))";
            }
        }
    }

    private List<Object> searchDf(GatewayContext ctx, Search s) {
        if (!(s.description() instanceof DfAgentDescription template)) {
            throw new IllegalArgumentException("search needs a df-agent-description template");
        }
        expire(epochMs.getAsLong());
        List<ServiceDescription> templates = services(template.services());
        long max = maxResults(s);
        List<Object> out = new ArrayList<>();
        for (AgentEntry e : ctx.search(templates)) {
            if (out.size() >= max) {
                return out;
            }
            out.add(describe(new AID(e.name(), acc.get().toArray(new String[0])), e.services()));
        }
        for (ForeignEntry f : foreignRegistrations.values()) {
            if (out.size() >= max) {
                return out;
            }
            if (ServiceDescription.offersAll(f.services(), templates)) {
                out.add(describe(f.aid(), f.services()));
            }
        }
        return out;
    }

    /** A search's {@code max-results}: JADE's default when none is given or it is negative, never past the cap. */
    private long maxResults(Search s) {
        Long asked = s.constraints() == null ? null : s.constraints().maxResults();
        return asked == null || asked < 0 ? limits.defaultResults() : Math.min(asked, limits.maxResults());
    }

    private List<Object> searchAms(GatewayContext ctx, Search s) {
        long max = maxResults(s);
        List<Object> out = new ArrayList<>();
        for (AgentEntry e : ctx.agents()) {
            if (out.size() >= max) {
                break;
            }
            out.add(new AmsAgentDescription(new AID(e.name(), acc.get().toArray(new String[0])), null, "active"));
        }
        return out;
    }

    /** Forgets the registrations whose lease has ended. */
    private void expire(long now) {
        if (leaseUntil.isEmpty()) {
            return;
        }
        for (var it = leaseUntil.entrySet().iterator(); it.hasNext(); ) {
            var e = it.next();
            if (e.getValue() <= now) {
                it.remove();
                forget(e.getKey());
            }
        }
    }

    private void forget(String key) {
        foreignRegistrations.remove(key);
        String by = registrant.remove(key);
        if (by != null) {
            perSender.computeIfPresent(by, (k, n) -> n <= 1 ? null : n - 1);
        }
        leaseUntil.remove(key);
    }

    private void register(Object description, AID sender, String platform) {
        if (!(description instanceof DfAgentDescription d) || d.name() == null) {
            throw new IllegalArgumentException("register needs a df-agent-description with a :name");
        }
        if (platform.equalsIgnoreCase(d.name().platform())) {
            throw new IllegalArgumentException(d.name().name() + " is an agent of this platform: it registers through its own "
                    + "container, never over HTTP");
        }
        if (sender == null || !d.name().name().equalsIgnoreCase(sender.name())) {
            throw new IllegalArgumentException("an agent of another platform registers itself only: the description names "
                    + d.name().name() + ", the request comes from " + (sender == null ? "nobody" : sender.name()));
        }
        long now = epochMs.getAsLong();
        expire(now);
        String key = d.name().name().toLowerCase(Locale.ROOT);
        String by = sender.name().toLowerCase(Locale.ROOT);
        String holder = registrant.get(key);
        if (holder != null && !holder.equals(by)) {
            throw new IllegalArgumentException("already-registered: " + d.name().name() + " was registered by another agent");
        }
        if (d.leaseTime() != null && d.leaseTime().toEpochMilli() <= now) {
            throw new IllegalArgumentException("the lease-time " + d.leaseTime() + " has passed already");
        }
        if (holder == null) {
            int mine = perSender.getOrDefault(by, 0);
            if (mine >= limits.perSender()) {
                String why = by + " has " + mine + " registrations in the DF, the most one agent of another platform may hold;"
                        + " deregister some, or give lease times";
                refused.accept("df-limit", why);
                throw new IllegalArgumentException(why);
            }
            if (foreignRegistrations.size() >= limits.total()) {
                String why = "the DF holds " + limits.total() + " registrations of agents of other platforms, the most it takes";
                refused.accept("df-limit", why);
                throw new IllegalArgumentException(why);
            }
            perSender.merge(by, 1, Integer::sum);
            registrant.put(key, by);
        }
        foreignRegistrations.put(key, new ForeignEntry(d.name(), services(d.services())));
        if (d.leaseTime() != null) {
            leaseUntil.put(key, d.leaseTime().toEpochMilli());
        } else {
            leaseUntil.remove(key);
        }
    }

    private void deregister(Object description, AID sender) {
        if (!(description instanceof DfAgentDescription d) || d.name() == null) {
            throw new IllegalArgumentException("deregister needs a df-agent-description with a :name");
        }
        expire(epochMs.getAsLong());
        String key = d.name().name().toLowerCase(Locale.ROOT);
        String holder = registrant.get(key);
        if (holder == null) {
            throw new IllegalArgumentException("not-registered");
        }
        if (sender == null || !holder.equals(sender.name().toLowerCase(Locale.ROOT))) {
            throw new IllegalArgumentException("unauthorised: " + d.name().name() + " was registered by another agent");
        }
        forget(key);
    }

    private static List<ServiceDescription> services(Set<FipaAgentManagement.ServiceDescription> set) {
        List<ServiceDescription> out = new ArrayList<>();
        if (set == null) {
            return out;
        }
        for (FipaAgentManagement.ServiceDescription sd : set) {
            Map<String, String> props = new LinkedHashMap<>();
            if (sd.properties() != null) {
                for (Property p : sd.properties()) {
                    if (p.value() != null) {
                        props.put(p.name(), String.valueOf(p.value()));
                    }
                }
            }
            out.add(new ServiceDescription(sd.type(), sd.name(), props, list(sd.ontologies()), list(sd.languages()),
                    list(sd.protocols())));
        }
        return out;
    }

    private static List<String> list(Set<String> s) {
        return s == null ? List.of() : List.copyOf(s);
    }

    private static Set<String> set(List<String> l) {
        return l.isEmpty() ? null : new LinkedHashSet<>(l);
    }

    private static DfAgentDescription describe(AID who, List<ServiceDescription> services) {
        Set<FipaAgentManagement.ServiceDescription> out = new LinkedHashSet<>();
        for (ServiceDescription s : services) {
            Set<Property> props = new LinkedHashSet<>();
            s.properties().forEach((k, v) -> props.add(new Property(k, v)));
            out.add(new FipaAgentManagement.ServiceDescription(s.name(), s.type(), null, set(s.protocols()),
                    set(s.languages()), set(s.ontologies()), props.isEmpty() ? null : props));
        }
        return new DfAgentDescription(who, out.isEmpty() ? null : out, null, null, null, null);
    }
}
