package io.concord.core.layer;

import io.concord.core.time.Clock;

/** What the node that owns a stack gives its layers: time, timers, tracing, drop counting. */
public interface StackHost {

    /** The node's name (its agent's full name, {@code local@platform}), for traces and frame ids. */
    String nodeName();

    /** The node's own transport address. */
    default io.concord.core.net.Address localAddress() {
        return null;
    }

    /**
     * Lets a layer that keeps the platform's time (the temporal layer) give it to the agent: from
     * then on the agent's {@code currentTimeMillis()} reads it. Until then the agent reads its
     * runtime's clock.
     */
    default void setPlatformTime(java.util.function.LongSupplier epochMillis) {
    }

    /**
     * True when frames to this address are handed over in memory (an agent of the same runtime),
     * where nothing is lost: the communication layer then sends no repeated copies.
     */
    default boolean inMemoryTo(io.concord.core.net.Address to) {
        return false;
    }

    /** The node's transport. */
    default io.concord.core.net.Transport transport() {
        return io.concord.core.net.Transport.UDP;
    }

    /**
     * Something more the node offers its layers, by type (for example the port neighbourhood of
     * {@link io.concord.core.net.internal.Neighbourhood}, which the container layer discovers with), or
     * {@code null} if it offers none of that type.
     */
    default <T> T capability(Class<T> type) {
        return null;
    }

    /**
     * True while the node's agent has more messages waiting than it should be sent more (half its
     * mailbox's capacity): a layer that paces senders closes their window meanwhile. When it has
     * taken them down to a quarter, the stack gets the event {@link #INBOX_DRAINED} (going down).
     */
    default boolean inboxFull() {
        return false;
    }

    /**
     * Messages the node's agent has sent (one a receiver), whichever way they went (through the
     * stack, or handed over in memory to an agent of the same runtime); -1 if the node does not count.
     */
    default long messagesSent() {
        return -1;
    }

    /** Messages put into the node's agent's mailbox, whichever way they came; -1 if the node does not count. */
    default long messagesReceived() {
        return -1;
    }

    /** Messages waiting in the node's agent's mailbox, or -1 if the node has no mailbox. */
    default int mailboxSize() {
        return -1;
    }

    /**
     * Deletes the node's agent after its current step, as {@code doDelete()} does: its
     * {@code takeDown()} runs and it leaves the platform (the observation service's {@code kill}).
     * Nothing by default.
     */
    default void deleteAgent() {
    }

    /** The event type fired down the stack when a full mailbox has been taken down again. */
    String INBOX_DRAINED = "inbox-drained";

    /**
     * A layer holds frames the agent sent because a receiver is not taking them as fast
     * ({@code true}), or holds none any more ({@code false}): the node pauses the agent's
     * behaviours meanwhile, so that a fast sender is slowed to its receiver's pace.
     */
    default void backpressure(boolean on) {
    }

    /** Runs a task on the node's loop; callable from any thread. */
    default void execute(Runnable task) {
        task.run();
    }

    /** The random source of the node's runtime: seeded, so that a simulation replays. */
    java.util.random.RandomGenerator random();

    /**
     * Fills {@code out} with bytes nobody can guess (a secret shared with a peer): a runtime's
     * SecureRandom, or its seeded random source in a simulation, which must replay.
     */
    default void secretBytes(byte[] out) {
        new java.security.SecureRandom().nextBytes(out);
    }

    /** The platform name (the part after {@code @} in agent names). */
    default String platformName() {
        String n = nodeName();
        int at = n.indexOf('@');
        return at < 0 ? "" : n.substring(at + 1);
    }

    Clock clock();

    /** The loop's current time (read once per work cycle). */
    long nowNs();

    /** Runs a task on the loop at or after the deadline; returns an id to cancel it. */
    long schedule(long deadlineNs, Runnable task);

    /** Cancels a scheduled task; false if it already ran or was cancelled. */
    boolean cancel(long timerId);

    Tracer tracer();

    DropCounters drops();
}
