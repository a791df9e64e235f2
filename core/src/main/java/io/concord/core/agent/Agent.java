package io.concord.core.agent;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.random.RandomGenerator;

/**
 * An agent, with JADE's programming model: override {@link #setup()} to add behaviours, and
 * {@link #takeDown()} to clean up; send with {@link #send}, take messages from the mailbox with
 * {@link #receive}. Started by {@link AgentRuntime#startAgent}, which gives it a name, its own
 * communication stack and reception port.
 *
 * <p>An agent's behaviours run on its runtime's loop, one step at a time; the methods of this
 * class are meant to be called from them. {@link #send}, {@link #addBehaviour} and
 * {@link #doDelete} may also be called from other threads, which hand the work to the loop.
 */
public abstract class Agent {
    private static final Logger LOG = LoggerFactory.getLogger(Agent.class);

    /** The agent's life cycle. */
    public enum State { INITIATED, ACTIVE, DELETED }

    private AgentRuntime runtime;
    private AgentNode node;
    private AID aid;
    private Object[] arguments = new Object[0];
    private final ArrayList<Behaviour> behaviours = new ArrayList<>();
    private final ArrayDeque<AclMessage> mailbox = new ArrayDeque<>();
    private final Object mailboxLock = new Object();
    private final List<ThreadedBehaviourFactory.Runner> runners = new CopyOnWriteArrayList<>();
    private int blockingWaiters;
    private volatile boolean deleteRequested;
    private boolean inRound;
    private boolean compactPending;
    private State state = State.INITIATED;
    private long idCounter;

    /** Adds behaviours and whatever else the agent needs when it starts. */
    protected void setup() {
    }

    /** Cleans up when the agent is deleted. */
    protected void takeDown() {
    }

    /** This agent's identifier, with its transport address. */
    public final AID getAID() {
        return aid;
    }

    /** The full name, {@code local@platform}. */
    public final String getName() {
        return aid.name();
    }

    /** The name without the platform. */
    public final String getLocalName() {
        return aid.localName();
    }

    /** The arguments given at start. */
    public final Object[] getArguments() {
        return arguments.clone();
    }

    public final State getState() {
        return state;
    }

    /** The runtime this agent lives in. */
    public final AgentRuntime runtime() {
        return runtime;
    }

    /** The seeded random source shared by the runtime (deterministic in a simulation). */
    public final RandomGenerator random() {
        return runtime.random();
    }

    /**
     * The platform's wall-clock time in epoch milliseconds: the time of the platform's time source
     * when the agent's stack keeps one (the temporal layer's NTP-like estimate), else its runtime's.
     */
    public final long currentTimeMillis() {
        return node != null ? node.platformMillis() : runtime.clock().epochMillis();
    }

    /** A conversation id unique to this agent ({@code name-c<n>}), deterministic in a simulation. */
    public final String newConversationId() {
        return aid.localName() + "-c" + (++idCounter);
    }

    /** A reply-with value unique to this agent. */
    public final String newReplyWith() {
        return aid.localName() + "-r" + (++idCounter);
    }

    /** Schedules a behaviour. Thread-safe. */
    public final void addBehaviour(Behaviour b) {
        Objects.requireNonNull(b, "behaviour");
        if (runtime != null && !runtime.inLoop()) {
            runtime.execute(() -> addBehaviour(b));
            return;
        }
        b.attach(this);
        b.parent = null;
        behaviours.add(b);
        if (runtime != null) {
            runtime.makeReady(node);
        }
    }

    /** Removes a behaviour; it is not run again and its {@code onEnd} is not called. */
    public final void removeBehaviour(Behaviour b) {
        int i = behaviours.indexOf(b);
        if (i < 0) {
            return;
        }
        b.detach();
        if (inRound) {
            // The round walks the list by index: leave a hole and close it when the round ends.
            behaviours.set(i, null);
            compactPending = true;
        } else {
            behaviours.remove(i);
        }
    }

    /**
     * Sends a message to its receivers. The sender is set to this agent if it is not set.
     * Thread-safe: from another thread the message is copied and handed to the loop.
     */
    public final void send(AclMessage msg) {
        if (runtime.inLoop()) {
            node.send(msg);
        } else {
            AclMessage copy = msg.copy();
            runtime.execute(() -> node.send(copy));
        }
    }

    /** The first message in the mailbox, or {@code null}. Never blocks. */
    public final AclMessage receive() {
        AclMessage m;
        synchronized (mailboxLock) {
            m = mailbox.poll();
        }
        if (m != null && inboxFull) {
            taken();
        }
        return m;
    }

    /**
     * More than half the mailbox's capacity waits: senders are asked to hold back (their window
     * shut) until it is down to a quarter.
     */
    private volatile boolean inboxFull;

    final boolean inboxFull() {
        return inboxFull;
    }

    /** Messages waiting in the mailbox now. */
    final int mailboxSize() {
        synchronized (mailboxLock) {
            return mailbox.size();
        }
    }

    /** A message was taken from a full mailbox: at a quarter of its capacity, the senders are let go on. */
    private void taken() {
        int size;
        synchronized (mailboxLock) {
            size = mailbox.size();
        }
        if (inboxFull && size <= runtime.mailboxCapacity() / 4) {
            inboxFull = false;
            AgentNode n = node;
            runtime.execute(n::inboxDrained);
        }
    }

    /** The first message in the mailbox that the template matches, or {@code null}. Never blocks. */
    public final AclMessage receive(MessageTemplate template) {
        AclMessage found = null;
        synchronized (mailboxLock) {
            for (Iterator<AclMessage> it = mailbox.iterator(); it.hasNext(); ) {
                AclMessage m = it.next();
                if (template.match(m)) {
                    it.remove();
                    found = m;
                    break;
                }
            }
        }
        if (found != null && inboxFull) {
            taken();
        }
        return found;
    }

    /** Messages waiting in the mailbox. */
    public final int getCurQueueSize() {
        synchronized (mailboxLock) {
            return mailbox.size();
        }
    }

    /**
     * Waits for a message the template matches, for at most {@code timeoutMs} (0: no limit).
     * Only in a behaviour that has a thread of its own ({@link ThreadedBehaviourFactory}): on the
     * shared loop it would stop every agent, so there it throws.
     *
     * @return the message, or {@code null} on timeout
     * @throws IllegalStateException on the loop thread
     */
    public final AclMessage blockingReceive(MessageTemplate template, long timeoutMs) {
        if (runtime.inLoop()) {
            throw new IllegalStateException("blockingReceive would block every agent of this runtime; "
                    + "call it only from a behaviour wrapped with ThreadedBehaviourFactory.wrap(), "
                    + "or use receive() and block() in a normal behaviour");
        }
        MessageTemplate tpl = template == null ? MessageTemplate.matchAll() : template;
        long deadline = timeoutMs <= 0 ? Long.MAX_VALUE : runtime.clock().nanoTime() + timeoutMs * 1_000_000L;
        synchronized (mailboxLock) {
            blockingWaiters++;
            try {
                while (true) {
                    AclMessage m = receive(tpl);
                    if (m != null) {
                        return m;
                    }
                    long left = deadline - runtime.clock().nanoTime();
                    if (left <= 0) {
                        return null;
                    }
                    mailboxLock.wait(deadline == Long.MAX_VALUE ? 0 : Math.max(1, left / 1_000_000L));
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return null;
            } finally {
                blockingWaiters--;
            }
        }
    }

    /** {@link #blockingReceive(MessageTemplate, long)} without a template or limit. */
    public final AclMessage blockingReceive() {
        return blockingReceive(null, 0);
    }

    /** Deletes the agent after its current step: {@link #takeDown()} runs, its port is released. */
    public final void doDelete() {
        deleteRequested = true;
        if (runtime != null) {
            if (runtime.inLoop()) {
                runtime.makeReady(node);
            } else {
                runtime.execute(() -> runtime.makeReady(node));
            }
        }
    }

    // ---- runtime side -------------------------------------------------------------------------

    void bind(AgentRuntime runtime, AgentNode node, AID aid, Object[] args) {
        this.runtime = runtime;
        this.node = node;
        this.aid = aid;
        this.arguments = args == null ? new Object[0] : args.clone();
    }

    void activate() {
        state = State.ACTIVE;
        setup();
    }

    boolean deleteRequested() {
        return deleteRequested;
    }

    /** Ends the agent: stops threads, runs takeDown, drops its behaviours. */
    void terminate(boolean runTakeDown) {
        if (state == State.DELETED) {
            return;
        }
        for (ThreadedBehaviourFactory.Runner r : runners) {
            r.stop();
        }
        if (runTakeDown) {
            try {
                takeDown();
            } catch (RuntimeException e) {
                LOG.error("takeDown of {} failed", aid.name(), e);
            }
        }
        for (Behaviour b : behaviours) {
            if (b != null) {
                b.detach();
            }
        }
        behaviours.clear();
        state = State.DELETED;
    }

    /**
     * Runs each runnable behaviour once.
     *
     * @return true if some behaviour is still runnable
     */
    boolean runRound() {
        int size = behaviours.size();
        boolean removed = false;
        inRound = true;
        for (int i = 0; i < size && !deleteRequested; i++) {
            Behaviour b = behaviours.get(i);
            if (b == null || !b.isRunnable()) {
                continue;
            }
            try {
                b.step();
                if (b.done()) {
                    behaviours.set(i, null);
                    removed = true;
                    b.onEnd();
                    b.detach();
                }
            } catch (RuntimeException e) {
                LOG.error("behaviour {} of {} threw; it is removed, the agent goes on",
                        b.getClass().getName(), aid.name(), e);
                behaviours.set(i, null);
                removed = true;
                b.detach();
            }
        }
        inRound = false;
        if (removed || compactPending) {
            behaviours.removeIf(Objects::isNull);
            compactPending = false;
        }
        return hasRunnable();
    }

    boolean hasRunnable() {
        for (Behaviour b : behaviours) {
            if (b != null && b.isRunnable()) {
                return true;
            }
        }
        return false;
    }

    /** Behaviours scheduled now (for tests and tools). */
    /** Slots in the behaviour list, holes included (for tests: removals must not leave holes). */
    int behaviourSlots() {
        return behaviours.size();
    }

    int behaviourCount() {
        int n = 0;
        for (Behaviour b : behaviours) {
            if (b != null) {
                n++;
            }
        }
        return n;
    }

    /**
     * A message arrived (on the loop).
     *
     * @return false if the mailbox was full and the message was not kept
     */
    boolean postMessage(AclMessage msg, int capacity) {
        synchronized (mailboxLock) {
            if (mailbox.size() >= capacity) {
                return false;
            }
            mailbox.add(msg);
            if (mailbox.size() > capacity / 2) {
                inboxFull = true;
            }
            if (blockingWaiters > 0) {
                mailboxLock.notifyAll();
            }
        }
        for (int i = 0, n = behaviours.size(); i < n; i++) {
            Behaviour b = behaviours.get(i);
            if (b != null) {
                b.restartOnMessage();
            }
        }
        for (ThreadedBehaviourFactory.Runner r : runners) {
            r.signal();
        }
        return true;
    }

    void behaviourRestarted() {
        if (runtime != null) {
            if (runtime.inLoop()) {
                runtime.makeReady(node);
            } else {
                runtime.execute(() -> runtime.makeReady(node));
            }
        }
    }

    void threadedStarted(ThreadedBehaviourFactory.Runner r) {
        runners.add(r);
    }

    void threadedEnded(ThreadedBehaviourFactory.Runner r) {
        runners.remove(r);
    }

    @Override
    public String toString() {
        return aid == null ? getClass().getSimpleName() : aid.name();
    }
}
