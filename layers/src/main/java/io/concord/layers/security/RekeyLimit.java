package io.concord.layers.security;

import io.concord.core.layer.LayerContext;
import io.concord.core.time.internal.TokenBucket;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * How often the {@link Handshake} may send a rekey notice: at most once a second per source id,
 * and at most {@link #NOTICES_PER_SECOND} in all, so that forged frames with a new source id each
 * cost no more than that. Loop thread only.
 */
final class RekeyLimit {
    static final long EVERY_MS = 1_000;
    private static final int MEMORY = 1024;
    /** REKEY notices sent at most a second, to all sources together. */
    static final int NOTICES_PER_SECOND = 64;

    /** When a REKEY notice last went to each source id (bounded: forgetting one costs a notice). */
    private final Map<Long, Long> rekeyed = new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Long, Long> eldest) {
            return size() > MEMORY;
        }
    };
    private final TokenBucket rekeys = new TokenBucket(NOTICES_PER_SECOND, NOTICES_PER_SECOND);

    /** True if a notice may go to {@code src} now; then it is counted as sent. */
    boolean allow(LayerContext ctx, long src) {
        long now = ctx.host().clock().epochMillis();
        Long last = rekeyed.get(src);
        if (last == null || now - last >= EVERY_MS) {
            // ... and at most NOTICES_PER_SECOND in all: forged frames with a new source id
            // each would otherwise cost a sealed notice and a send apiece.
            if (!rekeys.take(ctx.nowNs())) {
                return false;
            }
            rekeyed.put(src, now);
            return true;
        }
        return false;
    }
}
