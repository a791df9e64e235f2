package io.concord.core.agent;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.agent.internal.CoLocated;
import io.concord.core.layer.CodecLayer;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerStack;
import io.concord.core.layer.Tracer;
import io.concord.core.net.Address;
import io.concord.core.net.Endpoint;
import io.concord.core.net.Network;
import io.concord.core.net.SocketNetwork;
import io.concord.core.net.Transport;
import io.concord.core.time.Clock;
import io.concord.core.time.internal.DeadlineTimerWheel;
import io.concord.core.time.internal.LoopLimits;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.security.SecureRandom;
import java.util.SplittableRandom;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.TimeoutException;
import java.util.function.Supplier;
import java.util.random.RandomGenerator;

/**
 * The agents of one JVM (or of one simulated host) and the single loop that serves them all: one
 * network poll over every agent's socket, one timer wheel, one clock, one seeded random source.
 * A message from one agent of the runtime to another is handed over in memory where both stacks
 * allow it (no frame, no datagram; see docs/design.md), else it costs a datagram; never a thread
 * switch: the loop that sends it also receives it and runs the receiver's behaviours.
 *
 * <p>Two ways to drive it: {@link #start()} gives it a thread of its own (real platforms); or the
 * caller invokes {@link #doWork()} repeatedly, as the deterministic simulation does.
 */
public final class AgentRuntime implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(AgentRuntime.class);

    private final Clock clock;
    private final Network network;
    private final boolean ownsNetwork;
    private final String platformName;
    private final String host;
    private final RandomGenerator random;
    /** Where secrets come from: a SecureRandom, or null when the runtime was given its random source. */
    private final SecureRandom secrets;
    private final LoopLimits loopLimits = new LoopLimits();
    private final Tracer tracer;
    private final Supplier<List<Layer>> stackFactory;
    private final int mailboxCapacity;
    private final boolean handOver;
    /** The other loops of this platform in this JVM, or null: messages to their agents go through the stacks. */
    private final LoopGroup group;
    /** Written by the loop only; read anywhere. */
    private volatile long handedOver;
    private final int idleSpinIterations;
    private final int idleYieldIterations;
    private final Transport transport;
    private final DeadlineTimerWheel wheel;
    private final Map<Long, Timer> timersById = new HashMap<>();
    private final Map<Long, Timer> timersByWheelId = new HashMap<>();
    private final ArrayDeque<AgentNode> ready = new ArrayDeque<>();
    private final Map<AID, AgentNode> directory = new LinkedHashMap<>();
    private final Map<String, Address> addressCache = new HashMap<>();
    private final ConcurrentLinkedQueue<Runnable> tasks = new ConcurrentLinkedQueue<>();
    private final Thread ownerThread;
    private volatile Thread loopThread;
    private volatile boolean running;
    private volatile boolean parked;
    private long nextTimerId;
    private long nowNs;
    private boolean closed;

    private record Timer(long id, long wheelId, Runnable task) {
    }

    private AgentRuntime(Builder b) {
        this.clock = b.clock;
        this.network = b.network != null ? b.network : new SocketNetwork();
        this.ownsNetwork = b.network == null;
        this.platformName = b.platformName;
        this.host = b.host;
        this.random = b.random != null ? b.random : new SplittableRandom();
        this.secrets = b.random != null ? null : new SecureRandom();
        this.tracer = b.tracer;
        this.stackFactory = b.stackFactory != null ? b.stackFactory : defaultStack();
        this.mailboxCapacity = b.mailboxCapacity;
        this.handOver = b.handOver;
        this.group = b.group;
        this.idleSpinIterations = b.idleSpinIterations;
        this.idleYieldIterations = b.idleYieldIterations;
        this.transport = b.transport;
        this.nowNs = clock.nanoTime();
        this.wheel = DeadlineTimerWheel.forAgents(nowNs);
        this.ownerThread = Thread.currentThread();
    }

    private static Supplier<List<Layer>> defaultStack() {
        for (io.concord.core.layer.StackProvider p : java.util.ServiceLoader.load(io.concord.core.layer.StackProvider.class)) {
            return p.defaultStack();
        }
        LOG.warn("no safety layers on the class path: agents of this runtime talk without the EN 50159 defences; "
                + "add the concord-layers module, or choose a stack with AgentRuntime.builder().stack(...)");
        return () -> List.of(new CodecLayer());
    }

    /** A builder with the defaults: system clock, real UDP on 127.0.0.1, platform "concord". */
    public static Builder builder() {
        return new Builder();
    }

    /** Builds a runtime; every setting is checked at {@link #build()}. */
    public static final class Builder {
        private Clock clock = Clock.system();
        private Network network;
        private String platformName = "concord";
        private String host = "127.0.0.1";
        private RandomGenerator random;
        private Tracer tracer = Tracer.NONE;
        private Supplier<List<Layer>> stackFactory;
        private int mailboxCapacity = 100_000;
        private boolean handOver = !Boolean.getBoolean("concord.handover.off");
        private LoopGroup group;
        private int idleSpinIterations = Integer.getInteger("concord.idle.spin", 0);
        private int idleYieldIterations = Integer.getInteger("concord.idle.yield", 200);
        private Transport transport = Transport.UDP;

        private Builder() {
        }

        /** The transport of agents that do not choose one; UDP by default. */
        public Builder transport(Transport t) {
            this.transport = Objects.requireNonNull(t, "transport");
            return this;
        }

        public Builder clock(Clock clock) {
            this.clock = Objects.requireNonNull(clock, "clock");
            return this;
        }

        /**
         * The network; by default the runtime makes real UDP sockets of its own and closes them on
         * {@link AgentRuntime#close()}. A network given here belongs to the caller, who closes it.
         */
        public Builder network(Network network) {
            this.network = Objects.requireNonNull(network, "network");
            return this;
        }

        /** The platform name, the part after {@code @} in agent names. */
        public Builder platformName(String name) {
            this.platformName = Objects.requireNonNull(name, "platformName");
            return this;
        }

        /** The local host agents bind to (an IP literal, or a virtual host name). */
        public Builder host(String host) {
            this.host = Objects.requireNonNull(host, "host");
            return this;
        }

        /**
         * The random source; seed it for a deterministic run. A runtime given one (or a
         * {@link #seed}) takes its secrets from it too ({@link #secretBytes}), so that a
         * simulation replays: never give one to a runtime that faces a network.
         */
        public Builder random(RandomGenerator random) {
            this.random = Objects.requireNonNull(random, "random");
            return this;
        }

        /** A seeded random source ({@link #random}): for simulations and tests only. */
        public Builder seed(long seed) {
            this.random = new SplittableRandom(seed);
            return this;
        }

        public Builder tracer(Tracer tracer) {
            this.tracer = Objects.requireNonNull(tracer, "tracer");
            return this;
        }

        /**
         * Makes each agent's layers, top first. Default: the stack a {@link io.concord.core.layer.StackProvider}
         * on the class path supplies (the class-7 safety stack of {@code concord-layers}), else the
         * binary codec alone, with a warning.
         */
        public Builder stack(Supplier<List<Layer>> topFirstLayers) {
            this.stackFactory = Objects.requireNonNull(topFirstLayers, "stack");
            return this;
        }

        /**
         * Whether an application message from one agent of this runtime to another is handed over
         * in memory, a copy into the receiver's mailbox, as JADE does inside a container (default
         * true; {@code -Dconcord.handover.off=true} turns it off). It never leaves the process, so
         * the transmission defences (sequence, time, CRC, encryption) have nothing to defend, and
         * it passes neither stack. Only where the network delivers between the two in memory (not
         * on the test kit's, which may lose frames); only the agent's own messages; never a
         * message a layer acts on itself (platform, service and observation messages, and any
         * message while either agent is sniffed). A receiver whose mailbox is over half full
         * pauses its senders until it has taken it down to a quarter, as flow control does.
         */
        public Builder handOver(boolean on) {
            this.handOver = on;
            return this;
        }

        /**
         * The loops of one platform in this JVM that this runtime is one of (see {@link LoopGroup}):
         * an application message between agents of two of them (of one platform name, on one
         * transport) is handed over in memory, under the same conditions as within one
         * ({@link #handOver}, which both runtimes must have on; only where both networks deliver in
         * memory, so never on the test kit's), and is counted in {@link AgentRuntime#handedOver()} of
         * the sender's runtime. Null (the default):
         * agents of other runtimes are reached through the stacks and the network, as other JVMs'.
         * {@code Platform.Builder.loops(n)} makes one group of its n loops.
         */
        public Builder group(LoopGroup group) {
            this.group = group;
            return this;
        }

        /** Messages an agent's mailbox may hold before new ones are dropped (and counted). */
        public Builder mailboxCapacity(int capacity) {
            this.mailboxCapacity = capacity;
            return this;
        }

        /**
         * How many empty work cycles the loop spins before it starts yielding the CPU (default 0).
         * Spinning catches a reply that comes within microseconds without a kernel wake-up, but
         * holds the core while it waits; yielding catches it nearly as fast and lets others run.
         */
        public Builder idleSpinIterations(int iterations) {
            this.idleSpinIterations = iterations;
            return this;
        }

        /**
         * How many further empty cycles it yields the CPU (so that other processes on a busy machine
         * run) before it parks on the network until a datagram, a task or a timer (default 200).
         * The loop adapts how much of spin and yield it uses to how often waiting awake pays.
         */
        public Builder idleYieldIterations(int iterations) {
            this.idleYieldIterations = iterations;
            return this;
        }

        /**
         * @throws IllegalArgumentException naming the first bad setting
         */
        public AgentRuntime build() {
            if (platformName.isEmpty() || platformName.contains("@") || platformName.chars().anyMatch(c -> c <= ' ')) {
                throw new IllegalArgumentException("platformName must be a non-empty word without '@' or spaces, got '"
                        + platformName + "'");
            }
            if (host.isEmpty()) {
                throw new IllegalArgumentException("host must not be empty; use 127.0.0.1 for this machine only");
            }
            if (mailboxCapacity < 1) {
                throw new IllegalArgumentException("mailboxCapacity must be >= 1, got " + mailboxCapacity);
            }
            if (idleSpinIterations < 0 || idleYieldIterations < 0) {
                throw new IllegalArgumentException("idleSpinIterations and idleYieldIterations must be >= 0, got "
                        + idleSpinIterations + " and " + idleYieldIterations);
            }
            return new AgentRuntime(this);
        }
    }

    // ---- agents -----------------------------------------------------------------------------------

    /** Starts an agent on any free port. See {@link #startAgentOnPort(String, Agent, int, Object...)}. */
    public AID startAgent(String localName, Agent agent, Object... args) {
        return startAgentOnPort(localName, agent, 0, args);
    }

    /**
     * Starts an agent: binds its port, builds its stack, runs its {@code setup()}. Thread-safe;
     * returns when the agent is running.
     *
     * @param localName the name without the platform; unique in this runtime
     * @param port      its reception port, or 0 for any free one
     * @return its AID, with its transport address
     * @throws IllegalArgumentException if the name is bad or taken
     * @throws IllegalStateException    if the port is taken, or setup() failed
     */
    public AID startAgentOnPort(String localName, Agent agent, int port, Object... args) {
        return startAgentWith(localName, agent, AgentOptions.defaults().withPort(port), args);
    }

    /**
     * Starts an agent with options of its own: its port and its stack of layers.
     *
     * @see #startAgentOnPort(String, Agent, int, Object...)
     */
    public AID startAgentWith(String localName, Agent agent, AgentOptions options, Object... args) {
        Objects.requireNonNull(agent, "agent");
        Objects.requireNonNull(options, "options");
        if (!inLoop()) {
            return callInLoop(() -> startAgentInLoop(localName, agent, options, args));
        }
        return startAgentInLoop(localName, agent, options, args);
    }

    private AID startAgentInLoop(String localName, Agent agent, AgentOptions options, Object[] args) {
        int port = options.port();
        if (closed) {
            throw new IllegalStateException("the runtime is closed");
        }
        if (localName == null || localName.isEmpty() || localName.contains("@")
                || localName.chars().anyMatch(c -> c <= ' ' || c == '(' || c == ')' || c == '"')) {
            throw new IllegalArgumentException("an agent name must be a non-empty word without '@', spaces, "
                    + "quotes or parentheses, got '" + localName + "'");
        }
        AID nameOnly = AID.local(localName, platformName);
        if (directory.containsKey(nameOnly)) {
            throw new IllegalArgumentException("an agent named " + nameOnly.name() + " already runs here");
        }
        if (agent.getState() != Agent.State.INITIATED || agent.runtime() != null) {
            throw new IllegalArgumentException("this Agent object has already been started; create a new one");
        }
        AgentNode[] holder = new AgentNode[1];
        Transport t = options.transport() != null ? options.transport() : transport;
        io.concord.core.net.Receiver receiver = new io.concord.core.net.Receiver() {
            @Override
            public void onDatagram(Address from, byte[] data, int off, int len, long now) {
                holder[0].onDatagram(from, data, off, len, now);
            }

            @Override
            public void onRefused(Address from, String reason, String detail) {
                AgentNode n = holder[0];
                if (n != null) {
                    n.drops().record(n.nodeName(), "communication", reason, detail);
                }
            }
        };
        List<Address> neighbours = List.of();
        Endpoint ep;
        if (options.portRange() != null) {
            PortRange range = options.portRange();
            List<Address> held = new ArrayList<>();
            ep = range.bindFirstFree(network, t, host, receiver, held);
            neighbours = List.copyOf(held);
        } else {
            ep = network.tryBind(t, host, port, receiver);
            if (ep == null) {
                throw new IllegalStateException(t + " port " + port + " on " + host + " is already in use; "
                        + "choose another port or 0 for any free one");
            }
        }
        AID aid = new AID(nameOnly.name(), ep.localAddress().toUri(t));
        AgentNode node = new AgentNode(this, agent, aid, ep, t);
        holder[0] = node;
        node.neighbours = neighbours;
        try {
            List<Layer> layers = (options.stack() != null ? options.stack() : stackFactory).get();
            node.stack = new LayerStack(layers, node, node::deliver, node::transmit, ev -> { });
            node.stack.start();
        } catch (RuntimeException e) {
            ep.close();
            throw new IllegalStateException("the stack of " + aid.name() + " could not start: " + e.getMessage(), e);
        }
        directory.put(aid, node);
        byAddress.put(ep.localAddress(), node);
        if (group != null && ep.inMemoryTo(ep.localAddress())) {
            group.add(node); // only where its network hands frames over in memory (never the test kit's)
        }
        agent.bind(this, node, aid, args);
        if (tracer.enabled()) {
            tracer.trace(nowNs, aid.name(), "start", ep.localAddress().toString());
        }
        try {
            agent.activate();
        } catch (RuntimeException e) {
            removeAgent(node, false);
            throw new IllegalStateException("setup() of " + aid.name() + " failed: " + e, e);
        }
        makeReady(node);
        return aid;
    }

    /** The agents running here, in start order. */
    public List<AID> agents() {
        if (!inLoop()) {
            return callInLoop(this::agents);
        }
        return new ArrayList<>(directory.keySet());
    }

    /** The agent with this name here, or {@code null}. */
    public Agent agent(AID aid) {
        AgentNode n = directory.get(aid);
        return n == null ? null : n.agent;
    }

    /** Drops counted by one agent's stack, by reason. */
    public Map<String, Long> drops(AID aid) {
        AgentNode n = directory.get(aid);
        return n == null ? Map.of() : n.drops.snapshot();
    }

    /** Drops counted by all agents here, by reason. */
    public Map<String, Long> drops() {
        Map<String, Long> sum = new TreeMap<>();
        for (AgentNode n : directory.values()) {
            n.drops.snapshot().forEach((k, v) -> sum.merge(k, v, Long::sum));
        }
        return sum;
    }

    /** The layers of an agent's stack, top first (for tests and tools). */
    public List<Layer> layers(AID aid) {
        AgentNode n = directory.get(aid);
        return n == null ? List.of() : n.stack.layers();
    }

    /** The topmost layer of this type in an agent's stack, or {@code null} (no such agent or layer). */
    public <T> T layer(AID aid, Class<T> type) {
        AgentNode n = directory.get(aid);
        return n == null ? null : n.stack.find(type);
    }

    /**
     * Kills an agent without its takeDown, as a crash would: its port closes, its timers die. For
     * simulations and failure tests.
     */
    public void crashAgent(AID aid) {
        AgentNode n = directory.get(aid);
        if (n != null) {
            removeAgent(n, false);
        }
    }

    /**
     * The agent of this runtime a node may hand a message to in memory at that address, or
     * {@code null} (hand-over off, no such agent, another transport, not reached in memory).
     */
    AgentNode handOverTarget(AgentNode from, Address to) {
        if (!handOver || to == null) {
            return null;
        }
        AgentNode peer = byAddress.get(to);
        if (peer == null && group != null && from.endpoint.inMemoryTo(from.endpoint.localAddress())) {
            // Another loop's: its crashed flag and state are read here as a hint; its loop checks
            // them again when it takes the message.
            peer = group.at(to);
            return peer != null && peer.runtime != this && peer.runtime.handOver && peer.transport == from.transport
                    && peer.runtime.platformName.equals(platformName)
                    && !peer.crashed && peer.agent.getState() != Agent.State.DELETED ? peer : null;
        }
        return peer != null && peer.transport == from.transport && !peer.crashed && peer.agent.getState() != Agent.State.DELETED
                && from.endpoint.inMemoryTo(to) ? peer : null;
    }

    /** The address of an agent of another loop of this platform in this JVM, by name; null if none (or no group). */
    Address resolveInGroup(AID aid, Transport t) {
        if (group == null || !handOver) {
            return null;
        }
        AgentNode n = group.named(aid.name());
        return n != null && n.runtime != this && n.transport == t && n.runtime.platformName.equals(platformName)
                ? n.endpoint.localAddress() : null;
    }

    /**
     * Messages this runtime's agents handed over in memory, since start: to agents of this runtime,
     * and to agents of the other loops of its {@link LoopGroup}. Any thread.
     */
    public long handedOver() {
        return handedOver;
    }

    void countHandOver() {
        handedOver++;
    }

    /** An agent of this runtime with the given transport, by name; {@code null} if none. */
    Address resolveLocal(AID aid, Transport t) {
        AgentNode local = directory.get(aid);
        return local != null && local.transport == t ? local.endpoint.localAddress() : null;
    }

    /**
     * Where to send to an agent over the given transport: an agent of this runtime by name, else
     * the first address of that transport in its AID. {@code null} if neither is known.
     */
    Address resolve(AID aid, Transport t) {
        Address a = resolveLocal(aid, t);
        return a != null ? a : resolveByAddress(aid, t);
    }

    /** The first address of the transport in the AID, parsed (and cached); {@code null} if none. */
    Address resolveByAddress(AID aid, Transport t) {
        String uri = aid.firstAddress(t.scheme());
        if (uri == null) {
            return null;
        }
        Address a = addressCache.get(uri);
        if (a == null) {
            a = Address.parse(uri);
            if (a != null) {
                if (addressCache.size() > 100_000) {
                    addressCache.clear();
                }
                addressCache.put(uri, a);
            }
        }
        return a;
    }

    /** Written by the loop only; read anywhere. */
    private volatile long pauses;

    /**
     * How many times an agent of this runtime was paused because a receiver did not take its
     * messages as fast as it sent them (flow control: the sequence layer's window, or a receiver's mailbox
     * over half full when messages are handed over). Any thread.
     */
    public long pauses() {
        return pauses;
    }

    /** The transport addresses this runtime's agents hold (the test kit pauses what arrives there). Loop thread only. */
    public java.util.Set<Address> boundAddresses() {
        return java.util.Set.copyOf(byAddress.keySet());
    }

    /** Who watches which address of this runtime for its agent's leaving. */
    private final Map<Address, List<Runnable>> goneWatchers = new HashMap<>();
    private final Map<Address, AgentNode> byAddress = new HashMap<>();

    private final CoLocated coLocated = new CoLocated() {
        @Override
        public boolean here(Address address) {
            AgentNode n = byAddress.get(address);
            return n != null && n.endpoint.isOpen();
        }

        @Override
        public Runnable whenGone(Address address, Runnable callback) {
            if (!here(address)) {
                execute(callback);
                return () -> { };
            }
            Runnable once = new Runnable() {
                private boolean done;

                @Override
                public void run() {
                    if (!done) {
                        done = true;
                        callback.run();
                    }
                }
            };
            goneWatchers.computeIfAbsent(address, k -> new ArrayList<>()).add(once);
            return () -> {
                List<Runnable> l = goneWatchers.get(address);
                if (l != null && l.remove(once) && l.isEmpty()) {
                    goneWatchers.remove(address);
                }
            };
        }

        @Override
        public <T> T layer(Address address, Class<T> type) {
            AgentNode n = byAddress.get(address);
            return n == null || !n.endpoint.isOpen() || n.stack == null ? null : n.stack.find(type);
        }
    };

    CoLocated coLocated() {
        return coLocated;
    }

    private void removeAgent(AgentNode node, boolean takeDown) {
        if (!takeDown) {
            directory.remove(node.aid);
            node.crashed = true; // a crash: nothing more goes out, not even what the layers say on stop
            node.endpoint.close();
            node.agent.terminate(false);
        } else {
            // takeDown runs while the agent is still itself: its layers answer (it deregisters from
            // the DF there, as JADE code does), and it leaves the directory after.
            node.agent.terminate(true);
            directory.remove(node.aid);
        }
        node.stack.stop();
        node.endpoint.close();
        Address at = node.endpoint.localAddress();
        byAddress.remove(at, node);
        if (group != null) {
            group.remove(node, at);
        }
        releaseSenders(node);
        node.gone = true; // before the senders of other loops are let go: one that comes after sees it
        releaseAcross(node, true);
        for (AgentNode r : node.waitingOn) {
            if (r.runtime == this) {
                r.heldSenders.remove(node);
            } else {
                r.heldAcross.remove(node);
            }
        }
        node.waitingOn.clear();
        List<Runnable> watchers = goneWatchers.remove(at);
        if (tracer.enabled()) {
            tracer.trace(nowNs, node.aid.name(), takeDown ? "stop" : "crash", "");
        }
        if (watchers != null) {
            // Told on the next cycle, not in the middle of this removal (or of a whole crash).
            for (Runnable w : watchers) {
                tasks.add(w);
            }
        }
    }

    // ---- the loop -------------------------------------------------------------------------------

    /**
     * One work cycle: tasks handed in by other threads, arrived datagrams, due timers, then one
     * round of every agent that has a runnable behaviour.
     *
     * @return the amount of work done; 0 means idle
     */
    public int doWork() {
        nowNs = clock.nanoTime();
        int work = 0;
        Runnable t;
        while ((t = tasks.poll()) != null) {
            try {
                t.run();
            } catch (RuntimeException e) {
                LOG.error("task failed on the loop", e);
            }
            work++;
        }
        work += network.poll(nowNs);
        arrived = work > 0;
        work += wheel.poll(nowNs, this::onTimer);
        work += runReady();
        flushAcross();   // what this cycle handed to agents of other loops
        network.flush(); // what this cycle sent, gathered into as few datagrams as it takes
        return work;
    }

    /** Whether the last {@link #doWork} found a task or a datagram: work that no timer foretold. */
    private boolean arrived;

    private int runReady() {
        int n = ready.size();
        for (int i = 0; i < n; i++) {
            AgentNode node = ready.poll();
            node.queued = false;
            Agent agent = node.agent;
            if (agent.getState() == Agent.State.DELETED) {
                continue;
            }
            if ((node.backpressured || !node.waitingOn.isEmpty()) && !agent.inboxFull() && !agent.deleteRequested()) {
                continue; // made ready again when its stack lets its frames go
            }
            boolean more = !agent.deleteRequested() && agent.runRound();
            releaseAcross(node, false);
            if (agent.deleteRequested()) {
                removeAgent(node, true);
            } else if (more) {
                makeReady(node);
            }
        }
        return n;
    }

    /** A node handed a message to a receiver whose mailbox is over half full: it waits for it. */
    void waitFor(AgentNode node, AgentNode receiver) {
        if (node.waitingOn.isEmpty() && !node.backpressured) {
            pauses++;
        }
        if (node.waitingOn.add(receiver)) {
            receiver.heldSenders.add(node);
        }
    }

    /** The receiver took its mailbox down (or left): its waiting senders go on. */
    void releaseSenders(AgentNode receiver) {
        for (AgentNode s : receiver.heldSenders) {
            if (s.waitingOn.remove(receiver) && s.waitingOn.isEmpty()) {
                makeReady(s);
            }
        }
        receiver.heldSenders.clear();
    }

    /**
     * A node of another loop handed a message to {@code receiver} (of this one) and found its
     * mailbox over half full: it waits for it. On the sender's loop. The receiver's loop may have
     * taken its mailbox down meanwhile, unseen: looked at again once the sender is in its list.
     */
    void waitAcross(AgentNode sender, AgentNode receiver) {
        boolean first = sender.waitingOn.isEmpty() && !sender.backpressured;
        sender.waitingOn.add(receiver);
        receiver.heldAcross.add(sender); // again if it was let go meanwhile, its release still on its way
        if (receiver.gone || !receiver.overHalfAcross()) {
            // Left, or taken down, before it could see this sender in its list.
            receiver.heldAcross.remove(sender);
            sender.waitingOn.remove(receiver);
        } else if (first) {
            pauses++;
        }
    }

    /**
     * The senders of other loops that wait for this loop's {@code receiver} go on (on their own
     * loops) once it is no longer {@link AgentNode#overHalfAcross() over half} (its mailbox down to
     * a quarter, and it with what is queued for it at most half its capacity), or if it left ({@code gone}). On the
     * receiver's loop.
     */
    void releaseAcross(AgentNode receiver, boolean gone) {
        if (receiver.heldAcross.isEmpty() || (!gone && receiver.overHalfAcross())) {
            return;
        }
        for (AgentNode s : receiver.heldAcross) {
            if (receiver.heldAcross.remove(s)) {
                s.runtime.execute(() -> s.runtime.stopWaiting(s, receiver));
            }
        }
    }

    /** Messages this loop's agents handed to agents of other loops in this cycle, by their loop. Loop only. */
    private final Map<AgentRuntime, List<Handed>> handing = new HashMap<>();

    private record Handed(AgentNode to, AclMessage message, AgentNode from) {
    }

    /**
     * Hands a message (the receiver's copy) to an agent of another loop: gathered with the rest of
     * this cycle's for that loop, which gets them at the cycle's end in one task, in order.
     */
    void handAcross(AgentNode to, AclMessage message, AgentNode from) {
        handing.computeIfAbsent(to.runtime, k -> new ArrayList<>()).add(new Handed(to, message, from));
    }

    /** What this cycle handed to other loops goes to them: one task and at most one wake-up each. */
    private void flushAcross() {
        if (handing.isEmpty()) {
            return;
        }
        for (Map.Entry<AgentRuntime, List<Handed>> e : handing.entrySet()) {
            List<Handed> batch = e.getValue();
            if (!e.getKey().running && e.getKey().loopThread != null) {
                for (Handed h : batch) { // its loop has stopped: nobody would take them
                    h.from().drops.record(h.from().aid.name(), "receiver-gone", h.to().aid.name() + "'s loop has stopped");
                }
                continue;
            }
            e.getKey().execute(() -> {
                for (int i = 0, n = batch.size(); i < n; i++) {
                    Handed h = batch.get(i);
                    h.to().receiveAcross(h.message(), h.from());
                }
            });
        }
        handing.clear();
    }

    /** On the sender's loop: it no longer waits for that receiver of another loop. */
    private void stopWaiting(AgentNode sender, AgentNode receiver) {
        if (sender.waitingOn.remove(receiver) && sender.waitingOn.isEmpty()) {
            makeReady(sender);
        }
    }

    /**
     * The node's stack holds frames back for a slower receiver: its behaviours wait until it
     * holds none (unless its own mailbox is full: it may be the one its receiver waits for).
     */
    void backpressure(AgentNode node, boolean on) {
        if (on && !node.backpressured) {
            pauses++;
        }
        node.backpressured = on;
        if (!on) {
            makeReady(node);
        }
    }

    void makeReady(AgentNode node) {
        if (!node.queued && node.agent.getState() != Agent.State.DELETED) {
            node.queued = true;
            ready.add(node);
        }
    }

    private void onTimer(long now, long wheelId) {
        Timer t = timersByWheelId.remove(wheelId);
        if (t == null) {
            return;
        }
        timersById.remove(t.id);
        try {
            t.task.run();
        } catch (RuntimeException e) {
            LOG.error("timer task failed", e);
        }
    }

    /** Runs a task on the loop at or after a deadline (loop time, ns); returns an id for {@link #cancel}. */
    public long schedule(long deadlineNs, Runnable task) {
        long id = ++nextTimerId;
        long wheelId = wheel.schedule(deadlineNs);
        Timer t = new Timer(id, wheelId, task);
        timersById.put(id, t);
        timersByWheelId.put(wheelId, t);
        return id;
    }

    /** Cancels a scheduled task; false if it already ran or was cancelled. */
    public boolean cancel(long timerId) {
        Timer t = timersById.remove(timerId);
        if (t == null) {
            return false;
        }
        wheel.cancel(t.wheelId);
        timersByWheelId.remove(t.wheelId);
        return true;
    }

    /** The earliest time at which this runtime has work, for a simulation to advance its clock to. */
    public long nextDeadlineNs() {
        if (!ready.isEmpty() || !tasks.isEmpty()) {
            return nowNs;
        }
        return Math.min(wheel.earliestDeadline(), network.nextEventNs());
    }

    /** Runs a task on the loop. Thread-safe. */
    public void execute(Runnable task) {
        tasks.add(task);
        if (parked) {
            network.wakeup();
            Thread loop = loopThread;
            if (loop != null) {
                LockSupport.unpark(loop);
            }
        }
    }

    /** True on the thread that drives this runtime. */
    public boolean inLoop() {
        Thread loop = loopThread;
        return Thread.currentThread() == (loop != null ? loop : ownerThread);
    }

    private <T> T callInLoop(Supplier<T> body) {
        if (!running) {
            throw new IllegalStateException("call from the thread that drives this runtime, or start() it first");
        }
        CompletableFuture<T> f = new CompletableFuture<>();
        execute(() -> {
            try {
                f.complete(body.get());
            } catch (RuntimeException e) {
                f.completeExceptionally(e);
            }
        });
        try {
            return f.get(30, TimeUnit.SECONDS);
        } catch (ExecutionException e) {
            if (e.getCause() instanceof RuntimeException re) {
                throw re;
            }
            throw new CompletionException(e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the loop", e);
        } catch (TimeoutException e) {
            throw new IllegalStateException("the loop did not answer within 30 s; is a behaviour blocking it?", e);
        }
    }

    /** Gives the runtime a thread of its own that runs the loop until {@link #close()}. */
    public AgentRuntime start() {
        if (running) {
            return this;
        }
        running = true;
        Thread t = new Thread(this::loop, "concord-loop-" + platformName);
        loopThread = t;
        t.start();
        return this;
    }

    /** How the loop waits when it has no work (made when the loop starts). */
    private volatile IdleStrategy idleStrategy;

    /** Idle waits cut short because yielding found the cores contended (the console, the benchmarks). */
    public long contendedYields() {
        IdleStrategy w = idleStrategy;
        return w == null ? 0 : w.contendedYields();
    }

    private void loop() {
        final IdleStrategy waiting = new IdleStrategy(clock, idleSpinIterations, idleYieldIterations);
        idleStrategy = waiting;
        final long resolutionNs = network.awaitResolutionNs();
        while (running) {
            int work;
            try {
                work = doWork();
            } catch (RuntimeException | Error e) {
                LOG.error("loop cycle failed; going on", e);
                work = 1;
                arrived = true;
            }
            if (work > 0) {
                waiting.worked(arrived);
                continue;
            }
            if (waiting.waitAwake()) {
                continue;
            }
            parked = true;
            long parkedAtNs = waiting.parking();
            if (tasks.isEmpty() && running) {
                long next = wheel.earliestDeadline();
                long timeout = next == Long.MAX_VALUE ? TimeUnit.SECONDS.toNanos(1) : next - parkedAtNs;
                if (timeout > 0 && timeout < resolutionNs) {
                    // The network's wait counts in coarse units (select(): whole milliseconds), and
                    // a timer is due within one: sleep exactly until it instead of yielding the CPU
                    // away meanwhile (a task from another thread unparks; a datagram waits for the
                    // timer, less than a millisecond).
                    LockSupport.parkNanos(timeout);
                } else if (timeout > 0) {
                    // Whole units only, so as to wake before the deadline; the rest as above.
                    network.await(resolutionNs <= 1 ? timeout : timeout / resolutionNs * resolutionNs);
                }
            }
            parked = false;
            waiting.woke(parkedAtNs);
        }
    }

    /** Stops every agent (running their takeDown), the loop, and the network if it made it. Idempotent. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        if (running && !inLoop()) {
            try {
                callInLoop(() -> {
                    shutdownAgents();
                    return null;
                });
            } catch (RuntimeException e) {
                LOG.warn("agents did not stop cleanly: {}", e.toString());
            }
            running = false;
            network.wakeup();
            try {
                loopThread.join(10_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        } else {
            running = false;
            shutdownAgents();
        }
        closed = true;
        if (ownsNetwork) {
            network.close();
        }
    }

    /** Crashes every agent at once (no takeDown), as a killed process would. */
    public void crash() {
        for (AgentNode n : new ArrayList<>(directory.values())) {
            removeAgent(n, false);
        }
        ready.clear();
    }

    private void shutdownAgents() {
        for (AgentNode n : new ArrayList<>(directory.values())) {
            removeAgent(n, true);
        }
        ready.clear();
        flushAcross(); // what their takeDowns said to agents of other loops
    }

    // ---- services ---------------------------------------------------------------------------------

    public Clock clock() {
        return clock;
    }

    /** The loop's time, read once at the start of each work cycle. */
    public long nowNs() {
        return nowNs;
    }

    public RandomGenerator random() {
        return random;
    }

    /**
     * Fills {@code out} with bytes nobody can guess (a secret, a key): from a {@link SecureRandom},
     * unless this runtime was given its random source or a seed (a simulation, which must replay
     * bit for bit), whose bytes it takes instead. Loop thread, or any thread for a SecureRandom.
     */
    public void secretBytes(byte[] out) {
        if (secrets != null) {
            secrets.nextBytes(out);
        } else {
            random.nextBytes(out);
        }
    }

    /** The rate limits every agent of this loop shares. Loop thread only. */
    LoopLimits loopLimits() {
        return loopLimits;
    }

    public Tracer tracer() {
        return tracer;
    }

    public String platformName() {
        return platformName;
    }

    public String host() {
        return host;
    }

    public Network network() {
        return network;
    }

    int mailboxCapacity() {
        return mailboxCapacity;
    }
}
