package io.concord.serial;

import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;

/** Frames dropped, counted by reason (corrupt, oversized, mac, malformed, repeated, out-of-order, stale, ...). Thread-safe. */
public final class Drops {
    private final Map<String, LongAdder> counts = new ConcurrentHashMap<>();

    /** Counts one drop. */
    public void count(String reason) {
        counts.computeIfAbsent(reason, k -> new LongAdder()).increment();
    }

    /** The count of one reason. */
    public long get(String reason) {
        LongAdder a = counts.get(reason);
        return a == null ? 0 : a.sum();
    }

    /** Every reason with its count, sorted by reason. */
    public Map<String, Long> snapshot() {
        Map<String, Long> out = new TreeMap<>();
        counts.forEach((k, v) -> out.put(k, v.sum()));
        return out;
    }

    /** All drops. */
    public long total() {
        return counts.values().stream().mapToLong(LongAdder::sum).sum();
    }

    @Override
    public String toString() {
        return snapshot().toString();
    }
}
