package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.layer.StackHost;
import io.concord.core.net.Address;
import io.concord.core.net.internal.Neighbourhood;
import io.concord.core.acl.MtsFailure;
import io.concord.layers.authority.Policy;
import io.concord.layers.defence.Defence;
import io.concord.layers.frame.Frames;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Set;
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
 * <p>This class is the layer's hooks and the views; the rules are in the roles ({@link SeekingRole},
 * {@link MemberRole}, {@link ContainerRole}, swapped by {@link Roles}), the lists in
 * {@link AgentLists}, the pages in {@link Directory}, the relay to foreign platforms in
 * {@link GatewayRelay}, the other hosts in {@link Federation}. Platform messages are FIPA ACL with
 * the ontology {@code concord-platform}, decoded into {@link PlatformMessage}s; this layer takes them
 * off the way up, so agents never see them. A message from an agent of another platform is dropped
 * and counted ({@code foreign-platform}), as is a malformed one ({@code malformed-platform}).
 */
public final class ContainerLayer extends Layer {
    /** How long a message that only a container can carry waits for one to be elected. */
    static final long CONTAINER_WAIT_MS = 2_000;
    static final int MAX_WAITING = 256;

    private final PlatformConfig config;
    private final NetworkConfig network;
    private final Gateway gateway;
    private final PlatformState st = new PlatformState();
    private final List<Consumer<ContainerLayer>> listeners = new ArrayList<>();
    private HostContext context;
    private StackHost host;
    private LayerContext layerContext;
    private String platform;
    private String self;
    private AID selfAid;
    /** The platform's service names, {@code df@platform} and {@code ams@platform}: asked of every message up. */
    private String dfName;
    private String amsName;
    private GatewayRelay relay;
    private Roles roles;
    private Directory directory;
    private ServiceRequests requests;
    private Registrations registrations;
    private MembershipGate gate;
    private final Policy policy;
    /** Messages for foreign agents (or the platform's DF and AMS) waiting for a container to carry them. */
    private WaitRoom forContainer;

    public ContainerLayer(PlatformConfig config) {
        this(config, NetworkConfig.defaults());
    }

    /** A container layer that also federates with the containers of other hosts. */
    public ContainerLayer(PlatformConfig config, NetworkConfig network) {
        this(config, network, null);
    }

    /** ... and reaches foreign platforms through a gateway (the JADE bridge), or none if {@code null}. */
    public ContainerLayer(PlatformConfig config, NetworkConfig network, Gateway gateway) {
        this(config, network, gateway, Set.of());
    }

    /**
     * ... without some defences: only for the threat tests, which show the threat reaching an
     * agent without its defence ({@link Defence#CLAIM_CHECK}).
     */
    public ContainerLayer(PlatformConfig config, NetworkConfig network, Gateway gateway, Set<Defence> off) {
        this(config, network, gateway, off, off.contains(Defence.AUTHORITY) ? Policy.allowingEverything() : Policy.defaults());
    }

    /**
     * ... with the platform's {@link Policy}: what agents of other platforms, arriving through the
     * gateway, may reach (by default the agents' own conversations, the DF and the AMS; never the
     * platform protocol or the observation service).
     */
    public ContainerLayer(PlatformConfig config, NetworkConfig network, Gateway gateway, Set<Defence> off, Policy policy) {
        this.policy = java.util.Objects.requireNonNull(policy, "policy");
        this.config = config;
        this.network = network;
        this.gateway = gateway;
        st.claimCheck = !off.contains(Defence.CLAIM_CHECK);
        st.portCheck = !off.contains(Defence.PORT_CHECK);
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
        return roles == null ? Role.SEEKING : roles.kind();
    }

    /** The container this agent follows (itself if it is the container), or {@code null}. */
    public String containerName() {
        return st.container == null ? null : st.container.name();
    }

    /** The LAL as this agent holds it, by name. Loop thread only. */
    public Collection<AgentEntry> agents() {
        return List.copyOf(st.lists.lal.values());
    }

    /** How many agents the LAL holds, without copying it. Loop thread only. */
    public int agentCount() {
        return st.lists.lal.size();
    }

    /** How many agents the GAL holds, without copying it. Loop thread only. */
    public int globalAgentCount() {
        return st.lists.gal.size();
    }

    /**
     * How long the last complete maintenance cycle took on the container: from its alive messages
     * to the last agent's confirmation, in ns; -1 if none completed yet. Safe from any thread.
     */
    public long lastCycleNs() {
        return st.lastCycleNs;
    }

    /** The Global Agent List as this agent holds it: agents of other hosts. Loop thread only. */
    public Collection<AgentEntry> globalAgents() {
        return List.copyOf(st.lists.gal.values());
    }

    /** The other hosts' containers this container is in contact with (empty unless container). */
    public List<String> facilitators() {
        return roles == null || roles.federation == null ? List.of() : roles.federation.contacted();
    }

    /** The federation with other hosts' containers, or {@code null} without a network. For tests. */
    Federation federation() {
        return roles == null ? null : roles.federation;
    }

    public long term() {
        return st.term;
    }

    public long lalSequence() {
        return st.seq;
    }

    /** This agent's own entry (its services included). */
    public AgentEntry selfEntry() {
        return st.selfEntry;
    }

    /** Calls back on the loop whenever the role, the container or the list changes. */
    public void addListener(Consumer<ContainerLayer> l) {
        listeners.add(l);
    }

    /** Searches the yellow pages in this agent's copy of the LAL (no message is sent). */
    public List<AgentEntry> search(ServiceDescription template) {
        return st.lists.search(List.of(template));
    }

    // ---- life cycle -------------------------------------------------------------------------------

    /** This layer finds where receivers known only by name are: in the platform's lists. */
    @Override
    public boolean resolvesNames() {
        return true;
    }

    @Override
    public void init(LayerContext ctx) {
        this.host = ctx.host();
        this.layerContext = ctx;
    }

    @Override
    public void start(LayerContext ctx) {
        platform = host.platformName();
        self = host.nodeName();
        dfName = "df@" + platform;
        amsName = "ams@" + platform;
        Address at = host.localAddress();
        String uri = at == null ? "" : at.toUri(host.transport());
        st.selfEntry = new AgentEntry(self, uri, host.clock().epochMillis(), List.of());
        selfAid = st.selfEntry.aid();
        context = new HostContext(host, layerContext, config, st, platform, selfAid, this::place);
        relay = new GatewayRelay(context, st, gateway, policy, this::role, m -> layerContext.passUp(Envelope.outgoing(m, selfAid, null)),
                host::execute);
        Neighbourhood around = host.capability(Neighbourhood.class);
        List<Address> neighbours = around == null ? List.of() : around.neighbours();
        gate = new MembershipGate(context, layerContext, st.lists, self);
        forContainer = new WaitRoom(context, CONTAINER_WAIT_MS, MAX_WAITING, (h, why) -> refuse(h.env(),
                why == WaitRoom.Why.STOPPED ? "stopped" : "no-container", switch (why) {
                    case FULL -> MAX_WAITING + " messages already wait for a container to carry them to " + h.key();
                    case EXPIRED -> "no container was elected within " + CONTAINER_WAIT_MS + " ms to carry it to " + h.key();
                    case STOPPED -> "the agent stopped while its message to " + h.key() + " waited for a container";
                }, why == WaitRoom.Why.STOPPED ? null : "Foreign agent unreachable: no container of platform " + platform
                        + " to carry the message"));
        roles = new Roles(context, st, network, around, relay, this::publish, () -> {
            gate.listsChanged();
            registrations.reconcile();
        });
        directory = new Directory(context, roles);
        requests = new ServiceRequests(context, roles);
        registrations = new Registrations(context, st, requests);
        context.trace("start", "neighbours=" + neighbours.size());
        roles.start(neighbours);
    }

    @Override
    public void stop(LayerContext ctx) {
        if (gate != null) {
            gate.stop();
            forContainer.stop();
        }
        registrations.stop();
        roles.stop();
        if (requests != null) {
            requests.stop();
        }
        publish();
    }

    // ---- routing and down -------------------------------------------------------------------------

    /**
     * Where a receiver known by name is: an agent of the lists (or one that left them less than the
     * grace ago); a foreign agent the gateway reaches, or the platform's DF and AMS, through the
     * container.
     */
    private AgentLists.Route route(AID receiver) {
        String name = receiver.name();
        AgentLists.Route r = st.lists.route(name, host.nowNs());
        if (r != null) {
            return r;
        }
        AgentEntry c = st.container;
        if (c != null && (!platform.equals(receiver.platform()) && relay.reaches(receiver)
                || name.equals(amsName) || name.equals(dfName))) {
            Address a = c.transportAddress();
            return a == null ? null : new AgentLists.Route(a, c.aid());
        }
        return null;
    }

    /**
     * Gives a copy the node could not place (not an agent of its runtime) its destination: the
     * route the lists give, else the first address of the receiver's AID. A receiver known by
     * neither is dropped ({@code unknown-receiver}) and its sender told with the FAILURE JADE's AMS
     * sends, so that its protocol ends instead of waiting. One that only a container can carry waits
     * for one while none is known, at most {@link #CONTAINER_WAIT_MS} ({@code no-container} after).
     *
     * @return false if dropped, or waiting (then it goes down by itself once a container is known)
     */
    private boolean place(Envelope env) {
        AID r = env.receiver();
        AgentLists.Route route = route(r);
        if (route != null) {
            env.setDestination(route.address());
            if (!route.node().equals(r)) {
                env.putHeader(Frames.ENVELOPE_VIA, route.node());
            }
            return true;
        }
        String uri = r.firstAddress(host.transport().scheme());
        Address a = uri == null ? null : Address.parse(uri);
        if (a != null) {
            env.setDestination(a);
            return true;
        }
        if (waitsForContainer(env)) {
            forContainer.hold(env, r.name());
            return false;
        }
        refuse(env, "unknown-receiver", "no " + host.transport() + " address known for " + r.name(), "Agent not found: " + r.name());
        return false;
    }

    /**
     * True for an application message that only a container can carry (to a foreign agent the
     * gateway reaches, or to the platform's DF or AMS) while none is known: in the first moments,
     * before an election ends, and during a failover.
     */
    private boolean waitsForContainer(Envelope env) {
        AID r = env.receiver();
        AclMessage m = env.message();
        return st.container == null && roles != null && roles.kind() != Role.STOPPED && m != null
                && !Protocol.ONTOLOGY.equals(m.getOntology()) && (!platform.equals(r.platform()) && relay.reaches(r)
                || r.name().equals(amsName) || r.name().equals(dfName));
    }

    /**
     * Drops a message this agent cannot send, and tells its sender with a FAILURE as JADE's AMS
     * words it ({@code failure}; {@code null}: the sender is stopping, nobody to tell).
     */
    private void refuse(Envelope env, String reason, String why, String failure) {
        layerContext.drop(env, reason, why);
        AclMessage m = env.message();
        if (failure != null && m != null && !Protocol.ONTOLOGY.equals(m.getOntology())) {
            layerContext.passUp(Envelope.outgoing(MtsFailure.of(platform, m, env.receiver(), failure),
                    selfAid, null));
        }
    }

    /**
     * A message of this agent: placed if the node could not, and one to a foreign receiver goes to
     * the container wrapped, for the container's gateway to carry out. The frame stays the
     * container's, so identification holds.
     */
    @Override
    public void onDown(LayerContext ctx, Envelope env) {
        if (env.destination() == null && !place(env)) {
            return;
        }
        AID r = env.receiver();
        AID via = env.header(Frames.ENVELOPE_VIA);
        if (relay != null && relay.present() && r != null && via != null && env.message() != null
                && !Protocol.ONTOLOGY.equals(env.message().getOntology()) && !platform.equals(r.platform())) {
            Envelope wrapped = Envelope.outgoing(relay.wrap(env.message(), r, via), via, env.destination());
            ctx.passDown(env.sentByAgent() ? wrapped.markSentByAgent() : wrapped);
            return;
        }
        ctx.passDown(env);
    }

    /** Platform and service messages are this layer's own: they take the stacks. */
    @Override
    public boolean mayHandOver(AclMessage m) {
        return !Protocol.ONTOLOGY.equals(m.getOntology()) && !addressedToService(m);
    }

    // ---- up ---------------------------------------------------------------------------------------

    @Override
    public void onUp(LayerContext ctx, Envelope env) {
        AclMessage m = env.message();
        boolean forService = addressedToService(m);
        boolean platformMessage = !forService && Protocol.ONTOLOGY.equals(m.getOntology());
        if (!platformMessage && !forService) {
            if (roles == null || roles.kind() == Role.STOPPED) {
                ctx.passUp(env);
            } else {
                gate.admit(env, m.getSender().name());
            }
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
        if (from != 0 && from != Frames.id(sender.name())) {
            ctx.drop(env, "masquerade", "a platform message in the name of " + sender.name() + " from another agent (id "
                    + Long.toHexString(from) + ")");
            return;
        }
        if (roles.kind() == Role.STOPPED) {
            return;
        }
        if (env.source() != null) {
            // Who holds which port: a message from a port comes from its holder (on one host no
            // other process can send from it), so a listed agent of another name whose port this is
            // is gone, whatever the port check would say of the port itself.
            st.heardAt.put(env.source(), sender.name());
        }
        if (forService) {
            if (env.header(Frames.ENVELOPE_ANY) != null) {
                unauthenticated(ctx, env, "a request to " + m.getReceivers().get(0).name());
                return;
            }
            directory.serve(m);
            return;
        }
        if (requests.answer(m)) {
            return;
        }
        PlatformMessage p;
        try {
            p = PlatformMessage.decode(m);
        } catch (Lines.NotTheSender e) {
            // Where a message names whom it is from, that must be its sender (e.g. an alive in the
            // container's name from a member).
            ctx.drop(env, "masquerade", e.getMessage());
            return;
        } catch (IllegalArgumentException e) {
            ctx.drop(env, "malformed-platform", e.getMessage());
            return;
        }
        // A frame for any agent at a port is sealed with the platform key alone: its source is
        // whatever its sender wrote. Only discovery travels that way; nothing that changes state.
        if (env.header(Frames.ENVELOPE_ANY) != null && !PlatformMessage.discovery(p)) {
            unauthenticated(ctx, env, firstWord(m.getContent()) + " from " + sender.name());
            return;
        }
        if (host.tracer().enabled()) {
            host.tracer().trace(host.nowNs(), self, "platform-accept", m.getPerformative().wireName() + " "
                    + firstWord(m.getContent()) + " from " + sender.name());
        }
        st.fromAny = env.header(Frames.ENVELOPE_ANY) != null;
        try {
            dispatch(p, m);
        } catch (PlatformLimit e) {
            ctx.drop(env, e.reason(), e.getMessage());
        } catch (IllegalArgumentException e) {
            ctx.drop(env, "malformed-platform", e.getMessage());
        } finally {
            st.fromAny = false;
        }
    }

    private void dispatch(PlatformMessage p, AclMessage m) {
        if (p instanceof PlatformMessage.RelayIn || p instanceof PlatformMessage.RelayOut) {
            p.to(relay, m);
        } else if (p instanceof PlatformMessage.Announce || p instanceof PlatformMessage.WhoIsFacilitator
                || p instanceof PlatformMessage.IsFacilitator || p instanceof PlatformMessage.IsNotFacilitator
                || p instanceof PlatformMessage.GalUpdate || p instanceof PlatformMessage.GalHeld
                || p instanceof PlatformMessage.UnknownSecret || p instanceof PlatformMessage.ContactMe) {
            if (roles.federation == null) {
                throw new IllegalArgumentException("a network message, and this agent has no network discovery");
            }
            p.to(roles.federation, m);
        } else {
            p.to(roles.current(), m);
        }
    }

    private static void unauthenticated(LayerContext ctx, Envelope env, String what) {
        ctx.drop(env, "unauthenticated", "a platform message other than discovery in a frame for any agent ("
                + what + "): it must come sealed to this agent");
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
            if (r.name().equals(dfName) || r.name().equals(amsName)) {
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
    /**
     * The content of a subscription to this platform's DF (a SUBSCRIBE to {@code df@platform}):
     * the subscriber is told at once of the agents whose services match the template, if any,
     * then of each change among them (INFORM in the subscription's conversation; an agent that
     * stopped matching comes with no services); a CANCEL in that conversation ends it.
     */
    public static String subscriptionContent(ServiceDescription template) {
        StringBuilder b = new StringBuilder();
        Lines.appendService(b, template);
        return Lines.content("subscribe", Lines.params("template", b.toString()), List.of());
    }

    /** The entries a DF answer or subscription notification ({@code result ...}) carries. */
    public static List<AgentEntry> resultEntries(String content) {
        return Lines.parse(content).entries();
    }

    /** The content language of the platform's own messages, its DF's answers and notifications included. */
    public static String contentLanguage() {
        return Protocol.LANGUAGE;
    }

    static AclMessage stamped(AclMessage m, long epochMillis) {
        if (m.getReceivedAtEpochMs() == Long.MIN_VALUE) {
            m.setReceivedAtEpochMs(epochMillis);
        }
        return m;
    }

    // ---- the Java API -------------------------------------------------------------------------------

    /**
     * Sends a request to this platform's DF or AMS for the Java API; the future completes with the
     * reply. Held until the agent knows its container; sent again if unanswered. Loop thread only.
     */
    CompletableFuture<AclMessage> request(boolean df, Performative p, String content) {
        if (requests == null) {
            return CompletableFuture.failedFuture(new IllegalStateException("the agent has not started"));
        }
        return requests.request(df, p, content);
    }

    /**
     * Asks the platform's DF itself (not this agent's copy of the lists) for the agents whose
     * services match the template; the future completes with the entries it answered. Loop thread
     * only.
     */
    public CompletableFuture<List<AgentEntry>> searchAtDf(ServiceDescription template) {
        return request(true, Performative.REQUEST, ServiceRequests.searchContent(template)).thenApply(ServiceRequests::entries);
    }

    /**
     * The agent's own registration: these services added to ({@code add}) or in place of those it
     * asked for before. It sends them again whenever its container does not hold them (a flap, a
     * failover, a refusal); the future completes once the DF took them. Loop thread only.
     */
    public CompletableFuture<Void> registerServices(List<ServiceDescription> services, boolean add) {
        if (registrations == null) {
            return CompletableFuture.failedFuture(new IllegalStateException("the agent has not started"));
        }
        return registrations.want(services, add);
    }

    /** Times this agent registered its services again on its own (after a flap, a failover, a refusal). */
    public long registrationsResent() {
        return registrations == null ? 0 : registrations.resent();
    }

    /** Times the DF did not take this agent's services at once (not listed yet, no container, no answer). */
    public long registrationsRefused() {
        return registrations == null ? 0 : registrations.refused();
    }

    private void publish() {
        if (roles.current() instanceof ContainerRole) {
            directory.listChanged();
        }
        requests.release();
        registrations.reconcile();
        if (st.container != null) {
            forContainer.release(name -> true, env -> onDown(layerContext, env));
        }
        for (Consumer<ContainerLayer> l : listeners) {
            l.accept(this);
        }
    }
}
