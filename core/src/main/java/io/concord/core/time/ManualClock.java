package io.concord.core.time;

import java.util.concurrent.TimeUnit;

/**
 * A clock that moves only when told: the virtual time of tests and simulations. Its monotonic and
 * wall times advance together; the wall time starts at a fixed, configurable epoch.
 */
public final class ManualClock implements Clock {
    /** 2026-01-01T00:00:00Z: a fixed origin so that traces do not depend on the day they ran. */
    public static final long DEFAULT_EPOCH_MS = 1_767_225_600_000L;

    private final long epochOriginMs;
    private long nowNs;

    /** A clock at zero nanoseconds and {@link #DEFAULT_EPOCH_MS}. */
    public ManualClock() {
        this(DEFAULT_EPOCH_MS);
    }

    /** A clock at zero nanoseconds whose wall time starts at the given epoch milliseconds. */
    public ManualClock(long epochOriginMs) {
        this.epochOriginMs = epochOriginMs;
    }

    @Override
    public long nanoTime() {
        return nowNs;
    }

    @Override
    public long epochMillis() {
        return epochOriginMs + TimeUnit.NANOSECONDS.toMillis(nowNs);
    }

    /** Moves time forward by the given nanoseconds (never backward). */
    public void advanceNs(long ns) {
        if (ns < 0) {
            throw new IllegalArgumentException("time only moves forward; got " + ns + " ns");
        }
        nowNs += ns;
    }

    /** Moves time forward by the given milliseconds. */
    public void advanceMs(long ms) {
        advanceNs(TimeUnit.MILLISECONDS.toNanos(ms));
    }

    /** Sets the monotonic time, which must not be earlier than now. */
    public void setNanoTime(long ns) {
        if (ns < nowNs) {
            throw new IllegalArgumentException("time only moves forward: " + ns + " < " + nowNs);
        }
        nowNs = ns;
    }
}
