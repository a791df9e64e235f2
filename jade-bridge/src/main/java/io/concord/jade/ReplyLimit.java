package io.concord.jade;

import io.concord.core.time.internal.TokenBucket;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.LongSupplier;

/**
 * How fast the bridge answers requests that name one host as their sender's address: a token
 * bucket per host, {@link #BURST} at once and {@link #RATE} a second after that. Requests can name
 * any address, so without it one small request listing many unknown receivers, or a flood of them,
 * would make the bridge post FAILUREs to a host of the requester's choosing. At most
 * {@link #HOSTS} hosts are tracked; the one untouched longest is forgotten first.
 */
final class ReplyLimit {
    static final int RATE = 50;
    static final int BURST = 200;
    static final int HOSTS = 1024;

    /** What the agents' own messages may post to one host: far above any conversation, a bound on any amplifier. */
    static final int AGENT_RATE = 5_000;
    static final int AGENT_BURST = 10_000;

    private final LongSupplier nanos;
    private final int burst;
    private final int rate;
    private final Map<String, TokenBucket> buckets = new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, TokenBucket> eldest) {
            return size() > HOSTS;
        }
    };

    ReplyLimit(LongSupplier nanos) {
        this(nanos, BURST, RATE);
    }

    ReplyLimit(LongSupplier nanos, int burst, int rate) {
        this.nanos = nanos;
        this.burst = burst;
        this.rate = rate;
    }

    /** The tokens a second this limit gives each host. */
    int rate() {
        return rate;
    }

    /** Takes a token for that host if one is left. */
    synchronized boolean allow(String host) {
        return buckets.computeIfAbsent(host.toLowerCase(java.util.Locale.ROOT), h -> new TokenBucket(burst, rate))
                .take(nanos.getAsLong());
    }
}
