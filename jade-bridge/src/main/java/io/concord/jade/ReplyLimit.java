package io.concord.jade;

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
    private final Map<String, double[]> buckets = new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, double[]> eldest) {
            return size() > HOSTS;
        }
    };

    ReplyLimit(LongSupplier nanos) {
        this.nanos = nanos;
    }

    /** Takes a token for that host if one is left. */
    synchronized boolean allow(String host) {
        long now = nanos.getAsLong();
        double[] b = buckets.computeIfAbsent(host.toLowerCase(java.util.Locale.ROOT), h -> new double[] {BURST, now});
        b[0] = Math.min(BURST, b[0] + (now - (long) b[1]) * RATE / 1e9);
        b[1] = now;
        if (b[0] < 1) {
            return false;
        }
        b[0]--;
        return true;
    }
}
