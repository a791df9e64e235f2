package io.concord.bench.throughput;

import java.util.concurrent.atomic.AtomicLong;

/** What the agents of one JVM sent and received in a throughput run; the senders' stop switch. */
public final class Counters {
    public static final AtomicLong SENT = new AtomicLong();
    public static final AtomicLong RECEIVED = new AtomicLong();
    /** The senders' stop signal for this benchmark's JVM: set only by {@link #stopSenders}, cleared by {@link #reset}. */
    private static volatile boolean stop;

    private Counters() {
    }

    public static void reset() {
        SENT.set(0);
        RECEIVED.set(0);
        stop = false;
    }

    /** Tells every sender of this JVM to stop. */
    public static void stopSenders() {
        stop = true;
    }

    /** True once the senders were told to stop. */
    public static boolean stopped() {
        return stop;
    }

    /** A content of {@code bytes} ASCII characters. */
    public static String content(int bytes) {
        return "x".repeat(bytes);
    }
}
