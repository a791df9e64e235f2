package io.concord.sim.board;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/** The board emulator in a process of its own, asked for its status on standard input. */
final class EmulatorProcess implements AutoCloseable {
    private final Process process;
    private final Writer in;
    private final LinkedBlockingQueue<String> lines = new LinkedBlockingQueue<>();
    final List<String> log = java.util.Collections.synchronizedList(new ArrayList<>());

    /** True once a line the emulator printed contains {@code text} (read under the log's lock: its reader thread appends to it). */
    boolean said(String text) {
        synchronized (log) {
            return log.stream().anyMatch(l -> l.contains(text));
        }
    }

    EmulatorProcess(Path port, String... options) throws IOException {
        process = JavaProcess.start(BoardEmulator.class, concat(new String[] {"--port", port.toString()}, options));
        in = new OutputStreamWriter(process.getOutputStream(), StandardCharsets.UTF_8);
        Thread t = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                for (String l; (l = r.readLine()) != null; ) {
                    log.add(l);
                    lines.add(l);
                }
            } catch (IOException e) {
                // ended
            }
        }, "emulator-out");
        t.setDaemon(true);
        t.start();
    }

    private static String[] concat(String[] a, String[] b) {
        String[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    /** The emulator's status: motors, tripped, armed, x, y, moved, accepted, drops. */
    Map<String, String> status() throws Exception {
        lines.clear();
        in.write("status\n");
        in.flush();
        long end = System.nanoTime() + 10_000_000_000L;
        while (System.nanoTime() < end) {
            String l = lines.poll(100, TimeUnit.MILLISECONDS);
            if (l != null && l.startsWith("status ")) {
                Map<String, String> m = new java.util.LinkedHashMap<>();
                String body = l.substring(7);
                int drops = body.indexOf(" drops=");
                m.put("drops", body.substring(drops + 7));
                for (String kv : body.substring(0, drops).split(" ")) {
                    int eq = kv.indexOf('=');
                    m.put(kv.substring(0, eq), kv.substring(eq + 1));
                }
                return m;
            }
        }
        throw new AssertionError("the emulator did not answer status; it said: " + log);
    }

    /** Asks for the status until it satisfies the condition; fails after the limit. */
    void awaitStatus(java.util.function.Predicate<Map<String, String>> condition, long limitMs, String what) {
        Pty.await(() -> {
            try {
                return condition.test(status());
            } catch (Exception e) {
                throw new AssertionError(e);
            }
        }, limitMs, what);
    }

    void command(String c) throws IOException {
        in.write(c + "\n");
        in.flush();
    }

    @Override
    public void close() {
        process.destroyForcibly();
    }
}
