package io.concord.core.time;

/**
 * The one source of time. Everything that needs time is given a clock; only this package reads
 * the system's (the benchmarks, and the demos' wall-clock printing, measure real time and read it
 * directly; each says so). Read it once per work cycle and pass the value down ({@code nowNs}).
 */
public interface Clock {

    /** Monotonic time in nanoseconds, for deadlines and durations; its origin means nothing. */
    long nanoTime();

    /** Wall-clock time in milliseconds since the epoch, for timestamps seen by others. */
    long epochMillis();

    /** The system's clock. */
    static Clock system() {
        return SystemClock.INSTANCE;
    }
}
