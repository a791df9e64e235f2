package io.concord.console;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Inbox;
import io.concord.core.agent.TickerBehaviour;
import io.concord.layers.Platform;
import io.concord.layers.observe.ObserverLayer;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.platform.ServiceDescription;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.Collection;
import java.util.Deque;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The console's agent: a member of the platform like any other. It reads the lists from its own
 * container layer, sniffs the agents the browsers picked and asks agents for their status through
 * their observation service (over the platform, never the network), and publishes what it learns
 * to the {@link Hub}. Everything here runs on the agents' loop.
 */
final class ConsoleAgent extends Agent {
    static final long TICK_MS = 500;
    static final long RENEW_MS = ObserverLayer.LEASE_MS / 3;
    static final long STATUS_MS = 2_000;
    /** Agents asked for their status in one round, and sniffed at once, at most. */
    static final int MAX_ASKED = 256;
    static final int MAX_SNIFFED = 64;
    private static final long MINUTE_MS = 60_000;

    private final Hub hub;
    private final List<ConsoleView> views;
    private final ObjectMapper json = new ObjectMapper();
    /** Agent name to when its sniff subscription was last renewed (epoch ms). */
    private final Map<String, Long> sniffing = new HashMap<>();
    /** Agent name to its last status and its drop totals by threat over the last minute. */
    private final Map<String, JsonNode> status = new TreeMap<>();
    private final Map<String, Deque<long[]>> history = new HashMap<>();
    private final Map<String, Long> viewDue = new HashMap<>();
    final AtomicLong malformed = new AtomicLong();
    private boolean listsChanged = true;
    private String container;
    private long term = -1;
    private long containerSinceMs;
    private long statusDue;
    private long conversations;

    ConsoleAgent(Hub hub, List<ConsoleView> views) {
        this.hub = hub;
        this.views = views;
    }

    @Override
    protected void setup() {
        Inbox.each(this, MessageTemplate.matchOntology(ObserverLayer.ONTOLOGY), this::take);
        addBehaviour(new TickerBehaviour(this, TICK_MS) {
            @Override
            protected void onTick() {
                tick();
            }
        });
        // A change only marks the lists dirty (and notes when the container changed): the event is
        // built at most once a tick, however many changes a tick sees.
        Platform.containerLayer(runtime(), getAID()).addListener(c -> {
            listsChanged = true;
            if (c.containerName() != null && (!c.containerName().equals(container) || c.term() != term)) {
                container = c.containerName();
                term = c.term();
                containerSinceMs = currentTimeMillis();
            }
        });
    }

    /** A new platform event, if the lists changed since the last one. */
    private void platform() {
        ContainerLayer c = Platform.containerLayer(runtime(), getAID());
        if (c == null || !listsChanged) {
            return;
        }
        listsChanged = false;
        ObjectNode o = json.createObjectNode();
        o.put("platform", runtime().platformName());
        o.put("console", getAID().name());
        o.put("role", c.role().name());
        o.put("container", c.containerName());
        o.put("term", c.term());
        o.put("containerSinceMs", containerSinceMs);
        o.set("lal", entries(c.agents()));
        o.set("gal", entries(c.globalAgents()));
        ArrayNode f = o.putArray("facilitators");
        c.facilitators().forEach(f::add);
        hub.publish("platform", o.toString());
    }

    private ArrayNode entries(Collection<AgentEntry> list) {
        ArrayNode a = json.createArrayNode();
        for (AgentEntry e : list) {
            ObjectNode n = a.addObject();
            n.put("name", e.name());
            n.put("address", e.address());
            n.put("startMs", e.startMs());
            ArrayNode s = n.putArray("services");
            for (ServiceDescription d : e.services()) {
                s.addObject().put("type", d.type()).put("name", d.name());
            }
        }
        return a;
    }

    private Set<String> known() {
        ContainerLayer c = Platform.containerLayer(runtime(), getAID());
        Set<String> all = new LinkedHashSet<>();
        if (c != null) {
            c.agents().forEach(e -> all.add(e.name()));
            c.globalAgents().forEach(e -> all.add(e.name()));
        }
        all.remove(getAID().name());
        return all;
    }

    private void tick() {
        platform();
        if (hub.open() == 0 && sniffing.isEmpty()) {
            return;   // nobody watches: nothing to ask the agents
        }
        long now = currentTimeMillis();
        Set<String> known = known();
        // Sniffing: what the open browsers picked, renewed before the lease ends.
        Set<String> want = new LinkedHashSet<>();
        for (String a : hub.sniffed(known)) {
            if (want.size() >= MAX_SNIFFED) {
                break;
            }
            if (!a.equals(getAID().name())) {
                want.add(a);
            }
        }
        for (String a : want) {
            Long at = sniffing.get(a);
            if (at == null || now - at >= RENEW_MS) {
                sniffing.put(a, now);
                send(observe(Performative.SUBSCRIBE, a, "sniff", "sniff-" + a));
            }
        }
        for (Iterator<Map.Entry<String, Long>> it = sniffing.entrySet().iterator(); it.hasNext(); ) {
            Map.Entry<String, Long> e = it.next();
            if (!want.contains(e.getKey())) {
                it.remove();
                send(observe(Performative.CANCEL, e.getKey(), "sniff", "sniff-" + e.getKey()));
            }
        }
        // Status: while a browser shows the safety view.
        if (hub.wants("safety") && now >= statusDue) {
            statusDue = now + STATUS_MS;
            int n = 0;
            for (String a : known) {
                if (n++ >= MAX_ASKED) {
                    break;
                }
                send(observe(Performative.QUERY_REF, a, "status", "status-" + (++conversations)));
            }
            status.put(getAID().name(), parse(selfStatus()));
            status.keySet().retainAll(withSelf(known));
            history.keySet().retainAll(withSelf(known));
            publishSafety(now);
        }
        for (ConsoleView v : views) {
            String topic = "view-" + v.id();
            if (hub.wants(topic) && now >= viewDue.getOrDefault(v.id(), 0L)) {
                viewDue.put(v.id(), now + v.periodMs());
                hub.publish(topic, v.snapshot());
            }
        }
    }

    private Set<String> withSelf(Set<String> known) {
        Set<String> s = new LinkedHashSet<>(known);
        s.add(getAID().name());
        return s;
    }

    private String selfStatus() {
        ObserverLayer o = runtime().layer(getAID(), ObserverLayer.class);
        return o == null ? null : o.status();
    }

    private AclMessage observe(Performative p, String to, String content, String conversation) {
        AclMessage m = new AclMessage(p);
        m.addReceiver(new AID(to));
        m.setOntology(ObserverLayer.ONTOLOGY);
        m.setConversationId(conversation);
        m.setContent(content);
        return m;
    }

    private JsonNode parse(String s) {
        if (s == null) {
            return null;
        }
        try {
            JsonNode n = json.readTree(s);
            return n != null && n.isObject() ? n : null;
        } catch (IOException e) {
            return null;
        }
    }

    private void take(AclMessage m) {
        if (m.getPerformative() != Performative.INFORM || m.getSender() == null) {
            return;   // AGREEs to subscriptions, anything else: nothing to show
        }
        String conv = m.getConversationId() == null ? "" : m.getConversationId();
        JsonNode n = parse(m.getContent());
        if (n == null) {
            malformed.incrementAndGet();
            return;
        }
        String by = m.getSender().name();
        if (conv.startsWith("sniff-")) {
            if (!sniffing.containsKey(by)) {
                return;   // a late event of a subscription given up
            }
            ObjectNode e = json.createObjectNode();
            e.put("by", by);
            e.put("dir", n.path("dir").asText());
            e.put("atMs", n.path("atMs").asLong());
            e.put("from", n.path("from").asText());
            e.put("to", n.path("to").asText());
            e.put("performative", n.path("performative").asText());
            e.put("conversation", n.path("conversation").asText(""));
            e.put("message", n.path("message").asText());
            if (n.path("missed").asLong() > 0) {
                e.put("missed", n.path("missed").asLong());
            }
            hub.sniff(by, e.path("from").asText(), e.path("to").asText(), e.path("conversation").asText(), e.toString());
        } else if (conv.startsWith("status-")) {
            if (!by.equals(n.path("agent").asText())) {
                malformed.incrementAndGet();   // an agent answers for itself only
                return;
            }
            status.put(by, n);
        }
    }

    private void publishSafety(long now) {
        ObjectNode o = json.createObjectNode();
        o.put("atMs", now);
        ArrayNode threats = o.putArray("threats");
        Threats.ORDER.forEach(threats::add);
        ArrayNode agents = o.putArray("agents");
        for (Map.Entry<String, JsonNode> e : status.entrySet()) {
            JsonNode s = e.getValue();
            if (s == null) {
                continue;
            }
            ObjectNode a = agents.addObject();
            a.put("agent", e.getKey());
            a.put("role", s.path("role").asText(""));
            a.put("clockOffsetUs", s.path("clockOffsetUs").asLong());
            a.put("clockSynced", s.path("clockSynced").asBoolean());
            Map<String, Long> byThreat = new LinkedHashMap<>();
            Threats.ORDER.forEach(t -> byThreat.put(t, 0L));
            ObjectNode layers = a.putObject("layers");
            ObjectNode threatOf = a.putObject("threatOf");
            s.path("drops").fields().forEachRemaining(l -> {
                ObjectNode ln = layers.putObject(l.getKey());
                l.getValue().fields().forEachRemaining(r -> {
                    long v = r.getValue().asLong();
                    ln.put(r.getKey(), v);
                    threatOf.put(r.getKey(), Threats.of(r.getKey()));
                    byThreat.merge(Threats.of(r.getKey()), v, Long::sum);
                });
            });
            long[] totals = new long[Threats.ORDER.size() + 1];
            totals[0] = now;
            for (int i = 0; i < Threats.ORDER.size(); i++) {
                totals[i + 1] = byThreat.get(Threats.ORDER.get(i));
            }
            Deque<long[]> h = history.computeIfAbsent(e.getKey(), k -> new ArrayDeque<>());
            h.addLast(totals);
            while (h.size() > 1 && now - h.peekFirst()[0] > MINUTE_MS) {
                h.removeFirst();
            }
            // The oldest sample of the last minute: what came since is the last minute's count.
            long[] first = h.peekFirst();
            ObjectNode t = a.putObject("threats");
            ObjectNode r = a.putObject("perMinute");
            for (int i = 0; i < Threats.ORDER.size(); i++) {
                t.put(Threats.ORDER.get(i), totals[i + 1]);
                r.put(Threats.ORDER.get(i), h.size() < 2 ? 0 : totals[i + 1] - first[i + 1]);
            }
        }
        o.put("consoleDrops", hub.slowDrops.get());
        o.put("consoleMalformed", malformed.get());
        hub.publish("safety", o.toString());
    }
}
