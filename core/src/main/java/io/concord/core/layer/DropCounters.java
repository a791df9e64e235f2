package io.concord.core.layer;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;

/**
 * Counts dropped messages by reason ({@code "malformed"}, {@code "too-large"}, ...). Every drop is
 * counted here and traced; nothing is dropped silently. The first drop of each reason is also
 * logged as a warning with its detail, so an operator sees it without enabling traces; later ones
 * are only counted, so that a flood of bad input cannot flood the log. Readable from any thread.
 */
public final class DropCounters {
    private static final Logger LOG = LoggerFactory.getLogger(DropCounters.class);
    /**
     * The drops by the layer that made them ({@link #NODE} when no layer is named): layer to
     * reason to count. The counts by reason are sums over it, so a drop updates one counter.
     */
    private final Map<String, Map<String, LongAdder>> byLayer = new ConcurrentHashMap<>();

    /** The layer name under which drops counted without one are kept. */
    public static final String NODE = "node";

    /** Counts one drop. */
    public void increment(String reason) {
        counter(NODE, reason).increment();
    }

    /** The counter of a layer's reason, or {@code null} before its first drop. */
    private LongAdder existing(String layer, String reason) {
        Map<String, LongAdder> m = byLayer.get(layer);
        return m == null ? null : m.get(reason);
    }

    private LongAdder counter(String layer, String reason) {
        LongAdder a = existing(layer, reason);
        return a != null ? a : byLayer.computeIfAbsent(layer, l -> new ConcurrentHashMap<>()).computeIfAbsent(reason, r -> new LongAdder());
    }

    /**
     * Reasons that are part of normal operation, never warned about: a copy sent on purpose against
     * loss, a second answer to a handshake retried while the first answer was on its way, a message
     * to an agent nobody knows (its sender is told by the AMS's FAILURE, as in JADE, which prints
     * nothing either).
     */
    private static final java.util.Set<String> EXPECTED = java.util.Set.of("copy", "handshake-late", "unknown-receiver");
    /**
     * Reasons warned about once per process, not once per agent: frames of another platform
     * sharing the port range reach every agent of this one alike ({@code foreign-key} under
     * another key, {@code foreign-platform} under the same key and another name).
     */
    private static final java.util.Set<String> ONCE_PER_PROCESS = java.util.Set.of("foreign-key", "foreign-platform");
    private static final java.util.Set<String> WARNED_IN_PROCESS = ConcurrentHashMap.newKeySet();

    /** Counts one drop, and logs it if it is the first of its reason for this node. */
    public void record(String node, String reason, String detail) {
        record(node, null, reason, detail);
    }

    /**
     * Counts one drop by a layer; the detail is joined to the layer's name only if it is logged,
     * so that a counted drop (a copy, many times a second) allocates nothing.
     */
    public void record(String node, String layer, String reason, String detail) {
        String l = layer == null ? NODE : layer;
        LongAdder a = existing(l, reason);
        if (a == null) {
            boolean first = get(reason) == 0;
            a = counter(l, reason);
            if (first) {
                if (layer != null) {
                    detail = layer + ": " + detail;
                }
                if (EXPECTED.contains(reason) || ONCE_PER_PROCESS.contains(reason) && !WARNED_IN_PROCESS.add(reason)) {
                    LOG.debug("{} dropped a message ({}): {}", node, reason, detail);
                } else if (ONCE_PER_PROCESS.contains(reason)) {
                    LOG.warn("{} dropped a message ({}): {}. Logged once for this process: every agent counts them, "
                        + "see AgentRuntime.drops()", node, reason, detail);
                } else {
                    LOG.warn("{} dropped a message ({}): {}. Further drops for this reason are only counted; "
                        + "see AgentRuntime.drops()", node, reason, detail);
                }
            }
        }
        a.increment();
    }

    /** Drops counted for a reason, by any layer. */
    public long get(String reason) {
        long t = 0;
        for (Map<String, LongAdder> m : byLayer.values()) {
            LongAdder a = m.get(reason);
            if (a != null) {
                t += a.sum();
            }
        }
        return t;
    }

    /** All drops. */
    public long total() {
        long t = 0;
        for (Map<String, LongAdder> m : byLayer.values()) {
            for (LongAdder a : m.values()) {
                t += a.sum();
            }
        }
        return t;
    }

    /** A sorted copy: reason to count. */
    public Map<String, Long> snapshot() {
        Map<String, Long> m = new TreeMap<>();
        byLayer.values().forEach(reasons -> reasons.forEach((k, v) -> m.merge(k, v.sum(), Long::sum)));
        return m;
    }

    /** A sorted copy by layer: layer to reason to count (layer {@link #NODE} for drops no layer made). */
    public Map<String, Map<String, Long>> snapshotByLayer() {
        Map<String, Map<String, Long>> m = new TreeMap<>();
        byLayer.forEach((layer, reasons) -> {
            Map<String, Long> r = new TreeMap<>();
            reasons.forEach((k, v) -> r.put(k, v.sum()));
            m.put(layer, r);
        });
        return m;
    }

    @Override
    public String toString() {
        return snapshot().toString();
    }
}
