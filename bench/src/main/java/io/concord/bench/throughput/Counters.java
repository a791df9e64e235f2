package io.concord.bench.throughput;

import java.util.concurrent.atomic.AtomicLong;

/** What the agents of one JVM sent and received in a throughput run; the senders' stop switch. */
public final class Counters {
    public static final AtomicLong SENT = new AtomicLong();
    public static final AtomicLong RECEIVED = new AtomicLong();
    public static volatile boolean stop;

    private Counters() {
    }

    public static void reset() {
        SENT.set(0);
        RECEIVED.set(0);
        stop = false;
    }

    /** A content of {@code bytes} ASCII characters. */
    public static String content(int bytes) {
        return "x".repeat(bytes);
    }
}
