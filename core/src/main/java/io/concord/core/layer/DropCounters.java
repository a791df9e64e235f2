package io.concord.core.layer;

import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;

/**
 * Counts dropped messages by reason ({@code "malformed"}, {@code "too-large"}, ...). Every drop is
 * counted here and traced; nothing is dropped silently. Readable from any thread.
 */
public final class DropCounters {
    private final Map<String, LongAdder> counts = new ConcurrentHashMap<>();

    /** Counts one drop. */
    public void increment(String reason) {
        counts.computeIfAbsent(reason, r -> new LongAdder()).increment();
    }

    /** Drops counted for a reason. */
    public long get(String reason) {
        LongAdder a = counts.get(reason);
        return a == null ? 0 : a.sum();
    }

    /** All drops. */
    public long total() {
        long t = 0;
        for (LongAdder a : counts.values()) {
            t += a.sum();
        }
        return t;
    }

    /** A sorted copy: reason to count. */
    public Map<String, Long> snapshot() {
        Map<String, Long> m = new TreeMap<>();
        counts.forEach((k, v) -> m.put(k, v.sum()));
        return m;
    }

    @Override
    public String toString() {
        return snapshot().toString();
    }
}
