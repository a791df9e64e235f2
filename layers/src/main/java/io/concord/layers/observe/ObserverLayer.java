package io.concord.layers.observe;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.time.internal.TokenBucket;
import io.concord.layers.authority.Policy;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.temporal.TemporalLayer;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The agent's own observation service, on top of its stack: what the console (or any member of
 * the platform) may ask an agent about itself, in ACL, over the platform. It sits above the
 * container layer, so under class 7 only an authenticated member reaches it (the membership gate);
 * nothing here reads the network.
 *
 * <ul>
 * <li>{@code SUBSCRIBE}, ontology {@value #ONTOLOGY}, content {@code sniff}: AGREE, then for every
 * application message this agent sends or receives an INFORM to the subscriber (same
 * conversation id) whose content is one JSON event (see {@code docs/console.md}). A subscription
 * lasts {@link #LEASE_MS} and is renewed by subscribing again; CANCEL ends it. At most
 * {@link #MAX_SNIFFERS} subscribers; at most {@link #EVENTS_PER_SECOND} events a second each
 * (burst {@link #EVENT_BURST}), the rest counted ({@code sniff-limit}) and reported as
 * {@code missed} in the next event.</li>
 * <li>{@code QUERY-REF}, ontology {@value #ONTOLOGY}, content {@code status}: INFORM with this
 * agent's role, container and term, platform clock offset, its drops by layer and reason, where it
 * runs (host and process id), the messages it sent and got in its mailbox, its mailbox and its
 * loop's lag (how long a task due now waited for the loop when the question came).</li>
 * <li>{@code REQUEST}, ontology {@value #ONTOLOGY}, content {@code kill}: AGREE, then the agent is
 * deleted as its own {@code doDelete()} would (its {@code takeDown()} runs, it leaves the
 * platform's lists). JADE's AMS does the same for any agent of the platform; here, as everything
 * above the container layer, only a member of the platform reaches it (class 7: a key holder).</li>
 * </ul>
 *
 * <p>Who may ask is the {@link Policy}'s to decide: by default only a member of the platform; an
 * agent of another platform (over the HTTP MTP) is refused (REFUSE with the reason, counted as
 * {@code not-authorized}) unless an operator exposed that service to them ({@code -http-expose}).
 */
public final class ObserverLayer extends Layer {
    public static final String ONTOLOGY = "concord-observe";
    public static final long LEASE_MS = 30_000;
    public static final int MAX_SNIFFERS = 8;
    private int maxSniffers = MAX_SNIFFERS;
    public static final int EVENTS_PER_SECOND = 500;
    public static final int EVENT_BURST = 1_000;
    /** A sniffed message longer than this is cut in its event ({@code "cut": true}). */
    public static final int MAX_TEXT = 8 * 1024;

    private static final class Sniffer {
        final AID who;
        final String conversation;
        long untilNs;
        long missed;
        final TokenBucket bucket = new TokenBucket(EVENT_BURST, EVENTS_PER_SECOND);

        Sniffer(AID who, String conversation) {
            this.who = who;
            this.conversation = conversation;
        }
    }

    private static final String RATE_DETAIL = "more than " + EVENTS_PER_SECOND + " messages a second to report to a sniffer";

    private final Map<String, Sniffer> sniffers = new LinkedHashMap<>();
    private final Policy policy;
    /** Services this agent refuses to every other agent, members included, with why (an agent that drives a chair). */
    private final Map<Policy.Service, String> guarded = new java.util.EnumMap<>(Policy.Service.class);

    /** With the documented policy: members only. */
    public ObserverLayer() {
        this(Policy.defaults());
    }

    /** With the platform's policy (what it exposes to agents of other platforms). */
    public ObserverLayer(Policy policy) {
        this.policy = java.util.Objects.requireNonNull(policy, "policy");
    }

    /** Observation requests are this layer's own, and a sniffed agent's messages are reported here: both take the stacks. */
    @Override
    public boolean mayHandOver(AclMessage m) {
        return sniffers.isEmpty() && !ONTOLOGY.equals(m.getOntology());
    }
    private LayerContext ctx;
    private AID self;
    private static final long PID = ProcessHandle.current().pid();

    @Override
    public String name() {
        return "observer";
    }

    @Override
    public void start(LayerContext c) {
        this.ctx = c;
        ContainerLayer container = c.find(ContainerLayer.class);
        self = container != null && container.selfEntry() != null ? container.selfEntry().aid() : new AID(c.host().nodeName());
    }

    @Override
    public void stop(LayerContext c) {
        sniffers.clear();
    }

    /**
     * This agent refuses {@code service} to every agent, members of the platform included (a
     * control agent that drives a chair refuses {@code kill}: it is stopped where it runs, never by a
     * message that any holder of the platform key could send). The refusal says {@code why}; null
     * ends the guard. Loop only; a stack built without {@code Defence.AUTHORITY} ignores it.
     */
    public void guard(Policy.Service service, String why) {
        if (why == null) {
            guarded.remove(service);
        } else if (policy.checks()) {
            guarded.put(service, why);
        }
    }

    /** Subscribers now (tests, the console). */
    public int sniffers() {
        return sniffers.size();
    }

    /**
     * The most subscribers at once, {@link #MAX_SNIFFERS} unless changed here; a test lifts it to
     * show what the bound holds back (a flood of subscriptions kept whole). Loop only.
     */
    public ObserverLayer sniffLimit(int most) {
        if (most < 0) {
            throw new IllegalArgumentException("a sniffers' limit is 0 or more, got " + most);
        }
        this.maxSniffers = most;
        return this;
    }

    @Override
    public void onDown(LayerContext c, Envelope env) {
        AclMessage m = env.message();
        if (!sniffers.isEmpty() && m != null && !ONTOLOGY.equals(m.getOntology())) {
            event("sent", m, env.receiver());
        }
        c.passDown(env);
    }

    @Override
    public void onUp(LayerContext c, Envelope env) {
        AclMessage m = env.message();
        if (m != null && ONTOLOGY.equals(m.getOntology()) && m.getSender() != null) {
            switch (m.getPerformative()) {
                case SUBSCRIBE, QUERY_REF, CANCEL, REQUEST -> {
                    serve(m);
                    return;
                }
                default -> {
                    // an answer to this agent's own request: the agent's business
                }
            }
        }
        if (!sniffers.isEmpty() && m != null && !ONTOLOGY.equals(m.getOntology())) {
            event("received", m, self);
        }
        c.passUp(env);
    }

    private void serve(AclMessage m) {
        Policy.Service service = Policy.serviceOf(m);
        Policy.Decision d = policy.decide(Policy.principalOf(m, ctx.host().platformName()), service);
        String own = guarded.get(service);
        if (d.allowed() && own != null) {
            d = new Policy.Decision(false, own);
        }
        if (!d.allowed()) {
            ctx.host().drops().record(ctx.host().nodeName(), name(), "not-authorized", m.getSender().name() + ": " + d.reason());
            if (m.getPerformative() != Performative.CANCEL) {
                answer(m, Performative.REFUSE, "{\"reason\":" + Json.quote(d.reason()) + "}");
            }
            return;
        }
        String content = m.getContent() == null ? "" : m.getContent().trim();
        String key = m.getSender().name() + " " + m.getConversationId();
        if (m.getPerformative() == Performative.CANCEL) {
            sniffers.remove(key);
            return;
        }
        if (m.getPerformative() == Performative.SUBSCRIBE && content.equals("sniff")) {
            long now = ctx.nowNs();
            sniffers.values().removeIf(s -> s.untilNs - now < 0);
            Sniffer s = sniffers.get(key);
            if (s == null) {
                if (sniffers.size() >= maxSniffers) {
                    limit(m.getSender().name() + " asked to sniff " + self.name() + ", which has " + maxSniffers + " sniffers already");
                    answer(m, Performative.REFUSE, "{\"reason\":\"" + maxSniffers + " sniffers already\"}");
                    return;
                }
                s = new Sniffer(m.getSender(), m.getConversationId());
                sniffers.put(key, s);
            }
            s.untilNs = now + LEASE_MS * 1_000_000;
            answer(m, Performative.AGREE, "{\"lease-ms\":" + LEASE_MS + "}");
            return;
        }
        if (m.getPerformative() == Performative.QUERY_REF && content.equals("status")) {
            // The answer waits for the loop as a task due now does: how long it waited is the loop's lag.
            long asked = ctx.nowNs();
            ctx.host().schedule(asked, () -> answer(m, Performative.INFORM, status(Math.max(0, ctx.nowNs() - asked) / 1_000_000)));
            return;
        }
        if (m.getPerformative() == Performative.REQUEST && content.equals("kill")) {
            answer(m, Performative.AGREE, "{\"kill\":\"" + self.name() + " leaves the platform\"}");
            ctx.host().deleteAgent();
            return;
        }
        answer(m, Performative.NOT_UNDERSTOOD, "{\"reason\":\"" + ONTOLOGY + " knows SUBSCRIBE sniff, CANCEL, QUERY-REF status and REQUEST kill\"}");
    }

    /** This agent's status as JSON (its loop's lag not measured: 0). */
    public String status() {
        return status(0);
    }

    private String status(long lagMs) {
        StringBuilder b = new StringBuilder(256).append('{');
        Json.field(b, "agent", self.name()).append(',');
        io.concord.core.net.Address at = ctx.host().localAddress();
        Json.field(b, "host", at == null ? null : at.host()).append(',');
        // Counted by the node, so that messages handed over in memory (which skip the stacks) count too.
        b.append("\"pid\":").append(PID).append(",\"sent\":").append(ctx.host().messagesSent())
                .append(",\"received\":").append(ctx.host().messagesReceived())
                .append(",\"mailbox\":").append(ctx.host().mailboxSize()).append(",\"lagMs\":").append(lagMs).append(',');
        ContainerLayer c = ctx.find(ContainerLayer.class);
        if (c != null) {
            Json.field(b, "role", c.role().name()).append(',');
            Json.field(b, "container", c.containerName()).append(',');
            b.append("\"term\":").append(c.term()).append(',');
        }
        TemporalLayer t = ctx.find(TemporalLayer.class);
        if (t != null) {
            b.append("\"clockOffsetUs\":").append(t.clock().offsetUs()).append(",\"clockSynced\":").append(t.clock().isSynced()).append(',');
        }
        b.append("\"atMs\":").append(ctx.host().clock().epochMillis()).append(",\"drops\":{");
        boolean first = true;
        for (Map.Entry<String, Map<String, Long>> l : ctx.host().drops().snapshotByLayer().entrySet()) {
            if (!first) {
                b.append(',');
            }
            first = false;
            Json.string(b, l.getKey()).append(":{");
            boolean f2 = true;
            for (Map.Entry<String, Long> r : l.getValue().entrySet()) {
                if (!f2) {
                    b.append(',');
                }
                f2 = false;
                Json.string(b, r.getKey()).append(':').append(r.getValue());
            }
            b.append('}');
        }
        return b.append("}}").toString();
    }

    private void answer(AclMessage m, Performative p, String json) {
        AclMessage r = m.createReply().setPerformative(p);
        r.setContent(json);
        r.setSender(self);
        ctx.passDown(Envelope.outgoing(r, m.getSender(), null));
    }

    private void event(String dir, AclMessage m, AID to) {
        long now = ctx.nowNs();
        List<String> gone = null;
        String json = null;
        for (Map.Entry<String, Sniffer> e : sniffers.entrySet()) {
            Sniffer s = e.getValue();
            if (s.untilNs - now < 0) {
                (gone == null ? gone = new ArrayList<>() : gone).add(e.getKey());
                continue;
            }
            if (s.who.equals(m.getSender()) || s.who.equals(to)) {
                continue;   // the sniffer's own conversation with this agent is not news to it
            }
            if (!s.bucket.take(now)) {
                s.missed++;
                limit(RATE_DETAIL);   // a constant: the flooded path allocates nothing
                continue;
            }
            if (json == null) {
                json = eventJson(dir, m, to);
            }
            AclMessage inform = new AclMessage(Performative.INFORM);
            inform.addReceiver(s.who);
            inform.setSender(self);
            inform.setOntology(ONTOLOGY);
            inform.setConversationId(s.conversation);
            inform.setContent(s.missed == 0 ? json : json.substring(0, json.length() - 1) + ",\"missed\":" + s.missed + "}");
            long missed = s.missed;
            s.missed = 0;
            try {
                ctx.passDown(Envelope.outgoing(inform, s.who, null).report());
            } catch (io.concord.core.layer.SendRejectedException behind) {
                // The sniffer is behind (slow, stopped, gone): the event is counted where it was
                // refused and reported as missed in the next one that goes; the agent's own message,
                // whose event this was, goes on, and nothing waits for the sniffer.
                s.missed = missed + 1;
            }
        }
        if (gone != null) {
            gone.forEach(sniffers::remove);
        }
    }

    /** Counts what the service refused to do ({@code sniff-limit}). */
    private void limit(String detail) {
        ctx.host().drops().record(ctx.host().nodeName(), name(), "sniff-limit", detail);
    }

    private String eventJson(String dir, AclMessage m, AID to) {
        String text = m.toString();
        boolean cut = text.length() > MAX_TEXT;
        StringBuilder b = new StringBuilder(text.length() + 256).append('{');
        Json.field(b, "dir", dir).append(',');
        Json.field(b, "by", self.name()).append(',');
        b.append("\"atMs\":").append(ctx.host().clock().epochMillis()).append(',');
        Json.field(b, "from", m.getSender() == null ? null : m.getSender().name()).append(',');
        Json.field(b, "to", to == null ? null : to.name()).append(',');
        Json.field(b, "performative", m.getPerformative().name().replace('_', '-')).append(',');
        Json.field(b, "conversation", m.getConversationId()).append(',');
        Json.field(b, "message", cut ? text.substring(0, MAX_TEXT) : text);
        if (cut) {
            b.append(",\"cut\":true");
        }
        return b.append('}').toString();
    }
}
