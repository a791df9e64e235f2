package io.concord.sim;

import io.concord.examples.BookBuyer;
import io.concord.examples.BookSeller;
import io.concord.layers.Boot;
import io.concord.layers.security.PlatformKey;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * The demo jar's entry: {@code hospital} (the default) runs {@link HospitalDemo}; {@code platform}
 * runs the platform demo: three JVMs on this machine, started with the {@link Boot} command line and
 * nothing configured but the agents. They find each other by port binding (7001 and up), elect
 * a container, and build the white and yellow pages; a buyer finds three book sellers in the DF,
 * asks each its price by name (QUERY-REF) and orders from the cheapest (REQUEST): the annex agents
 * of {@code io.concord.examples}, as the runnable jar runs them. Then the container's JVM is
 * killed ({@code kill -9}) and the other two elect a new one. Every JVM's output is shown,
 * prefixed with its letter.
 */
public final class Demo {
    private static final PrintStream OUT = System.out;

    private Demo() {
    }

    /** One JVM of the demo, and the lines it printed. */
    private static final class Jvm {
        final String letter;
        final Process process;
        final LinkedBlockingQueue<String> lines;

        Jvm(String letter, Process process, LinkedBlockingQueue<String> lines) {
            this.letter = letter;
            this.process = process;
            this.lines = lines;
        }
    }

    public static void main(String[] args) throws Exception {
        // The hospital is the default; "platform" runs the three-JVM platform demo.
        if (args.length == 0 || !args[0].equals("platform")) {
            String[] rest = args.length > 0 && args[0].equals("hospital") ? java.util.Arrays.copyOfRange(args, 1, args.length) : args;
            HospitalDemo.main(rest);
            return;
        }
        if (args.length > 1) {
            System.err.println("platform takes no options; got '" + String.join(" ", java.util.Arrays.copyOfRange(args, 1, args.length))
                    + "' (the hospital's options go without 'platform')");
            System.err.println(HospitalDemo.USAGE);
            System.exit(2);
            return;
        }
        String platform = "demo";
        OUT.println("Concord platform demo: three JVMs, no main container, nothing configured but the agents.");
        OUT.println("Each agent binds the first free UDP port from 7001 on 127.0.0.1, finds the others by the ports");
        OUT.println("they hold, and they elect a container among themselves. Every message goes through the EN 50159");
        OUT.println("class-7 stack (per-pair AES-GCM keys from signed handshakes); platform key: "
                + PlatformKey.defaultDirectory().resolve("platform.key"));
        OUT.println();
        LinkedBlockingQueue<String> events = new LinkedBlockingQueue<>();
        Map<String, Jvm> jvms = new LinkedHashMap<>();
        try {
            jvms.put("A", spawn("A", platform, "seller1:" + BookSeller.class.getName() + "(42);"
                    + "seller2:" + BookSeller.class.getName() + "(35)", events));
            jvms.put("B", spawn("B", platform, "seller3:" + BookSeller.class.getName() + "(39)", events));
            // With no seller named, the buyer asks the DF's, once it lists all three.
            jvms.put("C", spawn("C", platform, "buyer:" + BookBuyer.class.getName() + "(sellers=3)", events));

            String done = await(events, l -> l.contains("buyer: bought "), 60);
            if (done == null) {
                OUT.println("The buyer did not finish within 60 s.");
                return;
            }
            OUT.println();
            String container = null;
            for (String l : new ArrayList<>(history)) {
                if (l.contains("I am the container")) {
                    container = l;
                }
            }
            if (container == null) {
                OUT.println("No container was reported.");
                return;
            }
            String letter = container.substring(1, 2);
            String name = container.substring(4, container.indexOf(':'));
            OUT.println("Failover: kill -9 JVM " + letter + ", whose " + name + " is the container.");
            Jvm victim = jvms.remove(letter);
            victim.process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            int left = 4 - (letter.equals("A") ? 2 : 1); // JVM A runs two sellers, B and C one agent each
            String next = await(events, l -> l.contains("I am the container") && !l.startsWith("[" + letter + "]")
                    && l.contains(" " + left + " agents here"), 30);
            OUT.println(next == null ? "No new container listing the " + left + " agents left within 30 s."
                    : "A new container took over and lists the " + left + " agents left; the demo ends.");
        } finally {
            for (Jvm j : jvms.values()) {
                j.process.destroy(); // SIGTERM: its agents leave the platform cleanly
            }
            for (Jvm j : jvms.values()) {
                if (!j.process.waitFor(10, TimeUnit.SECONDS)) {
                    j.process.destroyForcibly();
                }
            }
        }
    }

    private static final List<String> history = java.util.Collections.synchronizedList(new ArrayList<>());

    private static Jvm spawn(String letter, String platform, String agents, LinkedBlockingQueue<String> events)
            throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"),
                Boot.class.getName(), "-name", platform, "-watch", "-agents", agents)
                .redirectErrorStream(true).start();
        LinkedBlockingQueue<String> lines = new LinkedBlockingQueue<>();
        Thread t = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                String l;
                while ((l = r.readLine()) != null) {
                    String shown = "[" + letter + "] " + l;
                    OUT.println(shown);
                    history.add(shown);
                    events.add(shown);
                }
            } catch (java.io.IOException ignored) {
                // the JVM ended
            }
        }, "demo-" + letter);
        t.setDaemon(true);
        t.start();
        return new Jvm(letter, p, lines);
    }

    private static String await(LinkedBlockingQueue<String> events, java.util.function.Predicate<String> p, int seconds)
            throws InterruptedException {
        // Wall time: the demo waits as a person would for its child JVMs to print.
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        String l;
        while ((l = events.poll(Math.max(1, end - System.nanoTime()), TimeUnit.NANOSECONDS)) != null) {
            if (p.test(l)) {
                return l;
            }
        }
        return null;
    }
}
