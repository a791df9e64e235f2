package io.concord.bench.child;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Agents in JVM processes of their own, for the one-process-per-agent topology. Each child prints
 * {@code READY <address>} once its agent is set up, takes commands on its standard input, and
 * exits when that input closes.
 */
public final class Children implements AutoCloseable {
    private final List<Process> processes = new ArrayList<>();
    private final List<BufferedReader> outputs = new ArrayList<>();

    /** Starts a child JVM running {@code mainClass} with the arguments. */
    public void start(Class<?> mainClass, String... args) throws IOException {
        startOn(null, mainClass, args);
    }

    /** ... on the CPUs named (as {@code taskset -c} takes them), or on any if {@code null}. */
    public void startOn(String cpus, Class<?> mainClass, String... args) throws IOException {
        startWith(cpus == null ? List.of() : List.of("taskset", "-c", cpus), mainClass, args);
    }

    /** ... behind a command prefix ({@code ip netns exec <ns>}: on a host of {@code NetnsHosts}). */
    public void startWith(List<String> prefix, Class<?> mainClass, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(prefix);
        cmd.addAll(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx256m", "-XX:+UseSerialGC", "-Dorg.slf4j.simpleLogger.defaultLogLevel=error",
                "-cp", System.getProperty("java.class.path")));
        for (String prop : new String[]{"concord.idle.spin", "concord.idle.yield"}) {
            if (System.getProperty(prop) != null) {
                cmd.add("-D" + prop + "=" + System.getProperty(prop));
            }
        }
        cmd.add(mainClass.getName());
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        processes.add(p);
        outputs.add(new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8)));
    }

    /** Waits for every child's READY line and returns what follows READY, in start order. */
    public List<String> awaitReady() throws IOException {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < outputs.size(); i++) {
            String line;
            while ((line = outputs.get(i).readLine()) != null && !line.startsWith("READY")) {
                // JADE's banner and other chatter
            }
            if (line == null) {
                throw new IllegalStateException("child " + i + " ended before it was ready");
            }
            out.add(line.length() > 6 ? line.substring(6).trim() : "");
        }
        return out;
    }

    /** Reads child i's output up to the first line starting with {@code prefix}, and returns it. */
    public String readLine(int i, String prefix) throws IOException {
        String line;
        while ((line = outputs.get(i).readLine()) != null) {
            if (line.startsWith(prefix)) {
                return line;
            }
        }
        throw new IOException("child " + i + " ended before it printed " + prefix);
    }

    /** Sends child i a signal ({@code STOP} pauses it, {@code CONT} lets it go on), as {@code kill -SIG} does. */
    public void signal(int i, String sig) throws IOException {
        try {
            new ProcessBuilder("kill", "-" + sig, Long.toString(processes.get(i).pid())).inheritIO().start().waitFor();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Kills child i with SIGKILL, as a crash: nothing of it runs after. */
    public void kill(int i) {
        processes.get(i).destroyForcibly();
    }

    /** The CPU time child i has used so far (user and system, all its threads), in ns; -1 if unknown. */
    public long cpuNanos(int i) {
        return processes.get(i).info().totalCpuDuration().map(java.time.Duration::toNanos).orElse(-1L);
    }

    /** Sends a command line to child i and returns the first line it prints that starts with {@code answer}. */
    public String ask(int i, String line, String answer) throws IOException {
        tell(i, line);
        String got;
        while ((got = outputs.get(i).readLine()) != null) {
            if (got.startsWith(answer)) {
                return got;
            }
        }
        throw new IOException("child " + i + " ended before it answered " + line);
    }

    /** Sends a command line to child i. */
    public void tell(int i, String line) throws IOException {
        OutputStream in = processes.get(i).getOutputStream();
        in.write((line + "\n").getBytes(StandardCharsets.UTF_8));
        in.flush();
    }

    /** Closes child i's input (its signal to stop) and returns the number on its {@code SENT} line, or -1. */
    public long finish(int i) throws IOException {
        processes.get(i).getOutputStream().close();
        String line;
        StringBuilder said = new StringBuilder();
        while ((line = outputs.get(i).readLine()) != null) {
            if (line.startsWith("SENT ")) {
                return Long.parseLong(line.substring(5).trim());
            }
            said.append(line).append('\n');
        }
        int exit;
        try {
            exit = processes.get(i).waitFor();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            exit = -1;
        }
        throw new IOException("child " + i + " ended (exit " + exit + ") without saying what it sent; it printed: " + said);
    }

    @Override
    public void close() {
        for (Process p : processes) {
            try {
                p.getOutputStream().close();
            } catch (IOException ignored) {
                // already gone
            }
        }
        for (Process p : processes) {
            try {
                if (!p.waitFor(10, TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                p.destroyForcibly();
            }
        }
    }
}
