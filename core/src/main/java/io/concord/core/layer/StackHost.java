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

    /** The node's transport. */
    default io.concord.core.net.Transport transport() {
        return io.concord.core.net.Transport.UDP;
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
