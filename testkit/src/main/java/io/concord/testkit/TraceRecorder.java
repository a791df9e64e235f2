package io.concord.testkit;

import io.concord.core.layer.Tracer;

import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * A tracer that folds every event into a 64-bit hash (FNV-1a) and keeps the last few lines: two
 * runs with the same seed must give the same hash. Single-threaded.
 */
public final class TraceRecorder implements Tracer {
    private final int keepLines;
    private final ArrayDeque<String> lines;
    private long hash = 0xcbf29ce484222325L;
    private long count;
    private final List<Tracer> listeners = new ArrayList<>();

    /** Keeps the last 200 lines. */
    public TraceRecorder() {
        this(200);
    }

    public TraceRecorder(int keepLines) {
        this.keepLines = keepLines;
        this.lines = new ArrayDeque<>(Math.max(1, keepLines));
    }

    /** Also hands every event to a listener (an invariant checker). */
    public void addListener(Tracer listener) {
        listeners.add(listener);
    }

    @Override
    public void trace(long nowNs, String node, String event, String detail) {
        for (int i = 0; i < listeners.size(); i++) {
            listeners.get(i).trace(nowNs, node, event, detail);
        }
        String line = nowNs + " " + node + " " + event + " " + detail;
        byte[] b = line.getBytes(StandardCharsets.UTF_8);
        long h = hash;
        for (byte x : b) {
            h ^= x & 0xff;
            h *= 0x100000001b3L;
        }
        h ^= '\n';
        h *= 0x100000001b3L;
        hash = h;
        count++;
        if (keepLines > 0) {
            if (lines.size() == keepLines) {
                lines.removeFirst();
            }
            lines.addLast(line);
        }
    }

    /** The hash of every event so far. */
    public long hash() {
        return hash;
    }

    /** Events so far. */
    public long count() {
        return count;
    }

    /** The last lines kept. */
    public List<String> lastLines() {
        return new ArrayList<>(lines);
    }
}
