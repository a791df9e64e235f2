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
        // Anything else is an answer to a message an operator sent from the console (JADE's DummyAgent).
        Inbox.each(this, MessageTemplate.not(MessageTemplate.matchOntology(ObserverLayer.ONTOLOGY)), m -> mail("received", m));
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
        if (hub.open() == 0 && sniffing.isEmpty() && !hub.recording()) {
            return;   // nobody watches or records: nothing to ask the agents
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

    // ---- an operator's actions (JADE's RMA and DummyAgent); each runs on the loop ----------------

    /** The console's own actions, at {@code /api/agents/{action}}. */
    static final List<String> ACTIONS = List.of("start", "kill", "send", "compose", "parse");
    /** Messages the console sent and received, kept for the page. */
    static final int MAIL_KEPT = 100;
    private final Deque<ObjectNode> mail = new ArrayDeque<>();

    String act(String action, Map<String, String> p, io.concord.layers.Platform platform) {
        return switch (action) {
            case "start" -> start(platform, p.getOrDefault("name", "").trim(), p.getOrDefault("class", "").trim(),
                    p.getOrDefault("arguments", ""));
            case "kill" -> kill(p.getOrDefault("agent", "").trim());
            case "send" -> sendFor(p);
            case "compose" -> compose(p);
            case "parse" -> parseMessage(p.getOrDefault("text", ""));
            default -> throw new IllegalArgumentException("the console's actions are " + ACTIONS + ", not " + action);
        };
    }

    private String start(io.concord.layers.Platform platform, String name, String cls, String arguments) {
        if (!name.matches("[A-Za-z0-9][A-Za-z0-9._-]{0,63}")) {
            throw new IllegalArgumentException("an agent's name is 1 to 64 of letters, digits, '.', '_' and '-', got '" + name + "'");
        }
        Class<?> c;
        try {
            c = Class.forName(cls, false, ConsoleAgent.class.getClassLoader());
        } catch (ClassNotFoundException | LinkageError e) {
            throw new IllegalArgumentException("no class " + cls + " on this JVM's class path (give its full name, e.g. io.concord.examples.BookSeller)");
        }
        if (!Agent.class.isAssignableFrom(c) || java.lang.reflect.Modifier.isAbstract(c.getModifiers())) {
            throw new IllegalArgumentException(cls + " is not an agent: it must be a concrete subclass of " + Agent.class.getName());
        }
        Agent a;
        try {
            a = (Agent) c.getConstructor().newInstance();
        } catch (NoSuchMethodException e) {
            throw new IllegalArgumentException(cls + " has no public constructor without parameters; its arguments come from the form");
        } catch (ReflectiveOperationException e) {
            throw new IllegalArgumentException(cls + " could not be made: " + (e.getCause() == null ? e : e.getCause()));
        }
        Object[] args = arguments.isBlank() ? new Object[0] : java.util.Arrays.stream(arguments.split(",")).map(String::trim).toArray();
        AID aid;
        try {
            aid = platform.startAgent(name, a, args);
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw new IllegalArgumentException("could not start " + name + ": " + e.getMessage());
        }
        return "started " + aid.name() + " (" + cls + ") in the console's JVM";
    }

    private String kill(String name) {
        if (name.isEmpty()) {
            throw new IllegalArgumentException("say which agent to kill");
        }
        if (name.equals(getAID().name()) || name.equals(getAID().localName())) {
            throw new IllegalArgumentException("the console does not kill itself; close it instead");
        }
        String full = listed(name, known());
        for (AID here : runtime().agents()) {
            if (here.name().equals(full)) {
                runtime().agent(here).doDelete();
                return "killed " + full + " (in the console's JVM): its takeDown() runs and it leaves the lists";
            }
        }
        send(observe(Performative.REQUEST, full, "kill", "kill-" + (++conversations)));
        return "asked " + full + " to leave the platform (it runs in another JVM); it goes from the lists when it has";
    }

    /** An agent's full name in the lists, from its full or its local name. */
    private static String listed(String name, Set<String> known) {
        String full = known.contains(name) ? name : known.stream().filter(k -> k.startsWith(name + "@")).findFirst().orElse(null);
        if (full == null) {
            throw new IllegalArgumentException("no agent " + name + " in the platform's lists");
        }
        return full;
    }

    /**
     * The platform's DF or AMS by its local or full name ({@code df}, {@code ams@hospital}), as
     * JADE's DummyAgent reaches them: not agents of the lists, the container answers for them. Null otherwise.
     */
    private AID service(String name) {
        String platform = getAID().platform();
        for (String s : new String[] {"df", "ams"}) {
            if (name.equalsIgnoreCase(s) || name.equalsIgnoreCase(s + "@" + platform)) {
                return AID.local(s, platform);
            }
        }
        return null;
    }

    /**
     * The message the send form describes. {@code listed}: receivers must be in the platform's lists
     * (to send it), or any name, taken as a local name of this platform without '@' (to save it).
     */
    private AclMessage fromForm(Map<String, String> p, boolean listed) {
        Performative perf = Performative.fromWireName(p.getOrDefault("performative", "").trim());
        if (perf == null) {
            throw new IllegalArgumentException("no performative '" + p.get("performative") + "'; FIPA's are INFORM, REQUEST, QUERY-REF, CFP, ...");
        }
        AclMessage m = new AclMessage(perf);
        Set<String> known = listed ? known() : Set.of();
        for (String r : p.getOrDefault("receivers", "").split(",")) {
            String n = r.trim();
            if (n.isEmpty()) {
                continue;
            }
            m.addReceiver(service(n) != null ? service(n) : listed ? new AID(listed(n, known))
                    : n.contains("@") ? new AID(n) : AID.local(n, getAID().platform()));
        }
        if (m.getReceivers().isEmpty()) {
            throw new IllegalArgumentException("say who receives it: one or more agents' names, separated by commas");
        }
        m.setContent(p.getOrDefault("content", ""));
        String conv = p.getOrDefault("conversation", "").trim();
        if (!conv.isEmpty()) {
            m.setConversationId(conv);
        }
        for (String[] f : new String[][] {{"language", "l"}, {"ontology", "o"}, {"protocol", "p"}, {"in-reply-to", "r"}}) {
            String v = p.getOrDefault(f[0], "").trim();
            if (!v.isEmpty()) {
                switch (f[1]) {
                    case "l" -> m.setLanguage(v);
                    case "o" -> m.setOntology(v);
                    case "r" -> m.setInReplyTo(v);
                    default -> m.setProtocol(v);
                }
            }
        }
        if (ObserverLayer.ONTOLOGY.equals(m.getOntology())) {
            throw new IllegalArgumentException("the ontology " + ObserverLayer.ONTOLOGY + " is the console's own; kill and sniff have their buttons");
        }
        return m;
    }

    /** The send form's message in FIPA's string form, to save in a file (JADE's DummyAgent's "save"). */
    private String compose(Map<String, String> p) {
        AclMessage m = fromForm(p, false);
        m.setSender(new AID(getAID().name()));   // its name only: the platform's own addresses are no part of a saved message
        return io.concord.core.codec.StringAclCodec.INSTANCE.encodeToString(m);
    }

    /**
     * A message in FIPA's string form (a saved one, or one the console received) as the send form's
     * fields, JSON: performative, receivers, content, conversation, language, ontology, protocol,
     * in-reply-to; and, to reply to it, its sender and reply-with. Refused with the parser's reason.
     */
    private String parseMessage(String text) {
        AclMessage m;
        try {
            m = io.concord.core.codec.StringAclCodec.INSTANCE.decode(text.strip());
        } catch (io.concord.core.codec.AclParseException e) {
            throw new IllegalArgumentException("not a FIPA ACL message in string form (" + e.getMessage()
                    + "); a saved message reads (REQUEST :receiver (set (agent-identifier :name df@platform)) :content \"...\")");
        }
        ObjectNode o = json.createObjectNode();
        o.put("performative", m.getPerformative().wireName());
        o.put("receivers", String.join(", ", m.getReceivers().stream().map(a -> a.platform().equals(getAID().platform()) ? a.localName() : a.name()).toList()));
        o.put("content", m.getContent() == null ? "" : m.getContent());
        o.put("conversation", m.getConversationId() == null ? "" : m.getConversationId());
        o.put("language", m.getLanguage() == null ? "" : m.getLanguage());
        o.put("ontology", m.getOntology() == null ? "" : m.getOntology());
        o.put("protocol", m.getProtocol() == null ? "" : m.getProtocol());
        o.put("in-reply-to", m.getInReplyTo() == null ? "" : m.getInReplyTo());
        o.put("sender", m.getSender() == null ? "" : m.getSender().platform().equals(getAID().platform()) ? m.getSender().localName() : m.getSender().name());
        o.put("reply-with", m.getReplyWith() == null ? "" : m.getReplyWith());
        return o.toString();
    }

    private String sendFor(Map<String, String> p) {
        AclMessage m = fromForm(p, true);
        Performative perf = m.getPerformative();
        if (m.getConversationId() == null) {
            m.setConversationId("console-" + (++conversations));
        }
        m.setReplyWith("console-r" + (++conversations));
        send(m);
        mail("sent", m);
        return "sent " + perf.wireName() + " to " + p.get("receivers").trim() + " (conversation " + m.getConversationId() + ")";
    }

    private void mail(String dir, AclMessage m) {
        ObjectNode e = json.createObjectNode();
        e.put("dir", dir);
        e.put("atMs", currentTimeMillis());
        e.put("performative", m.getPerformative().wireName());
        e.put("from", m.getSender() == null ? "" : m.getSender().name());
        e.put("conversation", m.getConversationId() == null ? "" : m.getConversationId());
        e.put("message", m.toString());
        mail.addLast(e);
        while (mail.size() > MAIL_KEPT) {
            mail.removeFirst();
        }
        ArrayNode a = json.createArrayNode();
        mail.forEach(a::add);
        hub.publish("mail", a.toString());
    }

    private void publishSafety(long now) {
        ObjectNode o = json.createObjectNode();
        o.put("atMs", now);
        ArrayNode threats = o.putArray("threats");
        Threats.ORDER.forEach(threats::add);
        ArrayNode expected = o.putArray("expected");
        Threats.EXPECTED.forEach(expected::add);
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
            // Where it runs and how it is doing: the platform view groups and shows these.
            a.put("host", s.path("host").asText(""));
            a.put("pid", s.path("pid").asLong());
            a.put("sent", s.path("sent").asLong());
            a.put("received", s.path("received").asLong());
            a.put("mailbox", s.path("mailbox").asLong());
            a.put("lagMs", s.path("lagMs").asLong());
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
