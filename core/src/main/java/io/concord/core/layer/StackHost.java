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
     * The ports of this host that were held by others when this node bound its own in its port
     * range, and those found held in the probe window past it: the potential agents of the
     * port-binding discovery. Empty when the node was bound to a fixed port.
     */
    default java.util.List<io.concord.core.net.Address> neighbours() {
        return java.util.List.of();
    }

    /** Installs the name-based addressing of the platform's agent lists; {@code null} removes it. */
    default void setRouter(Router router) {
    }

    /**
     * Hands an ACL message to the node's agent, as if it had come up the stack; for layers that
     * answer for the platform (the AMS, a FAILURE).
     */
    default void deliverToAgent(io.concord.core.acl.AclMessage message) {
    }

    /** Sends an ACL message from this node, through the whole stack, as the agent would. */
    default void send(io.concord.core.acl.AclMessage message) {
    }

    /**
     * Opens the node's listener on a shared UDP port (the containers' network discovery port):
     * what arrives there goes up this node's stack. Receives broadcasts unless the node is bound
     * to loopback.
     *
     * @return the listener, to close when done; {@code null} if the port cannot be shared
     */
    default io.concord.core.net.Endpoint openListener(int port) {
        return null;
    }

    /** The broadcast addresses this node reaches (none on loopback). */
    default java.util.List<String> broadcastAddresses() {
        return java.util.List.of();
    }

    /** Runs a task on the node's loop; callable from any thread. */
    default void execute(Runnable task) {
        task.run();
    }

    /** The seeded random source of the node's runtime. */
    default java.util.random.RandomGenerator random() {
        return new java.util.SplittableRandom();
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
