package io.concord.jade;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.GatewayContext;
import io.concord.layers.platform.ServiceDescription;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;

/**
 * The platform's DF and AMS as JADE agents ask them, in {@code fipa-sl0} with the ontology
 * {@code FIPA-Agent-Management}: search (the platform's lists, through the gateway context, and the
 * foreign agents registered here), register and deregister (foreign agents only: a Concord agent
 * registers through its own container). Called on the loop.
 */
final class AgentManagement {
    static final String ONTOLOGY = "FIPA-Agent-Management";

    /** An agent of another platform registered in this platform's DF. */
    record ForeignEntry(AID aid, List<ServiceDescription> services) {
    }

    private final Map<String, ForeignEntry> foreignRegistrations = new LinkedHashMap<>();
    private final Supplier<List<String>> acc;

    /** @param acc the addresses of this platform's ACC: Concord agents are described as reached there */
    AgentManagement(Supplier<List<String>> acc) {
        this.acc = acc;
    }


    /** The answer to a REQUEST to this platform's DF ({@code df}) or AMS, to send back to its sender. */
    AclMessage answer(GatewayContext ctx, AclMessage m, boolean df) {
        AclMessage r = m.createReply();
        r.setSender(AID.local(df ? "df" : "ams", ctx.platformName()));
        r.setLanguage(m.getLanguage() == null ? "fipa-sl0" : m.getLanguage());
        r.setOntology(ONTOLOGY);
        Sl0.Expr action;
        try {
            if (m.getPerformative() != Performative.REQUEST) {
                throw new IllegalArgumentException("the " + (df ? "DF" : "AMS") + " takes REQUESTs, not "
                        + m.getPerformative().wireName());
            }
            Sl0.Expr outer = Sl0.parse(m.getContent() == null ? "" : m.getContent());
            if (outer.items().size() != 1 || !(outer.items().get(0) instanceof Sl0.Expr a) || !a.head().equals("action")
                    || a.items().size() != 3 || !(a.items().get(2) instanceof Sl0.Expr)) {
                throw new IllegalArgumentException("expected ((action <agent-identifier> (<function> ...)))");
            }
            action = a;
        } catch (IllegalArgumentException e) {
            r.setPerformative(Performative.NOT_UNDERSTOOD);
            r.setContent("(" + Sl0.word(m.getContent() == null ? "" : m.getContent()) + " (error " + Sl0.word(e.getMessage()) + "))");
            return r;
        }
        Sl0.Expr fn = (Sl0.Expr) action.items().get(2);
        try {
            String content = switch (fn.head().toLowerCase(Locale.ROOT)) {
                case "search" -> "((result " + action + " (sequence " + (df ? searchDf(ctx, fn) : searchAms(ctx)) + ")))";
                case "register" -> {
                    if (!df) {
                        throw new UnsupportedOperationException("register with the AMS");
                    }
                    register(fn);
                    yield "((done " + action + "))";
                }
                case "deregister" -> {
                    if (!df) {
                        throw new UnsupportedOperationException("deregister with the AMS");
                    }
                    deregister(fn);
                    yield "((done " + action + "))";
                }
                default -> throw new UnsupportedOperationException(fn.head());
            };
            r.setPerformative(Performative.INFORM);
            r.setContent(content);
        } catch (UnsupportedOperationException e) {
            r.setPerformative(Performative.FAILURE);
            r.setContent("(" + action + " (unsupported-function " + Sl0.word(e.getMessage()) + "))");
        } catch (IllegalArgumentException e) {
            r.setPerformative(Performative.FAILURE);
            r.setContent("(" + action + " (internal-error " + Sl0.word(e.getMessage()) + "))");
        }
        return r;
    }

    private String searchDf(GatewayContext ctx, Sl0.Expr fn) {
        Sl0.Expr dfd = argument(fn);
        if (dfd == null || !dfd.head().equals("df-agent-description")) {
            throw new IllegalArgumentException("search needs a df-agent-description template");
        }
        List<ServiceDescription> templates = services(dfd.slot("services"));
        long max = maxResults(fn);
        StringBuilder b = new StringBuilder();
        int n = 0;
        for (AgentEntry e : ctx.search(templates)) {
            if (max < 0 || n < max) {
                b.append(n++ == 0 ? "" : " ").append(describe(new AID(e.name(), acc.get().toArray(new String[0])), e.services()));
            }
        }
        for (ForeignEntry f : foreignRegistrations.values()) {
            if (ServiceDescription.offersAll(f.services(), templates) && (max < 0 || n < max)) {
                b.append(n++ == 0 ? "" : " ").append(describe(f.aid(), f.services()));
            }
        }
        return b.toString();
    }

    private String searchAms(GatewayContext ctx) {
        StringBuilder b = new StringBuilder();
        for (AgentEntry e : ctx.agents()) {
            b.append(b.length() == 0 ? "" : " ").append("(ams-agent-description :name ")
                    .append(aid(new AID(e.name(), acc.get().toArray(new String[0])))).append(" :state active)");
        }
        return b.toString();
    }

    /** The function's first argument, if it is an expression (the df-agent-description). */
    private static Sl0.Expr argument(Sl0.Expr fn) {
        return fn.items().size() > 1 && fn.items().get(1) instanceof Sl0.Expr e ? e : null;
    }

    private static long maxResults(Sl0.Expr fn) {
        for (Object o : fn.items()) {
            if (o instanceof Sl0.Expr e && e.head().equals("search-constraints")) {
                String v = e.text("max-results");
                if (v != null) {
                    try {
                        return Long.parseLong(v);
                    } catch (NumberFormatException x) {
                        throw new IllegalArgumentException("a bad :max-results " + v);
                    }
                }
            }
        }
        return -1;
    }

    private void register(Sl0.Expr fn) {
        Sl0.Expr dfd = argument(fn);
        if (dfd == null || !(dfd.slot("name") instanceof Sl0.Expr name)) {
            throw new IllegalArgumentException("register needs a df-agent-description with a :name");
        }
        AID who = aidOf(name);
        foreignRegistrations.put(who.name().toLowerCase(Locale.ROOT), new ForeignEntry(who, services(dfd.slot("services"))));
    }

    private void deregister(Sl0.Expr fn) {
        Sl0.Expr dfd = argument(fn);
        if (dfd == null || !(dfd.slot("name") instanceof Sl0.Expr name)) {
            throw new IllegalArgumentException("deregister needs a df-agent-description with a :name");
        }
        if (foreignRegistrations.remove(aidOf(name).name().toLowerCase(Locale.ROOT)) == null) {
            throw new IllegalArgumentException("not-registered");
        }
    }

    private static AID aidOf(Sl0.Expr e) {
        if (!e.head().equals("agent-identifier") || e.text("name") == null) {
            throw new IllegalArgumentException("expected (agent-identifier :name ...)");
        }
        List<String> urls = new ArrayList<>();
        if (e.slot("addresses") instanceof Sl0.Expr seq) {
            for (Object o : seq.items().subList(1, seq.items().size())) {
                if (o instanceof Sl0.Atom a) {
                    urls.add(a.text());
                }
            }
        }
        return new AID(e.text("name"), urls.toArray(new String[0]));
    }

    private static List<ServiceDescription> services(Object set) {
        List<ServiceDescription> out = new ArrayList<>();
        if (set == null) {
            return out;
        }
        if (!(set instanceof Sl0.Expr s) || !s.head().equals("set")) {
            throw new IllegalArgumentException(":services must be a (set ...)");
        }
        for (Object o : s.items().subList(1, s.items().size())) {
            if (!(o instanceof Sl0.Expr sd) || !sd.head().equals("service-description")) {
                throw new IllegalArgumentException("a :services set holds service-descriptions");
            }
            Map<String, String> props = new LinkedHashMap<>();
            if (sd.slot("properties") instanceof Sl0.Expr ps) {
                for (Object p : ps.items().subList(1, ps.items().size())) {
                    if (p instanceof Sl0.Expr prop && prop.text("name") != null && prop.text("value") != null) {
                        props.put(prop.text("name"), prop.text("value"));
                    }
                }
            }
            out.add(new ServiceDescription(sd.text("type"), sd.text("name"), props, List.of(), List.of(), List.of()));
        }
        return out;
    }

    private static String describe(AID who, List<ServiceDescription> services) {
        StringBuilder b = new StringBuilder("(df-agent-description :name ").append(aid(who));
        if (!services.isEmpty()) {
            b.append(" :services (set");
            for (ServiceDescription s : services) {
                b.append(" (service-description");
                if (s.name() != null) {
                    b.append(" :name ").append(Sl0.word(s.name()));
                }
                if (s.type() != null) {
                    b.append(" :type ").append(Sl0.word(s.type()));
                }
                if (!s.properties().isEmpty()) {
                    b.append(" :properties (set");
                    s.properties().forEach((k, v) -> b.append(" (property :name ").append(Sl0.word(k))
                            .append(" :value ").append(Sl0.word(v)).append(')'));
                    b.append(')');
                }
                b.append(')');
            }
            b.append(')');
        }
        return b.append(')').toString();
    }

    private static String aid(AID a) {
        StringBuilder b = new StringBuilder("(agent-identifier :name ").append(Sl0.word(a.name()));
        if (!a.addresses().isEmpty()) {
            b.append(" :addresses (sequence");
            for (String u : a.addresses()) {
                b.append(' ').append(u);
            }
            b.append(')');
        }
        return b.append(')').toString();
    }
}
