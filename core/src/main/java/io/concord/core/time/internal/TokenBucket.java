package io.concord.core.time.internal;

/**
 * A rate limit: {@code burst} takes at once, then {@code perSecond}, by a clock the caller passes
 * in (the loop's, or an injected one in tests). Not thread-safe; the owner's thread only.
 */
public final class TokenBucket {
    private final int burst;
    private final double perSecond;
    private double tokens;
    private long atNs;
    private boolean started;

    public TokenBucket(int burst, double perSecond) {
        if (burst < 1 || perSecond <= 0) {
            throw new IllegalArgumentException("a rate limit needs a burst of at least 1 and a positive rate, got "
                    + burst + " and " + perSecond);
        }
        this.burst = burst;
        this.perSecond = perSecond;
        this.tokens = burst;
    }

    /** Takes one if one is left at {@code nowNs}. */
    public boolean take(long nowNs) {
        if (started) {
            tokens = Math.min(burst, tokens + (nowNs - atNs) * perSecond / 1e9);
        }
        started = true;
        atNs = nowNs;
        if (tokens < 1) {
            return false;
        }
        tokens--;
        return true;
    }

    public int burst() {
        return burst;
    }

    public double perSecond() {
        return perSecond;
    }
}
