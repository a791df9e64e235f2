package io.concord.layers.temporal;

import io.concord.core.time.Clock;

/**
 * One agent's view of the platform's time: its host clock plus an offset to the time source (the
 * container's clock), estimated by {@link TemporalLayer}'s NTP-like exchange. Without a time
 * source, the offset stays 0 and the host clock is the platform clock (right on one host).
 */
public final class PlatformClock {
    private volatile Clock host;
    private volatile long offsetUs;
    private volatile long lastRoundTripUs = -1;
    private volatile boolean synced;

    /** A clock bound to a host clock now. */
    public PlatformClock(Clock host) {
        this.host = host;
    }

    /** A clock bound later, by the first layer that starts with it ({@link #bind}). */
    public PlatformClock() {
    }

    /** Binds the host clock if none is bound yet (the runtime's, which is virtual in a simulation). */
    public void bind(Clock hostClock) {
        if (host == null) {
            host = hostClock;
        }
    }

    /** Platform time in microseconds since the epoch. */
    public long nowUs() {
        Clock host = this.host;
        if (host == null) {
            throw new IllegalStateException("the platform clock is not bound to a host clock yet");
        }
        return host.epochMillis() * 1_000L + (host.nanoTime() / 1_000L) % 1_000L + offsetUs;
    }

    /** Platform time in milliseconds since the epoch. */
    public long nowMs() {
        return nowUs() / 1_000L;
    }

    /** The estimated offset from the host clock to the platform clock. */
    public long offsetUs() {
        return offsetUs;
    }

    /** The round trip of the last exchange that set the offset, or -1. */
    public long lastRoundTripUs() {
        return lastRoundTripUs;
    }

    /** True once an exchange with the time source succeeded. */
    public boolean isSynced() {
        return synced;
    }

    void update(long offsetUs, long roundTripUs) {
        this.offsetUs = offsetUs;
        this.lastRoundTripUs = roundTripUs;
        this.synced = true;
    }
}
