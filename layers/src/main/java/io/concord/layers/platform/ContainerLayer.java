package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.layer.Router;
import io.concord.core.layer.SendRejectedException;
import io.concord.core.layer.StackHost;
import io.concord.core.layer.Tracer;
import io.concord.core.net.Address;
import io.concord.layers.frame.Frames;
import io.concord.layers.parser.Membership;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;

/**
 * The container layer (dissertation ch. 5): the top of every agent's stack on a platform with no
 * main container. Each agent carries it, so each can be elected container.
 *
 * <ul>
 * <li><b>Discovery</b>: the ports held in the agent's port range when it bound its own are its
 *     potential peers; it asks each "who is container" (QUERY-REF, to whoever holds the port).
 *     If none was found it is container at once.</li>
 * <li><b>Election</b>: when nobody knows a container, the oldest agent (then the lowest port)
 *     takes the role; the others exclude themselves and wait for its announcement; after three
 *     rounds without one, the lowest port wins.</li>
 * <li><b>LAL</b>: newcomers join (INFORM-REF, answered by CONFIRM with the period and timeout the
 *     container computed from the agent count); the container distributes the Local Agent List,
 *     packed into as few messages as fit, versioned by (term, container, sequence), and each agent
 *     CONFIRMs the version it holds.</li>
 * <li><b>Maintenance</b>: each period the container tells every agent it is alive (INFORM);
 *     agents CONFIRM; a silent agent is removed and the removal distributed. Agents that stop
 *     hearing the container elect the oldest agent left in their list, which takes the next term,
 *     asks every agent for its information (REQUEST) and redistributes the list.</li>
 * <li><b>White and yellow pages</b>: the container answers {@code ams@platform} and
 *     {@code df@platform}; each entry of the LAL carries its agent's services, so the yellow pages
 *     survive a failover. Names resolve through the LAL: no address is configured anywhere.</li>
 * </ul>
 *
 * <p>Platform messages are FIPA ACL with the ontology {@code concord-platform}; this layer takes
 * them off the way up, so agents never see them. A message from an agent of another platform is
 * dropped and counted ({@code foreign-platform}), as is a malformed one ({@code malformed-platform}).
 */
public final class ContainerLayer extends Layer {
    /** The agent's part in the platform. */
    public enum Role { SEEKING, MEMBER, CONTAINER, STOPPED }

    static final String ONTOLOGY = Membership.PLATFORM_ONTOLOGY;
    static final String LANGUAGE = "concord-lines";
    static final String P_DISCOVERY = "concord-discovery";
    static final String P_LAL = "concord-lal";
    static final String P_MAINTENANCE = "concord-maintenance";
    static final String P_SERVICES = "concord-services";

    private final PlatformConfig config;
    private final Federation federation;
    private final Gateway gateway;
    private boolean gatewayStarted;
    // The Global Agent List as this agent holds it: the other hosts' agents, from its container.
    private final TreeMap<String, AgentEntry> gal = new TreeMap<>();
    private long gseq;
    private String galFrom;
    private final Map<String, String[]> galPages = new HashMap<>();
    private String galPagesKey;
    private LayerContext ctx;
    private StackHost host;
    private String platform;
    private String self;
    private AgentEntry selfEntry;
    private AID selfAid;
    private AID amsAid;
    private AID dfAid;

    private Role role = Role.SEEKING;
    private long term;
    private long seq;
    private AgentEntry container;
    private final TreeMap<String, AgentEntry> lal = new TreeMap<>();
    private final Map<String, Router.Route> routes = new HashMap<>();
    // Routes of agents that left the lists lately, kept for ROUTE_GRACE_NS: a list that flickers (an
    // agent taken for dead on a starved machine, a host's container changing) does not turn a
    // message to a known name into a FAILURE. After the grace the name is unknown.
    private final LinkedHashMap<String, Router.Route> recentRoutes = new LinkedHashMap<>(16, 0.75f, true);
    private final Map<String, Long> recentSince = new HashMap<>();
    static final long ROUTE_GRACE_NS = 5_000_000_000L;

    // seeking
    private final Map<Address, Boolean> asked = new LinkedHashMap<>(); // neighbour -> answered
    private final Set<Address> sentTo = new HashSet<>();
    private final Map<String, AgentEntry> seekers = new HashMap<>();
    private long claimTerm = -1;
    private AgentEntry claim;
    private int round;
    private int attempt;
    private long discoveryTimer = -1;
    private long maxTermSeen;

    // joining
    private AgentEntry joinTarget;
    private int joinFailures;
    private long joinTimer = -1;

    // member
    private long watchTimer = -1;
    private long periodMs;
    private long timeoutMs;
    private final Set<String> suspects = new HashSet<>();
    private AgentEntry successor; // after a failover, the agent expected to take over
    private int failoverRounds;
    private final Map<String, String[]> pages = new HashMap<>();
    private String pagesKey;

    // container
    private final Map<String, Long> lastHeard = new HashMap<>();
    private final Map<String, Long> heldSeq = new HashMap<>();
    private long cycleTimer = -1;
    private long pushTimer = -1;
    private int cycles;
    private long cycleStartNs;
    private long cycleDueNs;
    private final Set<String> cycleAwaiting = new HashSet<>();
    private volatile long lastCycleNs = -1;

    // requests of the Java API
    private long requestCounter;
    private final List<Consumer<ContainerLayer>> listeners = new ArrayList<>();

    public ContainerLayer(PlatformConfig config) {
        this(config, NetworkConfig.defaults());
    }

    /** A container layer that also federates with the containers of other hosts. */
    public ContainerLayer(PlatformConfig config, NetworkConfig network) {
        this(config, network, null);
    }

    /** ... and reaches foreign platforms through a gateway (the JADE bridge), or none if {@code null}. */
    public ContainerLayer(PlatformConfig config, NetworkConfig network, Gateway gateway) {
        this.config = config;
        this.federation = network == null ? null : new Federation(this, network);
        this.gateway = gateway;
    }

    public ContainerLayer() {
        this(PlatformConfig.defaults());
    }

    @Override
    public String name() {
        return "container";
    }

    // ---- views ------------------------------------------------------------------------------------

    public Role role() {
        return role;
    }

    /** The container this agent follows (itself if it is the container), or {@code null}. */
    public String containerName() {
        return container == null ? null : container.name();
    }

    /** The LAL as this agent holds it, by name. Loop thread only. */
    public Collection<AgentEntry> agents() {
        return List.copyOf(lal.values());
    }

    /**
     * How long the last complete maintenance cycle took on the container: from its alive messages
     * to the last agent's confirmation, in ns; -1 if none completed yet. Safe from any thread.
     */
    public long lastCycleNs() {
        return lastCycleNs;
    }

    /** The Global Agent List as this agent holds it: agents of other hosts. Loop thread only. */
    public Collection<AgentEntry> globalAgents() {
        return List.copyOf(gal.values());
    }

    /** The other hosts' containers this container is in contact with (empty unless container). */
    public List<String> facilitators() {
        if (federation == null) {
            return List.of();
        }
        List<String> out = new ArrayList<>();
        for (Federation.Facilitator f : federation.facilitators().values()) {
            if (f.contacted) {
                out.add(f.entry.name());
            }
        }
        return out;
    }

    public long term() {
        return term;
    }

    public long lalSequence() {
        return seq;
    }

    /** This agent's own entry (its services included). */
    public AgentEntry selfEntry() {
        return selfEntry;
    }

    /** Calls back on the loop whenever the role, the container or the list changes. */
    public void addListener(Consumer<ContainerLayer> l) {
        listeners.add(l);
    }

    /** Searches the yellow pages in this agent's copy of the LAL (no message is sent). */
    public List<AgentEntry> search(ServiceDescription template) {
        List<AgentEntry> out = new ArrayList<>();
        List<AgentEntry> all = new ArrayList<>(lal.values());
        for (AgentEntry e : gal.values()) {
            if (!lal.containsKey(e.name())) {
                all.add(e);
            }
        }
        for (AgentEntry e : all) {
            for (ServiceDescription s : e.services()) {
                if (s.matches(template)) {
                    out.add(e);
                    break;
                }
            }
        }
        return out;
    }

    // ---- life cycle -------------------------------------------------------------------------------

    @Override
    public void init(LayerContext ctx) {
        this.ctx = ctx;
        this.host = ctx.host();
    }

    @Override
    public void start(LayerContext ctx) {
        platform = host.platformName();
        self = host.nodeName();
        Address at = host.localAddress();
        String uri = at == null ? "" : at.toUri(host.transport());
        selfEntry = new AgentEntry(self, uri, host.clock().epochMillis(), List.of());
        selfAid = selfEntry.aid();
        amsAid = AID.local("ams", platform);
        dfAid = AID.local("df", platform);
        host.setRouter(this::route);
        trace("start", "neighbours=" + host.neighbours().size());
        if (host.neighbours().isEmpty()) {
            becomeContainer(1, "no other agent holds a port of the range");
        } else {
            for (Address a : host.neighbours()) {
                asked.put(a, Boolean.FALSE);
            }
            beginDiscovery();
        }
    }

    @Override
    public void stop(LayerContext ctx) {
        Role was = role;
        cancelAll();
        if (federation != null) {
            federation.stop();
        }
        stopGateway();
        if (was == Role.CONTAINER) {
            for (AgentEntry e : lal.values()) {
                if (!e.name().equals(self)) {
                    sendQuietly(platformMessage(Performative.INFORM, P_MAINTENANCE, e.aid(),
                            Lines.content("leave", Lines.params("term", term), List.of())));
                }
            }
        } else if (was == Role.MEMBER && container != null && !container.name().equals(self)) {
            sendQuietly(platformMessage(Performative.INFORM, P_MAINTENANCE, container.aid(),
                    Lines.content("leave", Lines.params("term", term), List.of())));
        }
        role = Role.STOPPED;
        host.setRouter(null);
        publish();
    }

    private void cancelAll() {
        discoveryTimer = cancel(discoveryTimer);
        joinTimer = cancel(joinTimer);
        watchTimer = cancel(watchTimer);
        cycleTimer = cancel(cycleTimer);
        pushTimer = cancel(pushTimer);
    }

    long cancel(long timer) {
        if (timer >= 0) {
            host.cancel(timer);
        }
        return -1;
    }

    StackHost host() {
        return host;
    }

    long after(long ms, Runnable r) {
        return host.schedule(host.nowNs() + ms * 1_000_000L, r);
    }

    // ---- routing ----------------------------------------------------------------------------------

    private Router.Route route(AID receiver) {
        String name = receiver.name();
        Router.Route r = routes.get(name);
        if (r != null) {
            return r;
        }
        r = recentRoutes.get(name);
        if (r != null) {
            Long since = recentSince.get(name);
            if (since != null && host.nowNs() - since < ROUTE_GRACE_NS) {
                return r;
            }
            recentRoutes.remove(name);
            recentSince.remove(name);
        }
        if (gateway != null && container != null && !platform.equals(receiver.platform()) && gateway.reaches(receiver)) {
            Address a = container.transportAddress();
            return a == null ? null : new Router.Route(a, container.aid());
        }
        if (container != null && (name.equals(amsAid.name()) || name.equals(dfAid.name()))) {
            Address a = container.transportAddress();
            return a == null ? null : new Router.Route(a, container.aid());
        }
        return null;
    }

    private void rebuildRoutes() {
        long now = host.nowNs();
        for (Map.Entry<String, Router.Route> e : routes.entrySet()) {
            recentRoutes.put(e.getKey(), e.getValue());
            recentSince.put(e.getKey(), now);
        }
        while (recentRoutes.size() > 10_000) {
            String eldest = recentRoutes.keySet().iterator().next();
            recentRoutes.remove(eldest);
            recentSince.remove(eldest);
        }
        routes.clear();
        for (AgentEntry e : gal.values()) {
            Address a = e.transportAddress();
            if (a != null) {
                routes.put(e.name(), new Router.Route(a, e.aid()));
            }
        }
        for (AgentEntry e : lal.values()) {
            Address a = e.transportAddress();
            if (a != null) {
                routes.put(e.name(), new Router.Route(a, e.aid()));
            }
        }
    }

    // ---- up ---------------------------------------------------------------------------------------

    // ---- foreign platforms (gateway) ----------------------------------------------------------

    private static final String RELAY_OUT = "relay-out ";
    private static final String RELAY_IN = "relay-in ";

    /**
     * A message of this agent to a foreign receiver goes to the container, wrapped: the container's
     * gateway carries it out. The frame stays the container's, so identification holds.
     */
    @Override
    public void onDown(LayerContext ctx, Envelope env) {
        AID r = env.receiver();
        if (gateway != null && r != null && env.via() != null && env.message() != null
                && !ONTOLOGY.equals(env.message().getOntology()) && !platform.equals(r.platform())) {
            AclMessage wrapped = platformMessage(Performative.INFORM, P_SERVICES, env.via(),
                    RELAY_OUT + "receiver=" + Lines.escape(r.name()) + " addresses=" + Lines.escape(String.join(",", r.addresses()))
                            + "\n" + io.concord.core.codec.StringAclCodec.INSTANCE.encodeToString(env.message()));
            Envelope w = Envelope.outgoing(wrapped, env.via(), env.destination());
            ctx.passDown(w);
            return;
        }
        ctx.passDown(env);
    }

    private void onRelay(AclMessage wrapper) {
        String text = wrapper.getContent();
        int nl = text.indexOf('\n');
        if (nl < 0) {
            throw new IllegalArgumentException("a relayed message without its ACL part");
        }
        AclMessage inner;
        try {
            inner = io.concord.core.codec.StringAclCodec.INSTANCE.decode(text.substring(nl + 1));
        } catch (io.concord.core.codec.AclParseException e) {
            throw new IllegalArgumentException("a relayed message that does not parse: " + e.getMessage());
        }
        if (text.startsWith(RELAY_IN)) {
            // From the container: a foreign agent's message for this agent.
            if (container == null || !container.name().equals(wrapper.getSender().name())) {
                throw new IllegalArgumentException("a foreign message relayed by " + wrapper.getSender().name()
                        + ", which is not this agent's container");
            }
            host.deliverToAgent(inner);
            return;
        }
        // RELAY_OUT: to the container's gateway.
        Map<String, String> p = Lines.parse(text.substring(0, nl)).params();
        String name = p.get("receiver");
        if (name == null) {
            throw new IllegalArgumentException("a relay without receiver=");
        }
        String addrs = p.getOrDefault("addresses", "");
        AID receiver = new AID(name, addrs.isEmpty() ? new String[0] : addrs.split(","));
        if (role == Role.CONTAINER && !gatewayStarted) {
            startGateway();
        }
        if (role != Role.CONTAINER || !gatewayStarted) {
            // Nothing can carry it now: the sender hears so at once, and its protocol ends.
            host.drops().record(self, "no-gateway", "a message for " + name + " reached an agent that serves no gateway");
            if (inner.getSender() != null && inner.getPerformative() != Performative.FAILURE) {
                gatewayContext.deliver(io.concord.core.proto.MtsFailure.of(platform, inner, receiver,
                        "Foreign agent unreachable: the platform's gateway is not serving (its container is changing)"),
                        inner.getSender());
            }
            return;
        }
        gateway.sendOut(inner, receiver);
    }

    private void startGateway() {
        if (gateway == null || gatewayStarted) {
            return;
        }
        gatewayStarted = true;
        try {
            gateway.start(gatewayContext);
            trace("gateway", "started at " + gateway.addresses());
        } catch (RuntimeException e) {
            gatewayStarted = false;
            host.drops().record(self, "gateway-failed", "the gateway did not start: " + e.getMessage());
        }
    }

    private void stopGateway() {
        if (gateway != null && gatewayStarted) {
            gatewayStarted = false;
            try {
                gateway.stop();
            } catch (RuntimeException e) {
                host.drops().record(self, "gateway-failed", "the gateway did not stop cleanly: " + e.getMessage());
            }
        }
    }

    private final GatewayContext gatewayContext = new GatewayContext() {
        @Override
        public String platformName() {
            return platform;
        }

        @Override
        public void execute(Runnable task) {
            host.execute(task);
        }

        @Override
        public boolean deliver(AclMessage message, AID receiver) {
            String name = receiver.name();
            if (name.equalsIgnoreCase(self)) {
                host.deliverToAgent(message);
                return true;
            }
            AgentEntry e = null;
            for (AgentEntry x : lal.values()) {
                if (x.name().equalsIgnoreCase(name)) {
                    e = x;
                }
            }
            if (e == null) {
                for (AgentEntry x : gal.values()) {
                    if (x.name().equalsIgnoreCase(name)) {
                        e = x;
                    }
                }
            }
            if (e == null) {
                return false;
            }
            sendQuietly(platformMessage(Performative.INFORM, P_SERVICES, e.aid(), RELAY_IN + "receiver="
                    + Lines.escape(e.name()) + "\n" + io.concord.core.codec.StringAclCodec.INSTANCE.encodeToString(message)));
            return true;
        }

        @Override
        public List<AgentEntry> search(ServiceDescription template) {
            return ContainerLayer.this.search(template);
        }

        @Override
        public List<AgentEntry> agents() {
            List<AgentEntry> all = new ArrayList<>(lal.values());
            for (AgentEntry e : gal.values()) {
                if (!lal.containsKey(e.name())) {
                    all.add(e);
                }
            }
            return all;
        }
    };

    @Override
    public void onUp(LayerContext ctx, Envelope env) {
        AclMessage m = env.message();
        boolean forService = addressedToService(m);
        boolean platformMessage = !forService && ONTOLOGY.equals(m.getOntology());
        if (!platformMessage && !forService) {
            ctx.passUp(env);
            return;
        }
        AID sender = m.getSender();
        if (!platform.equals(sender.platform())) {
            ctx.drop(env, "foreign-platform", sender.name() + " belongs to platform '" + sender.platform()
                    + "', not to '" + platform + "'");
            return;
        }
        // The sender a platform message names must be the agent whose frame carried it (under
        // class 7 the pair key authenticates that): nobody speaks for another agent, so "leave",
        // the lists and the relays, checked against the sender's name below, are its own.
        long from = env.peerId();
        if (from != 0 && from != io.concord.layers.frame.Frames.id(sender.name())) {
            ctx.drop(env, "masquerade", "a platform message in the name of " + sender.name() + " from another agent (id "
                    + Long.toHexString(from) + ")");
            return;
        }
        // A frame for any agent at a port is sealed with the platform key alone: its source is
        // whatever its sender wrote. Only discovery travels that way; nothing that changes state.
        if (env.header(io.concord.layers.frame.Frames.ENVELOPE_ANY) != null && !discovery(m, forService)) {
            ctx.drop(env, "unauthenticated", "a platform message other than discovery in a frame for any agent ("
                    + firstWord(m.getContent()) + " from " + sender.name() + "): it must come sealed to this agent");
            return;
        }
        if (role == Role.STOPPED) {
            return;
        }
        try {
            if (forService) {
                serve(m);
            } else {
                onPlatformMessage(env, m);
            }
        } catch (IllegalArgumentException e) {
            ctx.drop(env, "malformed-platform", e.getMessage());
        }
    }

    /** Platform messages that may come in a frame for any agent: asking a port who is container, the answers, and a host container's announcement. */
    private static final Set<String> DISCOVERY = Set.of("who-is-container", "container", "seeking", "lal-request", "announce");

    private static boolean discovery(AclMessage m, boolean forService) {
        String text = m.getContent();
        if (forService || text == null || text.startsWith(RELAY_OUT) || text.startsWith(RELAY_IN)) {
            return false;
        }
        return DISCOVERY.contains(firstWord(text));
    }

    private static String firstWord(String text) {
        if (text == null) {
            return "";
        }
        int end = 0;
        while (end < text.length() && !Character.isWhitespace(text.charAt(end))) {
            end++;
        }
        return text.substring(0, end);
    }

    private boolean addressedToService(AclMessage m) {
        for (AID r : m.getReceivers()) {
            if (r.name().equals(dfAid.name()) || r.name().equals(amsAid.name())) {
                return true;
            }
        }
        return false;
    }

    /**
     * The message with its time of arrival on this host's clock, as a delivered message has it: a
     * reply's reply-with is made from it (without it, from a counter shared by the whole JVM, which
     * made two runs of one seed in one JVM differ).
     */
    private AclMessage stamped(AclMessage m) {
        if (m.getReceivedAtEpochMs() == Long.MIN_VALUE) {
            m.setReceivedAtEpochMs(host.clock().epochMillis());
        }
        return m;
    }

    private void onPlatformMessage(Envelope env, AclMessage m) {
        String text = m.getContent();
        if (text != null && (text.startsWith(RELAY_OUT) || text.startsWith(RELAY_IN))) {
            onRelay(m);
            return;
        }
        Lines.Content c = Lines.parse(m.getContent());
        AID sender = m.getSender();
        if (host.tracer().enabled()) {
            host.tracer().trace(host.nowNs(), self, "platform-accept", m.getPerformative().wireName() + " " + c.command()
                    + " from " + sender.name());
        }
        if (m.getInReplyTo() != null && serviceRequests.containsKey(m.getInReplyTo())) {
            answerRequest(m);
            return;
        }
        switch (c.command()) {
            case "who-is-container" -> onQuery(m, c);
            case "container" -> onContainerClaim(m, c);
            case "seeking" -> onSeekingReply(m, c);
            case "join" -> onJoin(m, c);
            case "joined" -> onJoined(m, c);
            case "lal" -> onLal(m, c);
            case "lal-held" -> onLalHeld(m, c);
            case "alive" -> onAlive(m, c);
            case "alive-held" -> onLalHeld(m, c);
            case "agent-info" -> onAgentInfo(m, c);
            case "leave" -> onLeave(m, c);
            case "lal-request" -> onLalRequest(m);
            case "lal-copy" -> onLalCopy(c);
            case "gal" -> onGal(m, c);
            default -> {
                if (federation == null || !federation.handle(m, c)) {
                    throw new IllegalArgumentException("unknown platform command '" + c.command() + "'");
                }
            }
        }
    }

    // ---- discovery and election ---------------------------------------------------------------

    private void beginDiscovery() {
        role = Role.SEEKING;
        attempt = 0;
        claim = null;
        claimTerm = -1;
        for (Map.Entry<Address, Boolean> e : asked.entrySet()) {
            e.setValue(Boolean.FALSE);
        }
        sentTo.clear();
        askNeighbours();
        publish();
    }

    private void askNeighbours() {
        attempt++;
        String content = Lines.content("who-is-container", Lines.params("round", round), List.of(selfEntry));
        // The nearest ports first, a batch at a time: any member that answers names the container.
        List<Address> open = new ArrayList<>();
        for (Map.Entry<Address, Boolean> e : asked.entrySet()) {
            if (!e.getValue()) {
                open.add(e.getKey());
            }
        }
        int own = selfEntry.port();
        open.sort(java.util.Comparator.comparingInt(a -> Math.abs(a.port() - own)));
        for (Address a : open.subList(0, Math.min(open.size(), batch()))) {
            sentTo.add(a);
            sendQuietly(platformMessage(Performative.QUERY_REF, P_DISCOVERY, anyAt(a), content));
        }
        discoveryTimer = cancel(discoveryTimer);
        discoveryTimer = after(config.discoveryTimeoutMs() << Math.min(attempt - 1, 4), this::onDiscoveryTimeout);
    }

    /** Neighbours asked per attempt: a batch that grows with the attempts. */
    private int batch() {
        return 16 << Math.min(attempt - 1, 10);
    }

    AID anyAt(Address a) {
        return new AID(Frames.ANY_LOCAL_NAME + "@" + platform, a.toUri(host.transport()));
    }

    private void onDiscoveryTimeout() {
        discoveryTimer = -1;
        if (role != Role.SEEKING || joinTarget != null) {
            return;
        }
        if (claim == null && attempt < config.discoveryAttempts() && asked.containsValue(Boolean.FALSE)) {
            askNeighbours();
            return;
        }
        decide();
    }

    private void onQuery(AclMessage m, Lines.Content c) {
        AgentEntry asker = c.senderEntry(m);
        AclMessage reply = stamped(m).createReply();
        reply.setSender(selfAid);
        reply.setPerformative(Performative.INFORM);
        if (container != null && role != Role.SEEKING) {
            reply.setContent(Lines.content("container", Lines.params("term", term), List.of(container, selfEntry)));
        } else {
            seekers.put(asker.name(), asker);
            reply.setContent(Lines.content("seeking", Lines.params("round", round, "term", maxTermSeen),
                    List.of(selfEntry)));
        }
        // Answered to whoever holds the asker's port, as it asked: sealed with the platform key, so
        // that discovery costs no signed handshake per pair of agents.
        reply.clearAllReceiver();
        Address back = asker.transportAddress();
        reply.addReceiver(back != null ? anyAt(back) : asker.aid());
        sendQuietly(reply);
        if (role == Role.CONTAINER) {
            // A newcomer: it will join; nothing to do until then.
            return;
        }
    }

    private void markAnswered(AclMessage m) {
        Address a = addressOf(m.getSender());
        if (a != null && asked.containsKey(a)) {
            asked.put(a, Boolean.TRUE);
        }
    }

    private static Address addressOf(AID aid) {
        for (String uri : aid.addresses()) {
            Address a = Address.parse(uri);
            if (a != null) {
                return a;
            }
        }
        return null;
    }

    private void onSeekingReply(AclMessage m, Lines.Content c) {
        markAnswered(m);
        if (c.entries().size() != 1) {
            throw new IllegalArgumentException("a seeking reply carries exactly its sender's entry");
        }
        AgentEntry e = c.entries().get(0);
        maxTermSeen = Math.max(maxTermSeen, Long.parseLong(c.params().getOrDefault("term", "0")));
        if (role == Role.SEEKING) {
            seekers.put(e.name(), e);
            boolean waiting = false;
            for (Address a : sentTo) {
                waiting |= !asked.get(a);
            }
            if (joinTarget == null && claim == null && !waiting) {
                discoveryTimer = cancel(discoveryTimer);
                if (asked.containsValue(Boolean.FALSE)) {
                    askNeighbours(); // every one asked is seeking too: ask the next batch now
                } else {
                    decide();
                }
            }
        }
    }

    /** A "container" message: a discovery reply, an announcement, or a redirection to a better one. */
    private void onContainerClaim(AclMessage m, Lines.Content c) {
        markAnswered(m);
        long t = c.longParam("term");
        if (c.entries().isEmpty()) {
            throw new IllegalArgumentException("a container message must carry the container's entry");
        }
        AgentEntry claimed = c.entries().get(0);
        maxTermSeen = Math.max(maxTermSeen, t);
        if (claimed.name().equals(self)) {
            return;
        }
        switch (role) {
            case SEEKING -> {
                if (claim == null || beats(t, claimed, claimTerm, claim)) {
                    claim = claimed;
                    claimTerm = t;
                }
                if (joinTarget == null || beats(t, claimed, claimTerm, joinTarget)) {
                    discoveryTimer = cancel(discoveryTimer);
                    startJoin(claimed, t);
                }
            }
            case MEMBER -> {
                if (container == null || beats(t, claimed, term, container)) {
                    startJoin(claimed, t);
                } else if (!claimed.name().equals(container.name())) {
                    tellBetter(claimed.aid());
                }
            }
            case CONTAINER -> contest(claimed, t);
            default -> { }
        }
    }

    /** True if (t1, c1) is a better container claim than (t2, c2): a later term, else the elder. */
    static boolean beats(long t1, AgentEntry c1, long t2, AgentEntry c2) {
        if (c2 == null) {
            return true;
        }
        if (t1 != t2) {
            return t1 > t2;
        }
        return AgentEntry.SENIORITY.compare(c1, c2) < 0;
    }

    private void tellBetter(AID to) {
        if (container == null) {
            return;
        }
        sendQuietly(platformMessage(Performative.INFORM, P_DISCOVERY, to,
                Lines.content("container", Lines.params("term", term), List.of(container, selfEntry))));
    }

    private void decide() {
        if (claim != null) {
            startJoin(claim, claimTerm);
            return;
        }
        List<AgentEntry> candidates = new ArrayList<>(seekers.values());
        candidates.add(selfEntry);
        candidates.sort(round < 3 ? AgentEntry.SENIORITY : AgentEntry.BY_PORT);
        if (candidates.get(0).name().equals(self)) {
            becomeContainer(maxTermSeen + 1, seekers.isEmpty() ? "no potential agent answered"
                    : "the " + (round < 3 ? "oldest" : "lowest port") + " of " + candidates.size() + " seeking agents");
            return;
        }
        // Excluded: wait for the winner to announce itself, then ask again.
        trace("excluded", "waiting for " + candidates.get(0).name() + " round=" + round);
        discoveryTimer = after(config.electionTimeoutMs(), () -> {
            discoveryTimer = -1;
            if (role == Role.SEEKING && joinTarget == null) {
                round++;
                seekers.clear();
                beginDiscovery();
            }
        });
    }

    private void becomeContainer(long newTerm, String why) {
        discoveryTimer = cancel(discoveryTimer);
        joinTimer = cancel(joinTimer);
        watchTimer = cancel(watchTimer);
        joinTarget = null;
        role = Role.CONTAINER;
        successor = null;
        galFrom = self;
        term = newTerm;
        maxTermSeen = Math.max(maxTermSeen, term);
        seq = 1;
        container = selfEntry;
        for (String s : suspects) {
            lal.remove(s);
        }
        suspects.clear();
        failoverRounds = 0;
        lal.put(self, selfEntry);
        long now = host.nowNs();
        lastHeard.clear();
        heldSeq.clear();
        for (String n : lal.keySet()) {
            lastHeard.put(n, now);
        }
        rebuildRoutes();
        trace("container", "term=" + term + " agents=" + lal.size() + ": " + why);
        // Announce to those who wait, and ask every listed agent for its information (rebuild).
        for (AgentEntry s : seekers.values()) {
            sendQuietly(platformMessage(Performative.INFORM, P_DISCOVERY, s.aid(),
                    Lines.content("container", Lines.params("term", term), List.of(selfEntry))));
        }
        seekers.clear();
        for (AgentEntry e : lal.values()) {
            if (!e.name().equals(self)) {
                sendQuietly(platformMessage(Performative.REQUEST, P_LAL, e.aid(),
                        Lines.content("agent-info", Lines.params("term", term), List.of(selfEntry))));
            }
        }
        if (lal.size() > 1) {
            schedulePush();
        }
        periodMs = config.periodMs(lal.size());
        timeoutMs = config.timeoutMs(lal.size());
        cycleTimer = cancel(cycleTimer);
        cycleDueNs = host.nowNs() + periodMs * 1_000_000L;
        cycleTimer = after(periodMs, this::cycle);
        if (federation != null) {
            federation.start();
        }
        startGateway();
        publish();
    }

    private void yieldTo(AgentEntry better, long t) {
        trace("yield", "to " + better.name() + " term=" + t);
        if (federation != null) {
            federation.stop();
        }
        stopGateway();
        cycleTimer = cancel(cycleTimer);
        pushTimer = cancel(pushTimer);
        String content = Lines.content("container", Lines.params("term", t), List.of(better, selfEntry));
        for (AgentEntry e : lal.values()) {
            if (!e.name().equals(self) && !e.name().equals(better.name())) {
                sendQuietly(platformMessage(Performative.INFORM, P_DISCOVERY, e.aid(), content));
            }
        }
        role = Role.MEMBER;
        startJoin(better, t);
    }

    // ---- join -----------------------------------------------------------------------------------

    private void startJoin(AgentEntry target, long t) {
        joinTarget = target;
        claimTerm = Math.max(claimTerm, t);
        joinFailures = 0;
        sendJoin();
    }

    private void sendJoin() {
        joinTimer = cancel(joinTimer);
        sendQuietly(platformMessage(Performative.INFORM_REF, P_LAL, joinTarget.aid(),
                Lines.content("join", Lines.params("term", claimTerm), List.of(selfEntry))));
        // Backing off: the first join to a container may wait for a signed handshake on a cold JVM.
        joinTimer = after(config.joinRetryMs() << Math.min(joinFailures, 4), this::onJoinTimeout);
    }

    private void onJoinTimeout() {
        joinTimer = -1;
        if (joinTarget == null) {
            return;
        }
        if (++joinFailures < config.joinAttempts()) {
            sendJoin();
            return;
        }
        // The container does not answer: ask a random known agent for the last valid LAL, then
        // take part in the next election with it.
        trace("join-failed", joinTarget.name() + " did not confirm " + joinFailures + " joins");
        suspects.add(joinTarget.name());
        AgentEntry failed = joinTarget;
        joinTarget = null;
        List<AID> known = new ArrayList<>();
        for (AgentEntry e : seekers.values()) {
            known.add(e.aid());
        }
        for (AgentEntry e : lal.values()) {
            if (!e.name().equals(self) && !e.name().equals(failed.name())) {
                known.add(e.aid());
            }
        }
        if (known.isEmpty()) {
            for (Address a : asked.keySet()) {
                if (!a.equals(failed.transportAddress())) {
                    known.add(anyAt(a));
                }
            }
        }
        if (!known.isEmpty()) {
            AID pick = known.get(host.random().nextInt(known.size()));
            sendQuietly(platformMessage(Performative.REQUEST, P_LAL, pick,
                    Lines.content("lal-request", Lines.params("term", term), List.of(selfEntry))));
        }
        // Wait a timeout for the copy (it may name a container to join); then elect from it.
        role = Role.MEMBER;
        container = null;
        successor = failed;
        term = Math.max(term, claimTerm);
        lal.put(self, selfEntry);
        rebuildRoutes();
        timeoutMs = Math.max(timeoutMs, config.timeoutMs(lal.size()));
        publish();
        resetWatch();
    }

    private void onJoin(AclMessage m, Lines.Content c) {
        AgentEntry e = c.senderEntry(m);
        if (role != Role.CONTAINER) {
            if (container != null && role == Role.MEMBER) {
                sendQuietly(platformMessage(Performative.INFORM, P_DISCOVERY, e.aid(),
                        Lines.content("container", Lines.params("term", term), List.of(container, selfEntry))));
            }
            return;
        }
        AgentEntry old = lal.put(e.name(), keepServices(lal.get(e.name()), e));
        lastHeard.put(e.name(), host.nowNs());
        if (old == null || !old.equals(lal.get(e.name()))) {
            seq++;
            rebuildRoutes();
            schedulePush();
            trace("registered", e.name() + " agents=" + lal.size());
        }
        periodMs = config.periodMs(lal.size());
        timeoutMs = config.timeoutMs(lal.size());
        AclMessage reply = platformReply(m, Performative.CONFIRM,
                Lines.content("joined", Lines.params("term", term, "period", periodMs, "timeout", timeoutMs), List.of(selfEntry)));
        sendQuietly(reply);
        publish();
    }

    /** A rejoining agent that lost its own copy keeps the services the list holds for it. */
    private static AgentEntry keepServices(AgentEntry known, AgentEntry joining) {
        if (known != null && joining.services().isEmpty() && !known.services().isEmpty()
                && known.address().equals(joining.address()) && known.startMs() == joining.startMs()) {
            return joining.withServices(known.services());
        }
        return joining;
    }

    private void onJoined(AclMessage m, Lines.Content c) {
        long t = c.longParam("term");
        AgentEntry by = c.senderEntry(m);
        if (joinTarget == null || !joinTarget.name().equals(by.name())) {
            return; // an old confirmation
        }
        joinTimer = cancel(joinTimer);
        discoveryTimer = cancel(discoveryTimer);
        joinTarget = null;
        becomeMember(by, t, c.longParam("period"), c.longParam("timeout"));
    }

    private void becomeMember(AgentEntry by, long t, long period, long timeout) {
        boolean changed = role != Role.MEMBER || container == null || !container.name().equals(by.name()) || term != t;
        if (federation != null) {
            federation.stop();
        }
        stopGateway();
        cycleTimer = cancel(cycleTimer);
        pushTimer = cancel(pushTimer);
        role = Role.MEMBER;
        successor = null;
        if (container == null || !container.name().equals(by.name()) || t != term) {
            seq = 0; // a new container's list replaces ours whatever its sequence
        }
        container = by;
        term = t;
        maxTermSeen = Math.max(maxTermSeen, t);
        periodMs = period;
        timeoutMs = timeout;
        suspects.clear();
        failoverRounds = 0;
        seekers.clear();
        if (!lal.containsKey(by.name())) {
            lal.put(by.name(), by);
            rebuildRoutes();
        }
        resetWatch();
        if (changed) {
            trace("member", "of " + by.name() + " term=" + t);
        }
        publish();
    }

    /** A page of the last valid LAL a known agent held, asked for after failed joins. */
    private void onLalCopy(Lines.Content c) {
        if (role == Role.CONTAINER) {
            return;
        }
        boolean added = false;
        for (AgentEntry e : c.entries()) {
            if (!lal.containsKey(e.name()) && !suspects.contains(e.name())) {
                lal.put(e.name(), e);
                added = true;
            }
        }
        if (added) {
            rebuildRoutes();
            publish();
        }
        // The copy names the container its holder follows: if that is not the one that failed us,
        // join it rather than wait for an election.
        String named = c.params().getOrDefault("container", "");
        long t = Long.parseLong(c.params().getOrDefault("term", "0"));
        if (!named.isEmpty() && !suspects.contains(named) && !named.equals(self) && joinTarget == null
                && (container == null || t > term)) {
            for (AgentEntry e : c.entries()) {
                if (e.name().equals(named)) {
                    trace("join-from-copy", named + " term=" + t);
                    startJoin(e, t);
                    return;
                }
            }
        }
    }

    // ---- LAL distribution -----------------------------------------------------------------------

    private void schedulePush() {
        if (pushTimer < 0) {
            pushTimer = after(config.pushDelayMs(), () -> {
                pushTimer = -1;
                pushAll();
            });
        }
    }

    List<String> lalPages() {
        return pagesOf(lal.values());
    }

    private List<String> pagesOf(Collection<AgentEntry> entries) {
        List<String> out = new ArrayList<>();
        StringBuilder b = new StringBuilder();
        for (AgentEntry e : entries) {
            StringBuilder line = new StringBuilder(80);
            Lines.appendEntry(line, e);
            if (b.length() > 0 && b.length() + line.length() + 1 > config.maxContentBytes()) {
                out.add(b.toString());
                b.setLength(0);
            }
            if (b.length() > 0) {
                b.append('\n');
            }
            b.append(line);
        }
        out.add(b.toString());
        return out;
    }

    private void pushAll() {
        if (role != Role.CONTAINER) {
            return;
        }
        List<String> p = lalPages();
        for (AgentEntry e : lal.values()) {
            if (!e.name().equals(self)) {
                pushTo(e.aid(), p);
            }
        }
        trace("distribute", "term=" + term + " seq=" + seq + " agents=" + lal.size() + " pages=" + p.size());
        if (federation != null) {
            federation.localChanged();
            globalChanged();
        }
        publish();
    }

    private void pushTo(AID to, List<String> p) {
        for (int i = 0; i < p.size(); i++) {
            String head = Lines.content("lal", Lines.params("term", term, "seq", seq, "page", i, "pages", p.size(),
                    "period", periodMs, "timeout", timeoutMs), List.of());
            sendQuietly(platformMessage(Performative.INFORM_REF, P_LAL, to, head + "\n" + p.get(i)));
        }
    }

    private void onLal(AclMessage m, Lines.Content c) {
        long t = c.longParam("term");
        long s = c.longParam("seq");
        int page = (int) c.longParam("page");
        int n = (int) c.longParam("pages");
        if (n < 1 || n > 10_000 || page < 0 || page >= n) {
            throw new IllegalArgumentException("a bad LAL page " + page + " of " + n);
        }
        String from = m.getSender().name();
        AgentEntry by = null;
        for (AgentEntry e : c.entries()) {
            if (e.name().equals(from)) {
                by = e;
            }
        }
        if (by == null && n == 1) {
            throw new IllegalArgumentException("a LAL must list its container");
        }
        AgentEntry claimed = by != null ? by : lal.get(from);
        if (claimed == null) {
            claimed = new AgentEntry(from, m.getSender().addresses().isEmpty() ? "" : m.getSender().addresses().get(0), Long.MAX_VALUE, List.of());
        }
        if (role == Role.CONTAINER) {
            contest(claimed, t);
            return;
        }
        boolean fromMine = container != null && container.name().equals(from) && term == t;
        if (!fromMine) {
            if (container != null && !beats(t, claimed, term, container) && !suspects.contains(container.name())) {
                tellBetter(m.getSender());
                return;
            }
        } else if (s <= seq) {
            // Already held: confirm again (our confirmation may have been lost).
            sendQuietly(platformMessage(Performative.CONFIRM, P_LAL, m.getSender(),
                    Lines.content("lal-held", Lines.params("term", term, "seq", seq), List.of())));
            resetWatch();
            return;
        }
        String key = t + "/" + from + "/" + s;
        if (!key.equals(pagesKey)) {
            pages.clear();
            pagesKey = key;
        }
        List<AgentEntry> all = Lines.collect(pages.computeIfAbsent(key, k -> new String[n]), page, n, m.getContent());
        if (all == null) {
            return;
        }
        pages.clear();
        pagesKey = null;
        AgentEntry containerEntry = null;
        for (AgentEntry e : all) {
            if (e.name().equals(from)) {
                containerEntry = e;
            }
        }
        if (containerEntry == null) {
            throw new IllegalArgumentException("the LAL from " + from + " does not list its container");
        }
        joinTarget = null;
        joinTimer = cancel(joinTimer);
        discoveryTimer = cancel(discoveryTimer);
        becomeMember(containerEntry, t, c.longParam("period"), c.longParam("timeout"));
        lal.clear();
        for (AgentEntry e : all) {
            lal.put(e.name(), e);
        }
        seq = s;
        rebuildRoutes();
        AgentEntry mine = lal.get(self);
        if (mine == null) {
            // Removed (we were silent too long): join again.
            trace("rejoin", "not in the list of " + from);
            startJoin(containerEntry, t);
        } else {
            selfEntry = mine;
        }
        sendQuietly(platformMessage(Performative.CONFIRM, P_LAL, m.getSender(),
                Lines.content("lal-held", Lines.params("term", term, "seq", seq), List.of())));
        publish();
    }

    /** A member's confirmation of the version it holds (after a LAL or an alive). */
    private void onLalHeld(AclMessage m, Lines.Content c) {
        if (role != Role.CONTAINER) {
            return;
        }
        String from = m.getSender().name();
        long t = c.longParam("term");
        long s = c.longParam("seq");
        if (!lal.containsKey(from)) {
            // Removed while silent: its list is outdated; our list tells it to join again.
            pushTo(m.getSender(), lalPages());
            return;
        }
        lastHeard.put(from, host.nowNs());
        heldSeq.put(from, s);
        String g = c.params().get("gseq");
        boolean otherSource = !self.equals(c.params().getOrDefault("gfrom", self));
        if (g != null && (otherSource || Long.parseLong(g) < gseq) && pushTimer < 0 && self.equals(galFrom)) {
            pushGalTo(lal.get(from).aid(), pagesOf(gal.values()));
        }
        if (cycleAwaiting.remove(from) && cycleAwaiting.isEmpty()) {
            lastCycleNs = host.nowNs() - cycleStartNs;
        }
        if (t != term || s < seq) {
            if (pushTimer < 0) {
                pushTo(lal.get(from).aid(), lalPages());
            }
        }
    }

    private void onLalRequest(AclMessage m) {
        if (lal.isEmpty()) {
            return;
        }
        List<String> p = lalPages();
        // The last valid list this agent holds, sent as its container sent it.
        for (int i = 0; i < p.size(); i++) {
            String head = Lines.content("lal-copy", Lines.params("term", term, "seq", seq, "page", i, "pages", p.size(),
                    "container", container == null ? "" : container.name()), List.of());
            AclMessage r = platformReply(m, Performative.INFORM_REF, head + "\n" + p.get(i));
            sendQuietly(r);
        }
    }

    // ---- maintenance ----------------------------------------------------------------------------

    private void cycle() {
        cycleTimer = -1;
        if (role != Role.CONTAINER) {
            return;
        }
        if (gateway != null && !gatewayStarted) {
            startGateway(); // its port may have been held by the previous container a moment ago
        }
        cycles++;
        long now = host.nowNs();
        // A cycle that runs late (this loop stalled) removes nobody: the agents' confirmations may
        // be waiting to be read.
        boolean late = cycleDueNs > 0 && now - cycleDueNs > periodMs * 500_000L;
        boolean changed = false;
        List<String> dead = new ArrayList<>();
        for (String n : lal.keySet()) {
            if (n.equals(self)) {
                continue;
            }
            Long heard = lastHeard.get(n);
            if (heard == null) {
                lastHeard.put(n, now);
            } else if (!late && now - heard > timeoutMs * 1_000_000L) {
                dead.add(n);
            }
        }
        for (String n : dead) {
            lal.remove(n);
            lastHeard.remove(n);
            heldSeq.remove(n);
            trace("removed", n + " silent for more than " + timeoutMs + " ms");
            changed = true;
        }
        if (changed) {
            seq++;
            rebuildRoutes();
            pushAll();
        }
        periodMs = config.periodMs(lal.size());
        timeoutMs = config.timeoutMs(lal.size());
        cycleStartNs = now;
        cycleAwaiting.clear();
        cycleAwaiting.addAll(lal.keySet());
        cycleAwaiting.remove(self);
        String alive = Lines.content("alive", Lines.params("term", term, "seq", seq, "period", periodMs,
                "timeout", timeoutMs), List.of(selfEntry));
        for (AgentEntry e : lal.values()) {
            if (!e.name().equals(self)) {
                sendQuietly(platformMessage(Performative.INFORM, P_MAINTENANCE, e.aid(), alive));
            }
        }
        // Keep asking the potential agents of the range that are not listed: a container elected
        // while one of them was slow to answer finds the other container this way.
        if (cycles % 4 == 1) {
            String q = Lines.content("who-is-container", Lines.params("round", round), List.of(selfEntry));
            Set<Address> listed = new HashSet<>();
            for (AgentEntry e : lal.values()) {
                listed.add(e.transportAddress());
            }
            for (Address a : asked.keySet()) {
                if (!listed.contains(a)) {
                    sendQuietly(platformMessage(Performative.QUERY_REF, P_DISCOVERY, anyAt(a), q));
                }
            }
        }
        cycleDueNs = now + periodMs * 1_000_000L;
        cycleTimer = after(periodMs, this::cycle);
        if (changed) {
            publish();
        }
    }

    private void onAlive(AclMessage m, Lines.Content c) {
        long t = c.longParam("term");
        AgentEntry by = c.senderEntry(m);
        if (role == Role.CONTAINER) {
            contest(by, t);
            return;
        }
        boolean mine = container != null && container.name().equals(by.name()) && term == t;
        if (!mine) {
            if (container == null || beats(t, by, term, container) || suspects.contains(container.name())) {
                if (joinTarget == null || !joinTarget.name().equals(by.name())) {
                    startJoin(by, t);
                }
            } else {
                tellBetter(m.getSender());
            }
            return;
        }
        periodMs = c.longParam("period");
        timeoutMs = c.longParam("timeout");
        if (role == Role.SEEKING && joinTarget == null) {
            becomeMember(by, t, periodMs, timeoutMs);
        }
        resetWatch();
        sendQuietly(platformMessage(Performative.CONFIRM, P_MAINTENANCE, m.getSender(),
                Lines.content("alive-held", Lines.params("term", term, "seq", seq, "gseq", gseq,
                        "gfrom", galFrom == null ? "-" : galFrom), List.of())));
    }

    private void resetWatch() {
        watchTimer = cancel(watchTimer);
        long t = timeoutMs > 0 ? timeoutMs : config.timeoutMs(Math.max(1, lal.size()));
        long deadline = host.nowNs() + t * 1_000_000L;
        watchTimer = after(t, () -> onWatch(deadline, t, false));
    }

    /**
     * The container stayed silent until the deadline. If this loop itself ran late (a stall: GC,
     * a starved CPU), the container's messages may be waiting to be read, or its own timers were
     * as late: grant one more period before giving it up.
     */
    private void onWatch(long deadline, long t, boolean graced) {
        watchTimer = -1;
        if (role != Role.MEMBER || joinTarget != null || (container == null && successor == null)) {
            return;
        }
        long period = Math.max(1, periodMs > 0 ? periodMs : config.periodMs(lal.size()));
        if (!graced && host.nowNs() - deadline > period * 500_000L) {
            watchTimer = after(period, () -> onWatch(deadline, t, true));
            return;
        }
        failover("no word from " + (container != null ? "the container " + container.name()
                : "the expected successor " + successor.name()) + " for " + t + " ms");
    }

    /** The container is gone: the eldest agent left in the list takes over. */
    private void failover(String why) {
        if (container != null) {
            suspects.add(container.name());
        }
        if (successor != null) {
            suspects.add(successor.name());
        }
        successor = null;
        failoverRounds++;
        List<AgentEntry> candidates = new ArrayList<>();
        for (AgentEntry e : lal.values()) {
            if (!suspects.contains(e.name())) {
                candidates.add(e);
            }
        }
        if (!candidates.contains(selfEntry) && !suspects.contains(self)) {
            candidates.add(selfEntry);
        }
        candidates.sort(failoverRounds <= 3 ? AgentEntry.SENIORITY : AgentEntry.BY_PORT);
        AgentEntry next = candidates.isEmpty() ? selfEntry : candidates.get(0);
        trace("failover", why + "; next container: " + next.name());
        if (next.name().equals(self)) {
            becomeContainer(Math.max(term, maxTermSeen) + 1, why);
            return;
        }
        // Wait for the successor; if it stays silent too, it is suspected in turn. Until it speaks
        // there is no container (requests to the DF wait).
        successor = next;
        container = null;
        publish();
        resetWatch();
    }

    private void onAgentInfo(AclMessage m, Lines.Content c) {
        if (m.getPerformative() == Performative.REQUEST) {
            long t = c.longParam("term");
            AgentEntry by = c.senderEntry(m);
            if (role == Role.CONTAINER ? beats(t, by, term, selfEntry)
                    : container == null || container.name().equals(by.name()) || beats(t, by, term, container)
                    || suspects.contains(container.name())) {
                if (role == Role.CONTAINER) {
                    yieldTo(by, t);
                    return;
                }
                joinTarget = null;
                joinTimer = cancel(joinTimer);
                becomeMember(by, t, Math.max(periodMs, config.periodMs(lal.size())), Math.max(timeoutMs, config.timeoutMs(lal.size())));
                sendQuietly(platformReply(m, Performative.INFORM,
                        Lines.content("agent-info", Lines.params("term", t), List.of(selfEntry))));
            } else {
                tellBetter(m.getSender());
            }
            return;
        }
        if (role != Role.CONTAINER || c.entries().size() != 1 || !c.entries().get(0).name().equals(m.getSender().name())) {
            return;
        }
        AgentEntry e = c.entries().get(0);
        lastHeard.put(e.name(), host.nowNs());
        AgentEntry was = lal.put(e.name(), e);
        if (!e.equals(was)) {
            seq++;
            rebuildRoutes();
            schedulePush();
            publish();
        }
    }

    private void onLeave(AclMessage m, Lines.Content c) {
        String from = m.getSender().name();
        if (role == Role.CONTAINER) {
            if (lal.remove(from) != null) {
                lastHeard.remove(from);
                heldSeq.remove(from);
                seq++;
                rebuildRoutes();
                trace("removed", from + " left");
                schedulePush();
                publish();
            }
        } else if (container != null && container.name().equals(from)) {
            lal.remove(from);
            rebuildRoutes();
            failover(from + " left");
        }
    }

    // ---- global agent list ----------------------------------------------------------------------

    /** The federation's lists changed (container): recompute the GAL and give it to every agent. */
    void globalChanged() {
        if (role != Role.CONTAINER || federation == null) {
            return;
        }
        List<AgentEntry> now = federation.globalAgents(lal.keySet());
        if (now.equals(List.copyOf(gal.values()))) {
            return;
        }
        gal.clear();
        for (AgentEntry e : now) {
            gal.put(e.name(), e);
        }
        gseq++;
        galFrom = self;
        rebuildRoutes();
        List<String> p = pagesOf(gal.values());
        for (AgentEntry e : lal.values()) {
            if (!e.name().equals(self)) {
                pushGalTo(e.aid(), p);
            }
        }
        trace("gal", "gseq=" + gseq + " agents=" + gal.size());
        publish();
    }

    private void pushGalTo(AID to, List<String> p) {
        for (int i = 0; i < p.size(); i++) {
            String head = Lines.content("gal", Lines.params("term", term, "gseq", gseq, "page", i, "pages", p.size()), List.of());
            // An empty GAL is a page without entry lines.
            sendQuietly(platformMessage(Performative.INFORM_REF, P_LAL, to, p.get(i).isEmpty() ? head : head + "\n" + p.get(i)));
        }
    }

    /** A page of the GAL from this agent's container. */
    private void onGal(AclMessage m, Lines.Content c) {
        String from = m.getSender().name();
        if (role != Role.MEMBER || container == null || !container.name().equals(from)) {
            return; // only the container this agent follows gives it the GAL
        }
        long g = c.longParam("gseq");
        int page = (int) c.longParam("page");
        int n = (int) c.longParam("pages");
        if (n < 1 || n > 10_000 || page < 0 || page >= n) {
            throw new IllegalArgumentException("a bad GAL page " + page + " of " + n);
        }
        if (from.equals(galFrom) && g <= gseq) {
            return;
        }
        String key = from + "/" + g;
        if (!key.equals(galPagesKey)) {
            galPages.clear();
            galPagesKey = key;
        }
        List<AgentEntry> all = Lines.collect(galPages.computeIfAbsent(key, k -> new String[n]), page, n, m.getContent());
        if (all == null) {
            return;
        }
        gal.clear();
        for (AgentEntry e : all) {
            gal.put(e.name(), e);
        }
        galPages.clear();
        galPagesKey = null;
        gseq = g;
        galFrom = from;
        rebuildRoutes();
        publish();
    }

    /**
     * Another agent claims to be container while this one is: the better claim wins; the loser of
     * the two yields, or is told of the winner.
     */
    void contest(AgentEntry other, long t) {
        if (role != Role.CONTAINER || other.name().equals(self)) {
            return;
        }
        if (beats(t, other, term, selfEntry)) {
            yieldTo(other, t);
        } else {
            tellBetter(other.aid());
        }
    }

    // ---- white and yellow pages ---------------------------------------------------------------

    private void serve(AclMessage m) {
        Performative act = m.getPerformative();
        if (act != Performative.REQUEST && act != Performative.QUERY_REF) {
            if (act == Performative.CFP || act == Performative.QUERY_IF || act == Performative.SUBSCRIBE
                    || act == Performative.PROPOSE) {
                sendQuietly(serviceReply(m, Performative.NOT_UNDERSTOOD, "(unsupported-act " + act.wireName() + ")"));
            }
            return;
        }
        if (role != Role.CONTAINER) {
            sendQuietly(serviceReply(m, Performative.FAILURE, "(not-container"
                    + (container == null ? "" : " " + Lines.escape(container.name())) + ")"));
            return;
        }
        Lines.Content c;
        try {
            c = Lines.parse(m.getContent());
        } catch (IllegalArgumentException e) {
            sendQuietly(serviceReply(m, Performative.NOT_UNDERSTOOD, "(malformed \"" + e.getMessage().replace("\"", "'") + "\")"));
            return;
        }
        String from = m.getSender().name();
        AgentEntry entry = lal.get(from);
        switch (c.command()) {
            case "register", "modify" -> {
                if (entry == null) {
                    sendQuietly(serviceReply(m, Performative.REFUSE, "(not-registered " + Lines.escape(from) + ")"));
                    return;
                }
                List<ServiceDescription> s = Lines.parseServices(c.params().getOrDefault("services", "-"));
                if (c.command().equals("register") && !entry.services().isEmpty()) {
                    List<ServiceDescription> merged = new ArrayList<>(entry.services());
                    for (ServiceDescription d : s) {
                        if (!merged.contains(d)) {
                            merged.add(d);
                        }
                    }
                    s = merged;
                }
                updateServices(entry, s);
                sendQuietly(serviceReply(m, Performative.INFORM, "done"));
            }
            case "deregister" -> {
                if (entry != null) {
                    updateServices(entry, List.of());
                }
                sendQuietly(serviceReply(m, Performative.INFORM, "done"));
            }
            case "search" -> {
                ServiceDescription template = Lines.parseService(c.params().getOrDefault("template", "*"));
                List<AgentEntry> found = search(template);
                sendQuietly(serviceReply(m, Performative.INFORM, Lines.content("result",
                        Lines.params("count", found.size()), found)));
            }
            case "agents" -> {
                String name = c.params().get("name");
                List<AgentEntry> found = new ArrayList<>();
                for (AgentEntry e : lal.values()) {
                    if (name == null || e.name().equalsIgnoreCase(name)) {
                        found.add(e);
                    }
                }
                sendQuietly(serviceReply(m, Performative.INFORM, Lines.content("result",
                        Lines.params("count", found.size(), "container", self, "term", term), found)));
            }
            default -> sendQuietly(serviceReply(m, Performative.NOT_UNDERSTOOD,
                    "(unknown-action " + Lines.escape(c.command()) + ")"));
        }
    }

    private void updateServices(AgentEntry entry, List<ServiceDescription> s) {
        AgentEntry updated = entry.withServices(s);
        if (!updated.equals(entry)) {
            lal.put(entry.name(), updated);
            if (entry.name().equals(self)) {
                selfEntry = updated;
            }
            seq++;
            rebuildRoutes();
            schedulePush();
            publish();
        }
    }

    private AclMessage serviceReply(AclMessage m, Performative p, String content) {
        AclMessage r = stamped(m).createReply();
        r.setPerformative(p);
        // Sent as the container itself: the frame is authenticated as the container's, and the
        // receiver's identification check holds the sender's name to that.
        r.setSender(selfAid);
        r.setContent(content);
        r.setLanguage(LANGUAGE);
        return r;
    }

    /** A request of the Java API, kept until answered: sent again on timeout (all are idempotent). */
    private static final class ServiceRequest {
        final boolean df;
        final Performative act;
        final String content;
        final String replyWith;
        final CompletableFuture<AclMessage> future = new CompletableFuture<>();
        int attempts;
        long timer = -1;

        ServiceRequest(boolean df, Performative act, String content, String replyWith) {
            this.df = df;
            this.act = act;
            this.content = content;
            this.replyWith = replyWith;
        }
    }

    private static final int REQUEST_ATTEMPTS = 4;
    private final List<ServiceRequest> waitingForContainer = new ArrayList<>();
    private final Map<String, ServiceRequest> serviceRequests = new HashMap<>();

    /**
     * Sends a request to this platform's DF or AMS for the Java API; the future completes with the
     * reply. Held until the agent knows its container; sent again if unanswered. Loop thread only.
     */
    CompletableFuture<AclMessage> request(boolean df, Performative p, String content) {
        ServiceRequest r = new ServiceRequest(df, p, content, self + "-p" + (++requestCounter));
        if (role == Role.STOPPED) {
            r.future.completeExceptionally(new IllegalStateException("the agent has stopped"));
            return r.future;
        }
        serviceRequests.put(r.replyWith, r);
        if (role == Role.SEEKING || container == null) {
            waitingForContainer.add(r);
        } else {
            sendRequest(r);
        }
        return r.future;
    }

    private void sendRequest(ServiceRequest r) {
        r.attempts++;
        AclMessage m = platformMessage(r.act, P_SERVICES, r.df ? dfAid : amsAid, r.content);
        m.setReplyWith(r.replyWith);
        long wait = Math.max(500, 2 * Math.max(timeoutMs, config.timeoutMs(lal.size())));
        r.timer = after(wait, () -> {
            r.timer = -1;
            if (r.future.isDone()) {
                return;
            }
            if (r.attempts >= REQUEST_ATTEMPTS) {
                serviceRequests.remove(r.replyWith);
                r.future.completeExceptionally(new java.util.concurrent.TimeoutException("the "
                        + (r.df ? "DF" : "AMS") + " did not answer " + r.attempts + " requests; is a container elected?"));
            } else if (role == Role.SEEKING || container == null) {
                waitingForContainer.add(r);
            } else {
                sendRequest(r);
            }
        });
        try {
            host.send(m);
        } catch (SendRejectedException e) {
            serviceRequests.remove(r.replyWith);
            r.timer = cancel(r.timer);
            r.future.completeExceptionally(e);
        }
    }

    private void answerRequest(AclMessage reply) {
        ServiceRequest r = serviceRequests.remove(reply.getInReplyTo());
        if (r != null) {
            r.timer = cancel(r.timer);
            r.future.complete(reply);
        }
    }

    private void releaseWaitingRequests() {
        if (waitingForContainer.isEmpty() || role == Role.SEEKING || container == null) {
            return;
        }
        List<ServiceRequest> ready = new ArrayList<>(waitingForContainer);
        waitingForContainer.clear();
        for (ServiceRequest r : ready) {
            if (!r.future.isDone()) {
                sendRequest(r);
            }
        }
    }

    // ---- helpers --------------------------------------------------------------------------------

    AclMessage platformMessage(Performative p, String protocol, AID to, String content) {
        AclMessage m = new AclMessage(p);
        m.setSender(selfAid);
        m.addReceiver(to);
        m.setOntology(ONTOLOGY);
        m.setLanguage(LANGUAGE);
        m.setProtocol(protocol);
        m.setContent(content);
        return m;
    }

    AclMessage platformReplyTo(AclMessage to, Performative p, String content) {
        return platformReply(to, p, content);
    }

    private AclMessage platformReply(AclMessage to, Performative p, String content) {
        AclMessage r = stamped(to).createReply();
        r.setPerformative(p);
        r.setSender(selfAid);
        r.setOntology(ONTOLOGY);
        r.setLanguage(LANGUAGE);
        r.setContent(content);
        return r;
    }

    void sendQuietly(AclMessage m) {
        try {
            host.send(m);
        } catch (SendRejectedException e) {
            host.drops().record(self, e.reason(), e.getMessage());
        } catch (RuntimeException e) {
            host.drops().record(self, "platform-send", e.toString());
        }
    }

    void trace(String event, String detail) {
        Tracer t = host.tracer();
        if (t.enabled()) {
            t.trace(host.nowNs(), self, "platform-" + event, detail);
        }
    }

    private void publish() {
        releaseWaitingRequests();
        for (Consumer<ContainerLayer> l : listeners) {
            l.accept(this);
        }
    }
}
