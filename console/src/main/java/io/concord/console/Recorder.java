package io.concord.console;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A recording of what the console publishes (the platform's lists, the safety counters, the
 * sniffed messages, every view's snapshots: the hospital's poses), one JSON line an event:
 * {@code {"t":epochMs,"topic":"view-hospital","data":{...}}}. The page plays it back with a time
 * slider in the same views. The agents' loop only offers a line to a bounded queue; a thread of
 * its own writes the file, so a slow disk never holds the agents up: what does not fit is dropped
 * and counted ({@link #dropped()}). A recording stops by itself at {@link #MAX_BYTES}.
 */
final class Recorder implements AutoCloseable {
    static final long MAX_BYTES = 128L << 20;
    static final int QUEUE = 4_096;
    private static final String END = "";

    private final Path file;
    private final ArrayBlockingQueue<String> queue = new ArrayBlockingQueue<>(QUEUE);
    private final Thread writer;
    private final AtomicLong events = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();
    private final AtomicLong bytes = new AtomicLong();
    private volatile boolean closed;
    private volatile String failure;

    Recorder(Path file) throws IOException {
        this.file = file;
        Files.createDirectories(file.toAbsolutePath().getParent());
        BufferedWriter out = Files.newBufferedWriter(file, StandardCharsets.UTF_8, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        this.writer = new Thread(() -> drain(out), "concord-console-recorder");
        writer.setDaemon(true);
        writer.start();
    }

    Path file() {
        return file;
    }

    /** Offers an event; never blocks. */
    void record(long atMs, String topic, String json) {
        if (closed) {
            return;
        }
        String line = "{\"t\":" + atMs + ",\"topic\":\"" + topic + "\",\"data\":" + json + "}\n";
        if (bytes.get() + line.length() > MAX_BYTES) {
            closed = true;
            failure = "stopped at " + (MAX_BYTES >> 20) + " MiB";
            queue.offer(END);
            return;
        }
        if (queue.offer(line)) {
            events.incrementAndGet();
            bytes.addAndGet(line.length());
        } else {
            dropped.incrementAndGet();
        }
    }

    private void drain(BufferedWriter out) {
        try (out) {
            while (true) {
                String line = queue.poll(200, TimeUnit.MILLISECONDS);
                if (line == null) {
                    out.flush();
                    if (closed && queue.isEmpty()) {
                        return;
                    }
                    continue;
                }
                if (line == END) {
                    // what came before the end is written; later offers were refused
                    String rest;
                    while ((rest = queue.poll()) != null) {
                        if (rest != END) {
                            out.write(rest);
                        }
                    }
                    return;
                }
                out.write(line);
            }
        } catch (IOException e) {
            failure = "the file could not be written: " + e.getMessage();
            closed = true;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    long events() {
        return events.get();
    }

    long dropped() {
        return dropped.get();
    }

    long bytes() {
        return bytes.get();
    }

    /** Why it stopped by itself, or {@code null}. */
    String failure() {
        return failure;
    }

    boolean recording() {
        return !closed;
    }

    /** Stops, and waits until what was offered is on disk. */
    @Override
    public void close() {
        closed = true;
        while (!queue.offer(END)) {
            if (queue.poll() != null) {   // full: the end must get in; what it pushed out is counted
                events.decrementAndGet();
                dropped.incrementAndGet();
            }
        }
        try {
            writer.join(10_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
