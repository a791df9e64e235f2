package io.concord.layers.platform;

import io.concord.layers.security.PlatformKey;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Five agents in five JVM processes on loopback, class 7, real sockets: they form one platform
 * and message each other by name; the container's process is killed with SIGKILL; the others
 * elect a new container and messaging by name goes on.
 */
class PlatformProcessesTest {
    static final String PLATFORM = "procs" + ProcessHandle.current().pid();
    static final String RANGE = "7401-7460";

    @TempDir
    Path home;

    final Map<String, Child> children = new LinkedHashMap<>();

    /** A child JVM and what it printed. */
    static final class Child {
        final String name;
        final Process process;
        final PrintWriter in;
        final LinkedBlockingQueue<String> lines = new LinkedBlockingQueue<>();
        volatile String state = "";
        final java.util.Collection<String> all = new java.util.concurrent.ConcurrentLinkedQueue<>();

        Child(String name, Process process) {
            this.name = name;
            this.process = process;
            this.in = new PrintWriter(process.getOutputStream(), true, StandardCharsets.UTF_8);
            Thread t = new Thread(() -> {
                try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                    String l;
                    while ((l = r.readLine()) != null) {
                        if (l.startsWith("STATE ")) {
                            state = l;
                        }
                        lines.add(l);
                        all.add(l);
                    }
                } catch (java.io.IOException ignored) {
                    // the child died
                }
            }, "child-" + name);
            t.setDaemon(true);
            t.start();
        }

        String field(String key) {
            for (String f : state.split(" ")) {
                if (f.startsWith(key + "=")) {
                    return f.substring(key.length() + 1);
                }
            }
            return "";
        }

        String awaitLine(Predicate<String> p, long ms) throws InterruptedException {
            long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ms);
            String l;
            while ((l = lines.poll(Math.max(1, end - System.nanoTime()), TimeUnit.NANOSECONDS)) != null) {
                if (p.test(l)) {
                    return l;
                }
            }
            return null;
        }
    }

    @AfterEach
    void stopAll() throws Exception {
        for (Child c : children.values()) {
            c.in.close();
            if (!c.process.waitFor(10, TimeUnit.SECONDS)) {
                c.process.destroyForcibly();
            }
        }
    }

    private Child spawn(String name) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-Dconcord.home=" + home, "-Xss512k", "-XX:TieredStopAtLevel=1",
                "-cp", System.getProperty("java.class.path"), PlatformChild.class.getName(), PLATFORM, RANGE, name)
                .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        Child c = new Child(name, p);
        children.put(name, c);
        return c;
    }

    /** Waits until every live child reports the same container and the given number of agents. */
    private String awaitAgreement(List<Child> live, int agents, String notContainer) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < end) {
            String c = live.get(0).field("container");
            boolean agree = !c.isEmpty() && !c.equals("null") && !c.equals(notContainer);
            for (Child ch : live) {
                agree &= ch.field("container").equals(c) && ch.field("agents").equals(String.valueOf(agents))
                        && !ch.field("role").equals("SEEKING");
            }
            if (agree) {
                return c;
            }
            // Not a wait for time to pass: a poll of the children's reports, with a deadline.
            Thread.onSpinWait();
            Thread.sleep(20);
        }
        StringBuilder b = new StringBuilder();
        for (Child ch : live) {
            b.append(ch.name).append(": ").append(ch.state).append('\n');
        }
        throw new AssertionError("no agreement on a container with " + agents + " agents:\n" + b);
    }

    @Test
    void fiveProcessesFormOnePlatformAndSurviveTheContainersKill() throws Exception {
        PlatformKey.loadOrCreate(home.resolve("platform.key"));
        for (int i = 0; i < 5; i++) {
            spawn("p" + i);
        }
        List<Child> live = new ArrayList<>(children.values());
        String container = awaitAgreement(live, 5, null);
        long containers = live.stream().filter(c -> c.field("role").equals("CONTAINER")).count();
        assertEquals(1, containers, "exactly one container");

        // By name, across processes.
        Child p0 = children.get("p0");
        Child p4 = children.get("p4");
        p0.in.println("send p4 hello-four");
        assertTrue(p4.awaitLine(l -> l.equals("GOT REQUEST from p0 hello-four"), 20_000) != null,
                () -> "p0: " + p0.all + "\np4: " + p4.all);
        assertTrue(p0.awaitLine(l -> l.equals("GOT INFORM from p4 echo:hello-four"), 20_000) != null);

        // kill -9 the container's process.
        String victim = container.substring(0, container.indexOf('@'));
        Child dead = children.remove(victim);
        dead.process.destroyForcibly().waitFor();
        live.remove(dead);
        String next = awaitAgreement(live, 4, container);
        assertNotEquals(container, next);
        assertEquals(1, live.stream().filter(c -> c.field("role").equals("CONTAINER")).count());

        Child a = live.get(0);
        Child b = live.get(live.size() - 1);
        a.in.println("send " + b.name + " after-failover");
        assertTrue(b.awaitLine(l -> l.equals("GOT REQUEST from " + a.name + " after-failover"), 20_000) != null,
                () -> a.name + ": " + a.all + "\n" + b.name + ": " + b.all);
        assertTrue(a.awaitLine(l -> l.equals("GOT INFORM from " + b.name + " echo:after-failover"), 20_000) != null);
    }
}
