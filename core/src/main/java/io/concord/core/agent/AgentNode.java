package io.concord.core.agent;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MtsFailure;
import io.concord.core.agent.internal.CoLocated;
import io.concord.core.layer.DropCounters;
import io.concord.core.layer.Envelope;
import io.concord.core.layer.LayerStack;
import io.concord.core.layer.SendRejectedException;
import io.concord.core.layer.StackEvent;
import io.concord.core.layer.StackHost;
import io.concord.core.layer.Tracer;
import io.concord.core.net.Address;
import io.concord.core.net.Channels;
import io.concord.core.net.Endpoint;
import io.concord.core.net.internal.Neighbourhood;
import io.concord.core.net.SocketNetwork;
import io.concord.core.net.Transport;
import io.concord.core.time.Clock;
import io.concord.core.time.internal.LoopLimits;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.LongSupplier;
import java.util.random.RandomGenerator;

/**
 * What the runtime keeps per agent: its endpoint, its stack, its counters. The stack's top
 * delivers into the agent's mailbox; its bottom transmits through the endpoint.
 */
final class AgentNode implements StackHost {
    final AgentRuntime runtime;
    final Agent agent;
    final AID aid;
    final Endpoint endpoint;
    final Transport transport;
    final DropCounters drops = new DropCounters();
    LayerStack stack;
    boolean queued;
    /** Set when the agent crashes: from then on nothing leaves or enters its stack. */
    boolean crashed;
    /** Set (on its loop) when the agent has left, before its senders of other loops are let go: they read it. */
    volatile boolean gone;
    LongSupplier platformTime;
    List<Address> neighbours = List.of();

    AgentNode(AgentRuntime runtime, Agent agent, AID aid, Endpoint endpoint, Transport transport) {
        this.runtime = runtime;
        this.agent = agent;
        this.aid = aid;
        this.endpoint = endpoint;
        this.transport = transport;
        endpoint.onSendFailure((to, frames) -> {
            for (int i = 0; i < frames; i++) {
                drops.record(aid.name(), "send-failed", "the network refused the datagram to " + to);
            }
        });
    }

    public void send(AclMessage msg) {
        if (msg.getSender() == null) {
            msg.setSender(aid);
        }
        if (msg.getReceivers().isEmpty()) {
            dropOutgoing(msg, "no-receiver", "the message lists no receiver");
            return;
        }
        Tracer tracer = runtime.tracer();
        boolean byName = stack.resolvesNames();
        for (AID receiver : msg.getReceivers()) {
            // An agent of this runtime by name; else, unless a layer finds receivers by name (the
            // container layer, from the platform's lists), the first address of the AID.
            Address dst = runtime.resolveLocal(receiver, transport);
            if (dst == null) {
                dst = runtime.resolveInGroup(receiver, transport); // an agent of another loop of this JVM
            }
            if (dst == null && !byName) {
                dst = runtime.resolveByAddress(receiver, transport);
                if (dst == null) {
                    dropOutgoing(msg, "unknown-receiver", "no " + transport + " address known for " + receiver.name());
                    returnFailure(msg, receiver);
                    continue;
                }
            }
            if (tracer.enabled()) {
                tracer.trace(runtime.nowNs(), aid.name(), "send", Tracer.describe(msg) + " to " + receiver.name());
            }
            AgentNode peer = runtime.handOverTarget(this, dst);
            if (peer != null && (peer.runtime == runtime ? handOver(msg, peer) : handOverAcross(msg, peer))) {
                sentCount++;
                continue;
            }
            sentCount++;
            stack.sendDown(Envelope.outgoing(msg, receiver, dst).markSentByAgent());
        }
    }

    /** Senders waiting for this agent to take its mailbox down, and the receivers this one waits for. */
    final Set<AgentNode> heldSenders = new LinkedHashSet<>();
    final Set<AgentNode> waitingOn = new LinkedHashSet<>();

    /**
     * Hands an application message of this agent to an agent of the runtime in memory (see
     * {@code AgentRuntime.Builder#handOver}); false if it must take the stacks.
     *
     * @throws io.concord.core.layer.SendRejectedException if the receiver's mailbox is full
     */
    private boolean handOver(AclMessage msg, AgentNode peer) {
        if (!aid.name().equals(msg.getSender().name()) || !stack.mayHandOver(msg) || !peer.stack.mayHandOver(msg)) {
            return false; // in another's name (the receiver's stack refuses it, counted), or a layer's own
        }
        if (!peer.post(msg.copy())) {
            String why = peer.aid.name() + "'s mailbox holds " + runtime.mailboxCapacity() + " messages; "
                    + "send again when it has taken some (this agent was paused from half of it)";
            drops.record(aid.name(), "flow-control", why);
            throw new SendRejectedException("flow-control", why);
        }
        runtime.countHandOver();
        if (peer.agent.inboxFull()) {
            runtime.waitFor(this, peer);
        }
        return true;
    }

    /** Senders of other loops waiting for this agent to take its mailbox down (any thread adds; this loop releases). */
    final Set<AgentNode> heldAcross = java.util.concurrent.ConcurrentHashMap.newKeySet();
    /** Messages handed to this agent by other loops and not yet in its mailbox. */
    private final java.util.concurrent.atomic.AtomicInteger queuedAcross = new java.util.concurrent.atomic.AtomicInteger();

    /**
     * True if this agent's mailbox is over half full (until it is down to a quarter, as on one loop),
     * or its mailbox and what other loops have queued for it hold more than half its capacity. Any
     * thread; the mailbox's size is read (under its lock) only once a quarter is queued.
     */
    boolean overHalfAcross() {
        int capacity = runtime.mailboxCapacity();
        int queued = queuedAcross.get();
        return agent.inboxFull() || queued > capacity / 4 && agent.mailboxSize() + queued > capacity / 2;
    }

    /**
     * As {@link #handOver}, to an agent of another loop of this JVM ({@link LoopGroup}): a copy is
     * gathered with what this loop's cycle hands that loop, and that loop posts it into the
     * mailbox ({@link AgentRuntime#handAcross}). On this agent's loop.
     *
     * @throws io.concord.core.layer.SendRejectedException if the receiver's mailbox, with what is
     *                                                     queued for it, is full (looked at under the
     *                                                     mailbox's lock only once it is over half)
     */
    private boolean handOverAcross(AclMessage msg, AgentNode peer) {
        if (!aid.name().equals(msg.getSender().name()) || !stack.mayHandOver(msg) || !peer.stack.mayHandOver(msg)) {
            return false;
        }
        int capacity = peer.runtime.mailboxCapacity();
        int queued = peer.queuedAcross.incrementAndGet();
        if ((queued > capacity / 2 || peer.agent.inboxFull()) && peer.agent.mailboxSize() + queued > capacity) {
            peer.queuedAcross.decrementAndGet();
            String why = peer.aid.name() + "'s mailbox holds " + capacity + " messages; "
                    + "send again when it has taken some (this agent was paused from half of it)";
            drops.record(aid.name(), "flow-control", why);
            throw new SendRejectedException("flow-control", why);
        }
        runtime.handAcross(peer, msg.copy(), this);
        runtime.countHandOver();
        if (peer.overHalfAcross()) {
            runtime.waitAcross(this, peer);
        }
        return true;
    }

    /** A message another loop's agent handed over ({@link #handOverAcross}): into the mailbox. On this agent's loop. */
    void receiveAcross(AclMessage msg, AgentNode from) {
        try {
            if (crashed || agent.getState() == Agent.State.DELETED) {
                from.drops.record(from.aid.name(), "receiver-gone", aid.name() + " left before its loop took the message");
                return;
            }
            if (!post(msg)) {
                // Agents of this loop filled the mailbox meanwhile (they post straight into it).
                dropOutgoing(msg, "mailbox-full", "the mailbox holds " + runtime.mailboxCapacity() + " messages");
            }
        } finally {
            queuedAcross.decrementAndGet(); // once it is in the mailbox (or dropped): a sender never sees it in neither
        }
    }

    private void dropOutgoing(AclMessage msg, String reason, String detail) {
        drops.record(aid.name(), reason, detail);
        Tracer t = runtime.tracer();
        if (t.enabled()) {
            t.trace(runtime.nowNs(), aid.name(), "drop", reason + ": " + detail + " " + Tracer.describe(msg));
        }
    }

    /**
     * Tells the sender that a receiver is unknown, with the FAILURE JADE's AMS sends, so that
     * protocols end instead of waiting.
     */
    private void returnFailure(AclMessage original, AID receiver) {
        deliverMessage(MtsFailure.of(runtime.platformName(), original, receiver,
                "Agent not found: " + receiver.name()));
    }

    /** The bottom of the stack: to the network. */
    void transmit(Envelope env) {
        if (crashed) {
            return;
        }
        if (transport == Transport.UDP && env.length() > SocketNetwork.MAX_DATAGRAM) {
            stackDrop(env, "too-large", env.length() + " bytes exceed the datagram limit of "
                    + SocketNetwork.MAX_DATAGRAM);
            return;
        }
        if (!endpoint.send(env.destination(), env.data(), env.offset(), env.length(), env.lane())) {
            stackDrop(env, "send-failed", "the network refused the datagram to " + env.destination());
        }
    }

    private void stackDrop(Envelope env, String reason, String detail) {
        drops.record(aid.name(), reason, detail);
        Tracer t = runtime.tracer();
        if (t.enabled()) {
            t.trace(runtime.nowNs(), aid.name(), "drop", reason + ": " + detail + " " + env);
        }
    }

    /** From the network. */
    void onDatagram(Address from, byte[] data, int offset, int length, long nowNs) {
        if (crashed || agent.getState() == Agent.State.DELETED) {
            return;
        }
        stack.receiveUp(Envelope.incoming(from, data, offset, length, nowNs));
    }

    /** Frames of this agent are held back by its stack (a receiver is slower): its behaviours wait. */
    boolean backpressured;

    @Override
    public boolean inboxFull() {
        return agent.inboxFull();
    }

    /** Messages the agent sent (one a receiver) and got into its mailbox, whichever way they went: on the loop. */
    private long sentCount;
    private long receivedCount;

    @Override
    public long messagesSent() {
        return sentCount;
    }

    @Override
    public long messagesReceived() {
        return receivedCount;
    }

    @Override
    public int mailboxSize() {
        return agent.mailboxSize();
    }

    @Override
    public void deleteAgent() {
        agent.doDelete();
    }

    @Override
    public void backpressure(boolean on) {
        runtime.backpressure(this, on);
    }

    /** The agent took its full mailbox down: the stack lets its senders go on. On the loop. */
    void inboxDrained() {
        runtime.releaseSenders(this);
        runtime.releaseAcross(this, false);
        if (!crashed && endpoint.isOpen()) {
            stack.fireEvent(new StackEvent(INBOX_DRAINED, null, false));
        }
    }

    /** The top of the stack: into the mailbox. */
    void deliver(Envelope env) {
        deliverMessage(env.message());
    }

    private void deliverMessage(AclMessage msg) {
        if (!post(msg)) {
            dropOutgoing(msg, "mailbox-full", "the mailbox holds " + runtime.mailboxCapacity() + " messages");
        }
    }

    /** Into the mailbox, stamped and traced; false if the mailbox is full (nothing kept). */
    private boolean post(AclMessage msg) {
        msg.setReceivedAtEpochMs(platformMillis());
        if (!agent.postMessage(msg, runtime.mailboxCapacity())) {
            return false;
        }
        receivedCount++;
        Tracer t = runtime.tracer();
        if (t.enabled()) {
            t.trace(runtime.nowNs(), aid.name(), "deliver", Tracer.describe(msg));
        }
        return true;
    }

    @Override
    public String nodeName() {
        return aid.name();
    }

    @Override
    public Address localAddress() {
        return endpoint.localAddress();
    }

    @Override
    public boolean inMemoryTo(Address to) {
        return endpoint.inMemoryTo(to);
    }

    @Override
    public Transport transport() {
        return transport;
    }

    @Override
    public void setPlatformTime(LongSupplier epochMillis) {
        this.platformTime = epochMillis;
    }

    /** The platform's time for this agent: its stack's platform clock if one was set, else the runtime's. */
    long platformMillis() {
        LongSupplier t = platformTime;
        return t != null ? t.getAsLong() : runtime.clock().epochMillis();
    }

    /** What the container layer discovers with: the ports held around this node's, and the shared listener. */
    private final Neighbourhood neighbourhood = new Neighbourhood() {
        @Override
        public List<Address> neighbours() {
            return neighbours;
        }

        @Override
        public Endpoint openListener(int port) {
            if (transport != Transport.UDP) {
                return null;
            }
            String host = endpoint.localAddress().host();
            boolean broadcast = !runtime.network().broadcastAddresses(host).isEmpty();
            return runtime.network().bindListener(host, port, broadcast, AgentNode.this::onDatagram);
        }

        @Override
        public List<String> broadcastAddresses() {
            return transport == Transport.UDP ? runtime.network().broadcastAddresses(endpoint.localAddress().host())
                    : List.of();
        }

        @Override
        public Boolean held(Address address) {
            Address own = endpoint.localAddress();
            if (address == null || !own.host().equals(address.host())) {
                return null;
            }
            if (address.equals(own)) {
                return Boolean.TRUE;
            }
            try {
                return runtime.network().isHeld(transport, address.host(), address.port());
            } catch (RuntimeException e) {
                return null; // not a port this node can bind to check
            }
        }
    };

    /**
     * The runtime's agents, as far as this node reaches them in memory (over a network that may
     * lose frames, such as the test kit's, none is taken for co-located).
     */
    private final CoLocated coLocated = new CoLocated() {
        @Override
        public boolean here(Address address) {
            return endpoint.inMemoryTo(address) && runtime.coLocated().here(address);
        }

        @Override
        public Runnable whenGone(Address address, Runnable callback) {
            // Not for an agent that has gone itself meanwhile (a whole runtime crashing at once).
            return runtime.coLocated().whenGone(address, () -> {
                if (endpoint.isOpen()) {
                    callback.run();
                }
            });
        }

        @Override
        public <T> T layer(Address address, Class<T> type) {
            return endpoint.inMemoryTo(address) ? runtime.coLocated().layer(address, type) : null;
        }
    };

    @Override
    public <T> T capability(Class<T> type) {
        if (type == Neighbourhood.class) {
            return type.cast(neighbourhood);
        }
        if (type == CoLocated.class) {
            return type.cast(coLocated);
        }
        if (type == Channels.class) {
            return runtime.network().capability(type);
        }
        return type == LoopLimits.class ? type.cast(runtime.loopLimits()) : null;
    }

    @Override
    public void execute(Runnable task) {
        runtime.execute(task);
    }

    @Override
    public RandomGenerator random() {
        return runtime.random();
    }

    @Override
    public void secretBytes(byte[] out) {
        runtime.secretBytes(out);
    }

    @Override
    public String platformName() {
        return runtime.platformName();
    }

    @Override
    public Clock clock() {
        return runtime.clock();
    }

    @Override
    public long nowNs() {
        return runtime.nowNs();
    }

    /** A timer of this agent's layers; it never runs once the agent is gone (stopped or crashed: its port is closed). */
    @Override
    public long schedule(long deadlineNs, Runnable task) {
        return runtime.schedule(deadlineNs, () -> {
            if (endpoint.isOpen()) {
                task.run();
            }
        });
    }

    @Override
    public boolean cancel(long timerId) {
        return runtime.cancel(timerId);
    }

    @Override
    public Tracer tracer() {
        return runtime.tracer();
    }

    @Override
    public DropCounters drops() {
        return drops;
    }
}
