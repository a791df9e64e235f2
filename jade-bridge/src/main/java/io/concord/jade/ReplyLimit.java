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

    private final LongSupplier nanos;
    private final Map<String, TokenBucket> buckets = new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, TokenBucket> eldest) {
            return size() > HOSTS;
        }
    };

    ReplyLimit(LongSupplier nanos) {
        this.nanos = nanos;
    }

    /** Takes a token for that host if one is left. */
    synchronized boolean allow(String host) {
        return buckets.computeIfAbsent(host.toLowerCase(java.util.Locale.ROOT), h -> new TokenBucket(BURST, RATE))
                .take(nanos.getAsLong());
    }
}
