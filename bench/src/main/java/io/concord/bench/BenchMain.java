package io.concord.bench;

import io.concord.agents.map.HospitalMap;
import io.concord.bench.child.Children;
import io.concord.bench.child.IdlePlatform;
import io.concord.bench.child.LoadChild;
import io.concord.bench.harness.AttackHarness;
import io.concord.bench.harness.BlockingBeside;
import io.concord.bench.harness.ConsoleCost;
import io.concord.bench.harness.FleetHarness;
import io.concord.bench.harness.HeartbeatBench;
import io.concord.bench.harness.HospitalBench;
import io.concord.bench.harness.NetworkHarness;
import io.concord.bench.harness.PlatformHarness;
import io.concord.bench.harness.ScaleChild;
import io.concord.bench.harness.ScaleHarness;
import io.concord.bench.harness.SerialBench;
import io.concord.bench.harness.SimHarness;
import io.concord.bench.harness.StressHarness;
import io.concord.bench.harness.ThroughputHarness;
import io.concord.bench.jade.JadeIdle;
import io.concord.bench.jmh.BooksBenchmark;
import io.concord.bench.jmh.ChainBenchmark;
import io.concord.bench.jmh.ContentBenchmark;
import io.concord.bench.jmh.HttpBenchmark;
import io.concord.bench.jmh.ProcessBooksBenchmark;
import io.concord.bench.jmh.ProcessChainBenchmark;
import io.concord.bench.jmh.StackBenchmark;
import io.concord.bench.jmh.UdpBaselineBenchmark;
import io.concord.bench.report.Charts;
import io.concord.bench.report.Machine;
import io.concord.bench.support.Chain;
import io.concord.bench.support.Platforms;
import io.concord.core.net.Transport;
import io.concord.testkit.NetnsHosts;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.results.RunResult;
import org.openjdk.jmh.runner.Runner;
import org.openjdk.jmh.runner.RunnerException;
import org.openjdk.jmh.runner.options.ChainedOptionsBuilder;
import org.openjdk.jmh.runner.options.OptionsBuilder;
import org.openjdk.jmh.runner.options.TimeValue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.function.ToDoubleFunction;

/**
 * {@code bench/run quick|full [name ...]}: runs the named benchmarks (all but fleet by default), prints one
 * RESULT line per measured point, and writes a page per benchmark under {@code bench/report/} with
 * tables, PNG charts and the machine's description. Names: {@code stack}, {@code chain},
 * {@code books}, {@code udp}.
 */
public final class BenchMain {
    static final List<String> NAMES = List.of("udp", "stack", "content", "chain", "books", "stress", "bootstrap", "failover", "network", "http",
            "console", "sim", "hospital", "serial", "attack", "idle", "throughput", "scale", "load", "blocking", "fleet");
    private static final List<String> PLATFORMS = List.of(Platforms.CONCORD_CLASS7, Platforms.CONCORD_CLASS7_SOCKETS,
            Platforms.CONCORD_CLOSED, Platforms.JADE);

    private final boolean full;
    private final Path reportDir;
    private final Map<String, Double> udpHopUs = new TreeMap<>();

    private static String hogsTag() {
        return hogs > 0 ? " hogs=" + hogs : "";
    }

    /** Busy loops running beside the whole run ({@code -Dconcord.bench.hogs}). */
    private static int hogs;

    private BenchMain(boolean full, Path reportDir) {
        this.full = full;
        this.reportDir = reportDir;
    }

    public static void main(String[] args) throws RunnerException, IOException {
        int i = 0;
        boolean full = false;
        if (args.length > 0 && (args[0].equals("quick") || args[0].equals("full"))) {
            full = args[0].equals("full");
            i = 1;
        }
        List<String> names = new ArrayList<>();
        for (; i < args.length; i++) {
            if (!NAMES.contains(args[i])) {
                System.err.println("unknown benchmark '" + args[i] + "'; available: " + String.join(", ", NAMES)
                        );
                System.exit(2);
            }
            names.add(args[i]);
        }
        // Stress runs minutes when asked for by name in quick mode, seconds as part of everything
        // (which keeps within five minutes).
        boolean stressByName = names.contains("stress");
        if (names.isEmpty()) {
            names.addAll(NAMES);
            names.remove("fleet"); // ten minutes of its own: asked for by name
        }
        // -Dconcord.bench.hogs=N: N busy loops (processes at normal priority) beside every platform
        // measured, the same for each, for the whole run: a busy machine. Its report goes apart.
        int hogs = Integer.getInteger("concord.bench.hogs", 0);
        List<Process> loops = new ArrayList<>();
        for (int h = 0; h < hogs; h++) {
            loops.add(new ProcessBuilder("sh", "-c", "while :; do :; done").start());
        }
        Runtime.getRuntime().addShutdownHook(new Thread(() -> loops.forEach(Process::destroyForcibly)));
        BenchMain.hogs = hogs;
        Path reportDir = Path.of(System.getProperty("concord.report", hogs > 0 ? "bench/report/hogs-" + hogs : "bench/report"));
        Files.createDirectories(reportDir);
        BenchMain b = new BenchMain(full, reportDir);
        if (names.contains("bootstrap") || names.contains("failover")) {
            b.platform(names.contains("bootstrap"), names.contains("failover"));
        }
        for (String name : NAMES) {
            if (names.contains(name)) {
                switch (name) {
                    case "udp" -> b.udp();
                    case "stack" -> b.stack();
                    case "content" -> b.content();
                    case "chain" -> {
                        b.rounds("chain", ChainBenchmark.class, "n", "N", List.of(2, 6, 10, 19));
                        b.processes("chain", ProcessChainBenchmark.class, "n", "N", full ? List.of(2, 6, 10, 19) : List.of(2, 6));
                    }
                    case "books" -> {
                        b.rounds("books", BooksBenchmark.class, "s", "S", List.of(1, 5, 10, 15));
                        b.processes("books", ProcessBooksBenchmark.class, "s", "S", full ? List.of(1, 5, 10, 15) : List.of(1, 5));
                    }
                    case "stress" -> b.stress(stressByName);
                    case "bootstrap", "failover" -> { }
                    case "network" -> b.network();
                    case "http" -> b.http();
                    case "sim" -> b.sim();
                    case "hospital" -> b.hospital();
                    case "console" -> b.console();
                    case "serial" -> b.serial();
                    case "attack" -> b.attack();
                    case "idle" -> b.idle();
                    case "throughput" -> b.throughput();
                    case "scale" -> b.scale();
                    case "load" -> b.load();
                    case "blocking" -> b.blocking();
                    case "fleet" -> b.fleet();
                    default -> throw new IllegalStateException(name);
                }
            }
        }
        b.index();
        System.exit(0); // JADE leaves threads behind that would keep this JVM up
    }

    private ChainedOptionsBuilder options(Class<?> benchmark) {
        return new OptionsBuilder()
                .include("\\." + benchmark.getSimpleName() + "\\.")
                .mode(Mode.SampleTime)
                .timeUnit(TimeUnit.MICROSECONDS)
                .forks(1)
                .jvmArgsAppend("-Djava.awt.headless=true", "-Dorg.slf4j.simpleLogger.defaultLogLevel=error")
                // The JIT needs about three seconds of rounds before a round's time settles.
                .warmupIterations(full ? 5 : 3).warmupTime(TimeValue.seconds(full ? 3 : 1))
                .measurementIterations(full ? 10 : 1).measurementTime(TimeValue.seconds(full ? 3 : 1));
    }

    private static double median(RunResult r) {
        return r.getPrimaryResult().getStatistics().getPercentile(50);
    }

    private String header(String title, String what) {
        return header(title, what, "JMH sample time");
    }

    private String header(String title, String what, String method) {
        return "# " + title + "\n\n" + what + "\n\n" + method + ", " + (full ? "full" : "quick") + " mode, "
                + LocalDate.now() + ". " + Machine.describe()
                + (hogs > 0 ? " **" + hogs + " busy loops ran beside every platform measured** (`-Dconcord.bench.hogs=" + hogs + "`)." : "")
                + "\n\n";
    }

    private void udp() throws RunnerException, IOException {
        // Raw sockets: little code to compile.
        Collection<RunResult> results = new Runner(options(UdpBaselineBenchmark.class).warmupIterations(full ? 3 : 1)
                .build()).run();
        StringBuilder md = new StringBuilder(header("UDP baseline", "A 500-byte datagram ping-pong on loopback, per hop: "
                + "the physical floor Concord's hops are measured against."));
        md.append("| mode | median µs per hop | p90 |\n|---|---|---|\n");
        for (RunResult r : results) {
            String mode = r.getParams().getParam("mode");
            double m = median(r);
            udpHopUs.put(mode, m);
            System.out.printf(Locale.ROOT, "RESULT udp %s 500 hop_us=%.2f%n", mode, m);
            md.append(String.format(Locale.ROOT, "| %s | %.2f | %.2f |%n", mode, m,
                    r.getPrimaryResult().getStatistics().getPercentile(90)));
        }
        Files.writeString(reportDir.resolve("udp.md"), md.toString());
    }

    private void stack() throws RunnerException, IOException {
        Collection<RunResult> results = new Runner(options(StackBenchmark.class).build()).run();
        StringBuilder md = new StringBuilder(header("Stack: one message down one stack and up another",
                "500-byte content, no sockets, both copies of each frame delivered (the second is filtered)."));
        md.append("| profile | median µs | p90 µs | p99 µs |\n|---|---|---|---|\n");
        for (RunResult r : results) {
            String profile = r.getParams().getParam("profile");
            var st = r.getPrimaryResult().getStatistics();
            System.out.printf(Locale.ROOT, "RESULT stack %s 500 down_up_us=%.2f%n",
                    profile.equals("CLASS_7") ? "class7" : profile.toLowerCase(Locale.ROOT), st.getPercentile(50));
            md.append(String.format(Locale.ROOT, "| %s | %.2f | %.2f | %.2f |%n", profile, st.getPercentile(50),
                    st.getPercentile(90), st.getPercentile(99)));
        }
        md.append("\nFor scale, the UDP baseline (udp.md) gives the cost of a loopback hop on the same machine.\n");
        Files.writeString(reportDir.resolve("stack.md"), md.toString());
    }

    /** Issue 33: fill + extract of a 10-slot action, Concord's SL and binary content against JADE's SLCodec. */
    private void content() throws RunnerException, IOException {
        Collection<RunResult> results = new Runner(options(ContentBenchmark.class).build()).run();
        StringBuilder md = new StringBuilder(header("Content: fill + extract of a 10-slot action",
                "One `(action (agent-identifier ...) (Order ...))` with ten slots (strings, integers, floats, a boolean, "
                        + "a date, a sequence, a nested concept): filled into a message and extracted again, in one JVM. "
                        + "Concord's SL and binary content codecs with its bean ontology; JADE 4.3's SLCodec with its BeanOntology."));
        md.append("| codec | median µs | p90 µs | p99 µs |\n|---|---|---|---|\n");
        for (RunResult r : results) {
            String codec = r.getParams().getParam("codec");
            var st = r.getPrimaryResult().getStatistics();
            System.out.printf(Locale.ROOT, "RESULT content %s 10 fill_extract_us=%.2f%n", codec, st.getPercentile(50));
            md.append(String.format(Locale.ROOT, "| %s | %.2f | %.2f | %.2f |%n", codec, st.getPercentile(50),
                    st.getPercentile(90), st.getPercentile(99)));
        }
        Files.writeString(reportDir.resolve("content.md"), md.toString());
    }

    /** Chain or books in one JVM: every platform at every size. */
    private void rounds(String name, Class<?> benchmark, String param, String label, List<Integer> sizes)
            throws RunnerException, IOException {
        // The targets (class 7 against JADE) at every size; quick mode measures the other two variants
        // at the largest size only, to keep within its time with a warm-up long enough for the JIT.
        List<String> targets = List.of(Platforms.CONCORD_CLASS7, Platforms.JADE);
        List<String> others = List.of(Platforms.CONCORD_CLASS7_SOCKETS, Platforms.CONCORD_CLOSED);
        // One size at a time, the platforms back to back: this machine's speed drifts over minutes,
        // and a ratio of two figures taken minutes apart would measure the drift too.
        Map<String, TreeMap<Integer, Double>> byPlatform = Charts.series(PLATFORMS);
        for (int size : sizes) {
            List<String> platforms = new ArrayList<>(full ? PLATFORMS : targets);
            if (!full && size == sizes.get(sizes.size() - 1)) {
                platforms.addAll(others);
            }
            measure(options(benchmark), platforms, param, size, byPlatform);
        }
        StringBuilder md = new StringBuilder(header(name.equals("chain") ? "Chain (pass the secret), one JVM"
                        : "Book buyer, one JVM",
                name.equals("chain") ? "N agents pass a 500-byte content round a ring; time per round. JADE: one main container."
                        : "One buyer, S sellers: QUERY-REF to all, INFORM quotes, REQUEST to the cheapest, AGREE; time per "
                        + "round. JADE: one main container."));
        md.append("Concord class 7 is the full EN 50159 class-7 stack with agents of one runtime handing frames over in "
                + "memory (both stacks still run whole); `class7-sockets` forces every frame through the kernel; "
                + "`closed` is the closed-network profile." + (full ? "" : " Quick mode measures these two at the largest "
                + "size only.") + "\n\n");
        md.append("| ").append(label).append(" | concord class 7 µs | class 7 sockets µs | closed µs | JADE µs | speedup (JADE / class 7) |");
        if (name.equals("chain")) {
            md.append(" class-7 µs per hop |");
        }
        md.append("\n|---|---|---|---|---|---|").append(name.equals("chain") ? "---|" : "").append("\n");
        for (int size : sizes) {
            Double c7 = byPlatform.get(Platforms.CONCORD_CLASS7).get(size);
            Double sock = byPlatform.get(Platforms.CONCORD_CLASS7_SOCKETS).get(size);
            Double closed = byPlatform.get(Platforms.CONCORD_CLOSED).get(size);
            Double jade = byPlatform.get(Platforms.JADE).get(size);
            if (c7 != null && jade != null) {
                System.out.printf(Locale.ROOT, "RESULT %s onejvm" + hogsTag() + " %d concord_us=%.1f jade_us=%.1f speedup=%.2f%n",
                        name, size, c7, jade, jade / c7);
            }
            md.append(String.format(Locale.ROOT, "| %d | %s | %s | %s | %s | %s |", size, fmt(c7), fmt(sock), fmt(closed),
                    fmt(jade), c7 != null && jade != null ? String.format(Locale.ROOT, "%.2f", jade / c7) : "-"));
            if (name.equals("chain")) {
                md.append(c7 == null ? " - |" : String.format(Locale.ROOT, " %.2f |", c7 / size));
            }
            md.append('\n');
        }
        if (name.equals("chain") && udpHopUs.containsKey("onethread")) {
            Double c7at19 = byPlatform.get(Platforms.CONCORD_CLASS7).get(19);
            if (c7at19 != null) {
                md.append(String.format(Locale.ROOT, "%nPer hop at N=19: %.2f µs, %.1f times the one-thread UDP floor of "
                        + "%.2f µs measured in this run.%n", c7at19 / 19, c7at19 / 19 / udpHopUs.get("onethread"),
                        udpHopUs.get("onethread")));
            }
        }
        String png = name + "-onejvm.png";
        Charts.line(reportDir.resolve(png), (name.equals("chain") ? "Chain" : "Book buyer") + ": time per round, one JVM",
                label, "µs per round", byPlatform);
        md.append("\n![").append(name).append("](").append(png).append(")\n");
        Files.writeString(reportDir.resolve(name + ".md"), md.toString());
    }

    /** Runs the platforms at one size, back to back, and puts each one's median round into its series. */
    private static void measure(ChainedOptionsBuilder options, List<String> platforms, String param, int size,
                                Map<String, TreeMap<Integer, Double>> byPlatform) throws RunnerException {
        options.param("platform", platforms.toArray(new String[0])).param(param, String.valueOf(size));
        for (RunResult r : new Runner(options.build()).run()) {
            byPlatform.get(r.getParams().getParam("platform")).put(size, median(r));
        }
    }

    /** Chain or books with one process per agent: Concord class 7 and JADE. */
    private void processes(String name, Class<?> benchmark, String param, String label, List<Integer> sizes)
            throws RunnerException, IOException {
        // Quick mode keeps within its five minutes; full mode adds the closed profile.
        List<String> platforms = full ? List.of(Platforms.CONCORD_CLASS7, Platforms.CONCORD_CLOSED, Platforms.JADE)
                : List.of(Platforms.CONCORD_CLASS7, Platforms.JADE);
        // With two processes a child sees thousands of messages a second and compiles its hot paths
        // within the usual warm-up; from six processes on it sees a few hundred, and takes about ten
        // seconds of rounds (the book buyer at S = 5 goes from 28 ms a round to 0.3 ms): warm those up
        // that long, on both platforms.
        Map<String, TreeMap<Integer, Double>> byPlatform = Charts.series(platforms);
        for (int size : sizes) {
            int warmups = size <= 2 ? (full ? 5 : 3) : (full ? 8 : 10);
            measure(options(benchmark).warmupIterations(warmups), platforms, param, size, byPlatform);
        }
        StringBuilder md = new StringBuilder("\n## One process per agent\n\n")
                .append("The first agent (link 0, or the buyer) runs in the benchmark's JVM, every other agent in a JVM ")
                .append("of its own. Concord: UDP on loopback with the class-7 stack, addresses exchanged at start. JADE: ")
                .append("a main container here and a peripheral container per agent. On 2 cores, from 6 processes on, ")
                .append("the operating system's scheduling weighs more than either platform.\n\n")
                .append("| ").append(label).append(" | concord class 7 µs | closed µs | JADE µs | speedup |\n|---|---|---|---|---|\n");
        for (int size : sizes) {
            Double c7 = byPlatform.get(Platforms.CONCORD_CLASS7).get(size);
            Double closed = byPlatform.containsKey(Platforms.CONCORD_CLOSED) ? byPlatform.get(Platforms.CONCORD_CLOSED).get(size) : null;
            Double jade = byPlatform.get(Platforms.JADE).get(size);
            if (c7 != null && jade != null) {
                System.out.printf(Locale.ROOT, "RESULT %s processes" + hogsTag() + " %d concord_us=%.1f jade_us=%.1f speedup=%.2f%n",
                        name, size, c7, jade, jade / c7);
            }
            md.append(String.format(Locale.ROOT, "| %d | %s | %s | %s | %s |%n", size, fmt(c7), fmt(closed), fmt(jade),
                    c7 != null && jade != null ? String.format(Locale.ROOT, "%.2f", jade / c7) : "-"));
        }
        Double c7at2 = byPlatform.get(Platforms.CONCORD_CLASS7).get(2);
        if (name.equals("chain") && c7at2 != null && udpHopUs.containsKey("processes")) {
            md.append(String.format(Locale.ROOT, "%nPer hop at N=2: %.2f µs, %.2f times the two-process UDP baseline of "
                    + "%.2f µs measured in this run (each class-7 frame goes twice, against loss).%n", c7at2 / 2,
                    c7at2 / 2 / udpHopUs.get("processes"), udpHopUs.get("processes")));
        }
        String png = name + "-processes.png";
        Charts.line(reportDir.resolve(png), (name.equals("chain") ? "Chain" : "Book buyer")
                + ": time per round, one process per agent", label, "µs per round", byPlatform);
        md.append("\n![").append(name).append(" processes](").append(png).append(")\n");
        Files.writeString(reportDir.resolve(name + ".md"), md.toString(), StandardOpenOption.APPEND);
    }

    /** Experiments 1 and 2: bootstrap of N agents started at once, one maintenance cycle, failover. */
    private void platform(boolean bootstrap, boolean failover) throws IOException {
        List<Integer> sizes = List.of(1, 2, 5, 10, 20, 50, 100);
        int runs = full ? 5 : 1;
        Map<Integer, List<PlatformHarness.Bootstrap>> boots = new TreeMap<>();
        Map<Integer, List<PlatformHarness.Failover>> fails = new TreeMap<>();
        for (int run = 0; run < runs + 1; run++) {
            for (int n : sizes) {
                PlatformHarness.Run r;
                try {
                    r = PlatformHarness.run(n);
                } catch (Exception e) {
                    throw new IOException("the platform harness failed for N=" + n + ": " + e, e);
                }
                if (run == 0) {
                    continue; // warm-up: class loading and JIT of the first run
                }
                boots.computeIfAbsent(n, k -> new ArrayList<>()).add(r.bootstrap());
                fails.computeIfAbsent(n, k -> new ArrayList<>()).add(r.failover());
            }
        }
        String conf = "Defaults of PlatformConfig: maintenance period 40 ms + 0.5 ms per agent, an agent or the container is "
                + "dead after 3 silent periods, LAL pushed 5 ms after a change. Real UDP sockets on 127.0.0.1, one JVM, "
                + "class-7 stack (each agent's first message to another waits for a signed X25519 handshake). "
                + (runs > 1 ? "Median of " + runs + " runs after a warm-up run." : "One run after a warm-up run.");
        if (bootstrap) {
            StringBuilder md = new StringBuilder(header("Bootstrap (experiment 1)", "N agents started in one loop turn "
                    + "discover each other by port binding, elect a container, which collects and distributes the LAL. "
                    + "elect: until every agent follows the one container; collect: until the container lists all N; "
                    + "distribute: until every agent holds the container's version; cycle: one maintenance cycle "
                    + "(alive to the last confirmation), measured by the container. " + conf, "Wall time on the loop"));
            md.append("| N | converged | elect ms | collect ms | distribute ms | total ms | cycle ms |\n|---|---|---|---|---|---|---|\n");
            TreeMap<Integer, Double> total = new TreeMap<>();
            for (Map.Entry<Integer, List<PlatformHarness.Bootstrap>> e : boots.entrySet()) {
                List<PlatformHarness.Bootstrap> l = e.getValue();
                PlatformHarness.Bootstrap m = new PlatformHarness.Bootstrap(e.getKey(), l.stream().allMatch(PlatformHarness.Bootstrap::converged),
                        med(l, PlatformHarness.Bootstrap::electMs), med(l, PlatformHarness.Bootstrap::collectMs),
                        med(l, PlatformHarness.Bootstrap::distributeMs), med(l, PlatformHarness.Bootstrap::totalMs),
                        med(l, PlatformHarness.Bootstrap::cycleMs));
                System.out.println(m.line());
                total.put(e.getKey(), m.totalMs());
                md.append(String.format(Locale.ROOT, "| %d | %s | %.1f | %.1f | %.1f | %.1f | %.1f |%n", m.agents(), m.converged(),
                        m.electMs(), m.collectMs(), m.distributeMs(), m.totalMs(), m.cycleMs()));
            }
            md.append("\nTarget (measured, not asserted): 100 agents started at once converge in under 1 s. For scale: a JADE "
                    + "peripheral container takes 0.2-0.3 s to join its main container.\n");
            Charts.line(reportDir.resolve("bootstrap.png"), "Bootstrap: N agents started at once", "agents", "ms to a complete LAL",
                    Map.of("Concord class 7", total));
            md.append("\n![bootstrap](bootstrap.png)\n");
            Files.writeString(reportDir.resolve("bootstrap.md"), md.toString());
        }
        if (failover) {
            StringBuilder md = new StringBuilder(header("Failover (experiment 2)", "After bootstrap, the container agent "
                    + "crashes (its port closes, nothing more is said). detected: until the first agent gives it up; "
                    + "new container: until exactly one other agent is container; LAL complete: until every survivor "
                    + "holds the new container's list of N-1 agents. All agents share one runtime here, which tells the "
                    + "members at once that their container left it (crash included): nobody waits for a timeout. Between "
                    + "runtimes (processes, hosts) the members give the container up after the timeout of 3 silent periods "
                    + "(about 250 ms at these sizes), as the runs before 2026-11-23 measured here (LAL complete: 250-359 ms). "
                    + conf, "Wall time on the loop"));
            md.append("| N | converged | detected ms | new container ms | LAL complete ms |\n|---|---|---|---|---|\n");
            TreeMap<Integer, Double> complete = new TreeMap<>();
            for (Map.Entry<Integer, List<PlatformHarness.Failover>> e : fails.entrySet()) {
                if (e.getKey() < 2) {
                    continue;
                }
                List<PlatformHarness.Failover> l = e.getValue();
                PlatformHarness.Failover m = new PlatformHarness.Failover(e.getKey(), l.stream().allMatch(PlatformHarness.Failover::converged),
                        med(l, PlatformHarness.Failover::detectedMs), med(l, PlatformHarness.Failover::newContainerMs),
                        med(l, PlatformHarness.Failover::lalCompleteMs));
                System.out.println(m.line());
                complete.put(e.getKey(), m.lalCompleteMs());
                md.append(String.format(Locale.ROOT, "| %d | %s | %.1f | %.1f | %.1f |%n", m.agents(), m.converged(),
                        m.detectedMs(), m.newContainerMs(), m.lalCompleteMs()));
            }
            md.append("\nTarget (measured, not asserted): a new container with a complete LAL within 500 ms of the old one's "
                    + "death. For scale: JGroups 1.5-3.5 s after a crash, ~40 s after a silent loss; JADE main-container "
                    + "replication 3-13 s.\n");
            Charts.line(reportDir.resolve("failover.png"), "Failover: container crash to complete LAL", "agents", "ms",
                    Map.of("Concord class 7", complete));
            md.append("\n![failover](failover.png)\n");
            Files.writeString(reportDir.resolve("failover.md"), md.toString());
        }
    }

    private static <T> double med(List<T> l, ToDoubleFunction<T> f) {
        double[] v = l.stream().mapToDouble(f).sorted().toArray();
        return v.length == 0 ? -1 : v[v.length / 2];
    }

    /** The JADE bridge: JADE to Concord over HTTP beside JADE to JADE over HTTP. */
    private void http() throws RunnerException, IOException {
        // The target JVM sees a few hundred requests a second: it needs about ten seconds to compile its
        // HTTP, XML and codec paths (with 3 s, both platforms measured 2-3 times slower).
        Collection<RunResult> results = new Runner(options(HttpBenchmark.class).warmupIterations(full ? 8 : 10)
                .build()).run();
        Map<String, Double> us = new TreeMap<>();
        for (RunResult r : results) {
            us.put(r.getParams().getParam("target"), median(r));
        }
        Double c = us.get("concord");
        Double j = us.get("jade");
        Double f = us.get("floor");
        System.out.println(String.format(Locale.ROOT, "RESULT http request_reply concord_us=%.1f jade_us=%.1f floor_us=%.1f "
                + "speedup=%.2f", c, j, f, j / c));
        StringBuilder md = new StringBuilder(header("JADE bridge over HTTP", "A JADE 4.3 agent REQUESTs an agent of another "
                + "platform over FIPA's HTTP MTP and waits for its INFORM, 500 bytes each way, on 127.0.0.1. The other "
                + "platform is Concord (class 7; its container serves the HTTP MTP and relays to the agent), a second "
                + "JADE platform, or the floor: a server that answers each POST with bytes written once (no parsing, "
                + "no platform, no thread hand-off), so that what it takes is JADE's own side of the round. Each "
                + "runs in a JVM of its own. Time per request and reply."));
        md.append("| other platform | median µs |\n|---|---|\n");
        md.append(String.format(Locale.ROOT, "| Concord | %.1f |%n| JADE | %.1f |%n| floor | %.1f |%n", c, j, f));
        md.append(String.format(Locale.ROOT, "%nJADE to Concord takes %.2f times the time of JADE to JADE (speedup %.2f). "
                + "JADE's own side of a round (the floor) is %.1f µs; the other platform's share is %.1f µs for Concord "
                + "and %.1f µs for JADE (%.2f times Concord's).%n", c / j, j / c, f, c - f, j - f, (j - f) / (c - f)));
        Files.writeString(reportDir.resolve("http.md"), md.toString());
    }

    /**
     * Idle cost: platforms of 3, 20 and 100 idle agents, Concord's and JADE's, each in a JVM of its
     * own, all at once (idle, they hardly compete); the CPU time each JVM uses over a window after a
     * warm-up long enough for the JIT to have compiled what the platform's maintenance runs.
     */
    private void idle() throws IOException {
        List<Integer> sizes = List.of(3, 20, 100);
        long warmupS = Long.getLong("concord.idle.warmup", full ? 180 : 60);
        long windowS = Long.getLong("concord.idle.seconds", full ? 60 : 30);
        Map<String, TreeMap<Integer, Double>> pct = Charts.series(List.of("concord", "jade"));
        try (Children kids = new Children()) {
            int port = 7600;
            for (int n : sizes) {
                kids.start(IdlePlatform.class, "idle" + n, Integer.toString(port), Integer.toString(n));
                port += n + 30;
                kids.start(JadeIdle.class, Integer.toString(n));
            }
            kids.awaitReady();
            sleepS(warmupS);
            long[] before = new long[sizes.size() * 2];
            for (int i = 0; i < before.length; i++) {
                before[i] = kids.cpuNanos(i);
            }
            long t0 = System.nanoTime();
            sleepS(windowS);
            double wallNs = System.nanoTime() - t0;
            for (int k = 0; k < sizes.size(); k++) {
                double c = (kids.cpuNanos(2 * k) - before[2 * k]) / wallNs * 100;
                double j = (kids.cpuNanos(2 * k + 1) - before[2 * k + 1]) / wallNs * 100;
                pct.get("concord").put(sizes.get(k), c);
                pct.get("jade").put(sizes.get(k), j);
                System.out.printf(Locale.ROOT, "RESULT idle %d concord_cpu_pct=%.3f jade_cpu_pct=%.3f ratio=%.2f%n",
                        sizes.get(k), c, j, c / j);
            }
        }
        StringBuilder md = new StringBuilder(header("Idle cost", "Platforms of N agents that do nothing, each platform in a JVM "
                + "of its own: Concord (Boot's defaults: class 7, one runtime, its agents electing a container among them) and "
                + "JADE 4.3 (a main container, no MTP, plain `jade.core.Agent`s). All six JVMs run at once. The CPU time each "
                + "JVM used (every thread: the loop, the JIT, the GC) over " + windowS + " s, after " + warmupS + " s of warm-up, "
                + "in per cent of one core.", "Process CPU time"));
        md.append("| agents | Concord % of a core | JADE % of a core | Concord / JADE |\n|---|---|---|---|\n");
        for (int n : sizes) {
            double c = pct.get("concord").get(n);
            double j = pct.get("jade").get(n);
            md.append(String.format(Locale.ROOT, "| %d | %.3f | %.3f | %.2f |%n", n, c, j, c / j));
        }
        Charts.line(reportDir.resolve("idle.png"), "Idle cost: % of a core", "agents", "% of one core", pct);
        md.append("\n![idle](idle.png)\n");
        Files.writeString(reportDir.resolve("idle.md"), md.toString());
    }

    /**
     * A platform on a busy machine: 4 JVMs of 5 agents on one host (each agent registered a service
     * through the Java API), converged; then a phase with no load, and phases with 4 and 8 busy
     * loops (separate processes, normal priority) each followed by a calm one. Per phase: agents
     * removed from a list (every removal of a live agent is false), elections, registrations missing
     * at the phase's end, the loops' worst lag; and at the end of each loaded phase, a fifth JVM
     * killed with SIGKILL and the time until the others' lists no longer hold its agent.
     */
    private void load() throws IOException {
        loadMd = new StringBuilder();
        long phaseS = Long.getLong("concord.load.seconds", full ? 60 : 10);
        load(phaseS, 1);
        // The same on 3 hosts (network namespaces, 2 JVMs each), when this machine can make them.
        try {
            load(phaseS, 3);
        } catch (IOException e) {
            System.out.println("RESULT load hosts=3 skipped: " + e.getMessage());
            loadMd.append("\n3 hosts: not run (").append(e.getMessage()).append(").\n");
        }
        loadNotes();
    }

    private void load(long phaseS, int hostCount) throws IOException {
        int processes = hostCount == 1 ? 4 : 2 * hostCount;
        int perProcess = hostCount == 1 ? 5 : 3;
        int total = processes * perProcess;
        int perHost = total / hostCount;
        NetnsHosts net = null;
        if (hostCount > 1) {
            try {
                net = new NetnsHosts("cl" + (ProcessHandle.current().pid() % 100_000), hostCount);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted", e);
            }
        }
        try {
            loadOn(phaseS, hostCount, net, processes, perProcess, total, perHost);
        } finally {
            if (net != null) {
                net.close();
            }
        }
    }

    private StringBuilder loadMd;

    private void loadOn(long phaseS, int hostCount, NetnsHosts net, int processes, int perProcess, int total,
            int perHost) throws IOException {
        String tag = hostCount == 1 ? "" : " hosts=" + hostCount;
        String platform = "load" + ProcessHandle.current().pid() + "h" + hostCount;
        // -Dconcord.load.without=PORT_CHECK: the same run with the platform's stacks built without it (a comparison).
        String without = System.getProperty("concord.load.without", "");
        String first = "7401";
        String last = "7460";
        StringBuilder md = loadMd.length() > 0 ? loadMd : loadMd.append(header("A platform on a busy machine", "4 JVMs of 5 agents each, one platform on "
                + "127.0.0.1 (class 7), every agent registered a service through the Java API. Phases of " + phaseS + " s: no "
                + "load; 4 busy loops (`sh -c 'while :; do :; done'`, normal priority) beside them; calm; 8 busy loops; calm; "
                + "4 busy loops with each JVM in turn stopped (SIGSTOP) for 1 s every 2 s; calm. "
                + "Per phase: agents removed from any list (none stops, so every removal is false), containers taken or "
                + "failovers begun, services missing from the lists at the phase's end, the worst lag of any JVM's loop (a task "
                + "handed to it every 20 ms), and, at the end of the no-load and loaded phases, a fifth JVM of one agent "
                + "killed with SIGKILL and the time until the first JVM's list no longer holds it.", "Wall clock"));
        md.append(hostCount == 1 ? "## One host\n\n" : "\n## " + hostCount + " hosts (network namespaces on a bridge), 2 JVMs of 3 agents "
                + "each: one container per host, the hosts' lists shared by the federation\n\n");
        md.append("| phase | busy loops | false evictions | elections | lost registrations | worst loop lag ms | kill -9 seen after ms |\n"
                + "|---|---|---|---|---|---|---|\n");
        try (Children kids = new Children()) {
            for (int i = 0; i < processes; i++) {
                int h = i % hostCount + 1;
                kids.startWith(net == null ? List.of() : net.exec(h), LoadChild.class, platform, first, last,
                        Integer.toString(i), Integer.toString(perProcess), Integer.toString(perHost), without,
                        net == null ? "127.0.0.1" : NetnsHosts.address(h), Integer.toString(total));
            }
            kids.awaitReady();
            for (int i = 0; i < processes; i++) {
                kids.ask(i, "stats", "STATS"); // from here on
            }
            // {busy loops, kill -9 at the end, pause the JVMs one after another}
            int[][] phases = {{0, 1, 0}, {4, 1, 0}, {0, 0, 0}, {8, 1, 0}, {0, 0, 0}, {4, 0, 1}, {0, 0, 0}};
            String[] names = {"quiet", "loaded", "calm", "loaded", "calm", "paused", "calm"};
            int victim = processes;
            for (int ph = 0; ph < phases.length; ph++) {
                int hogs = phases[ph][0];
                boolean kill = phases[ph][1] == 1;
                List<Process> loops = new ArrayList<>();
                for (int h = 0; h < hogs; h++) {
                    loops.add(new ProcessBuilder("sh", "-c", "while :; do :; done").start());
                }
                double killMs = Double.NaN;
                try {
                    if (kill) {
                        kids.startWith(net == null ? List.of() : net.exec(1), LoadChild.class, platform, first,
                                last, "v" + ph, "1", Integer.toString(perHost + 1), without,
                                net == null ? "127.0.0.1" : NetnsHosts.address(1), Integer.toString(total + 1));
                        kids.readLine(victim, "READY"); // started after the others were ready
                        kids.ask(0, "stats", "STATS"); // its join is not part of the phase
                    }
                    if (phases[ph][2] == 1) {
                        // Each JVM in turn stopped (SIGSTOP) for 1 s, then let go on, 1 s apart: a
                        // process paused by a GC, a swap, a debugger, or a machine starved harder than busy loops do.
                        long end = System.nanoTime() + phaseS * 1_000_000_000L;
                        for (int k = 0; System.nanoTime() < end; k++) {
                            int who = k % processes;
                            kids.signal(who, "STOP");
                            sleepMs(1_000);
                            kids.signal(who, "CONT");
                            sleepMs(1_000);
                        }
                    } else {
                        sleepS(phaseS);
                    }
                    if (kill) {
                        kids.tell(0, "watch " + perHost);
                        long t0 = System.nanoTime();
                        kids.kill(victim);
                        String at = kids.readLine(0, "AT ");
                        killMs = (Long.parseLong(at.substring(3).trim()) - t0) / 1e6;
                        victim++;
                    }
                } finally {
                    for (Process p : loops) {
                        p.destroyForcibly();
                    }
                }
                long removed = 0;
                long elections = 0;
                long lag = 0;
                long lost = 0;
                for (int i = 0; i < processes; i++) {
                    String st = kids.ask(i, "stats", "STATS");
                    removed += field(st, "removed");
                    elections += field(st, "elections");
                    lag = Math.max(lag, field(st, "lag_ms"));
                    lost = Math.max(lost, total - field(st, "services"));
                }
                if (kill) {
                    removed -= 1; // the killed JVM's agent, removed by its container: a true one
                }
                String result = String.format(Locale.ROOT, "RESULT load" + tag + (without.isEmpty() ? "" : " without=" + without) + " phase=%s hogs=%d false_evictions=%d elections=%d "
                        + "lost_registrations=%d max_loop_lag_ms=%d kill9_detect_ms=%s", names[ph], hogs, removed, elections, lost,
                        lag, Double.isNaN(killMs) ? "-" : String.format(Locale.ROOT, "%.0f", killMs));
                System.out.println(result);
                md.append(String.format(Locale.ROOT, "| %s | %d | %d | %d | %d | %d | %s |%n", names[ph], hogs, removed, elections,
                        lost, lag, Double.isNaN(killMs) ? "-" : String.format(Locale.ROOT, "%.0f", killMs)));
            }
        }
    }

    private void loadNotes() throws IOException {
        StringBuilder md = loadMd;
        md.append("\nA removal is counted once, by the container that removes the agent (members take the container's list), "
                + "and a host dropped from the federation once by each other host's container; the killed JVM's own removal is "
                + "subtracted. Elections count a container taken and every failover begun. The worst loop lag is measured by a "
                + "thread of the JVM, which a SIGSTOP stops too: a paused JVM's own pause shows only in part.\n");
        Files.writeString(reportDir.resolve("load.md"), md.toString());
    }

    private static long field(String line, String key) {
        for (String part : line.split(" ")) {
            if (part.startsWith(key + "=")) {
                return Long.parseLong(part.substring(key.length() + 1));
            }
        }
        throw new IllegalArgumentException("no " + key + " in " + line);
    }

    /** Sustained messages per second, Concord against JADE and raw UDP (see ThroughputHarness). */
    private void throughput() throws IOException {
        double warm = full ? 5 : 2;
        double window = full ? 10 : 3;
        List<String> groups = new ArrayList<>();
        Map<String, Map<String, List<Double>>> bars = new TreeMap<>();
        StringBuilder md = new StringBuilder(header("Throughput", "Sustained messages per second on 127.0.0.1: S senders "
                + "and R receivers (`1to1`: 1 and 1; `16to1`: 16 senders to one receiver; `16pairs`: 16 and 16, sender i to "
                + "receiver i), all in one JVM (`onejvm`) or the receivers in a second JVM (`processes`), with 100 and 1,000 "
                + "bytes of content. Concord: class 7, every defence on, one runtime (one loop thread) per JVM; each sender "
                + "sends as fast as it is let (32 messages an action of a cyclic behaviour) and nothing paces it but the "
                + "platform's flow control. " + "Within one JVM Concord hands each message over in memory, a copy into the "
                + "receiver's mailbox (as JADE does inside a container; the stacks are for what leaves the process, and the "
                + "mailbox paces a fast sender); across processes every message takes both class-7 stacks, each frame "
                + "is sent twice (the copies in different datagrams), and the frames a cycle of the loop sends to one "
                + "receiver leave as one datagram (a bundle, up to 16 KiB on loopback; docs/wire-format.md)"
                + (Boolean.getBoolean("concord.bundle.off") ? ", here switched off (-Dconcord.bundle.off=true)" : "") + ". "
                + "JADE 4.3: one main container (and a peripheral container for the receivers); "
                + "JADE has no flow control (its queues grow until the heap is gone), so its senders keep a window of 2,048 "
                + "messages that the receivers acknowledge every 256. UDP: raw datagrams of the content's size, one message "
                + "a datagram (no bundling, no copies), one thread "
                + "sending from S sockets as fast as the kernel takes them, one receiving on R sockets through a selector; "
                + "nothing is acknowledged, so its rate is what arrives. Received messages counted over " + window + " s after "
                + warm + " s; then the senders stop, and what was sent and never arrived is `lost`.",
                "Messages received per second"));
        int cores = Math.max(2, Runtime.getRuntime().availableProcessors());
        md.append("In one JVM Concord runs twice: on one loop, and on " + cores + " loops (" + cores + " runtimes of one platform in "
                + "the JVM, as `Platform.Builder.loops(" + cores + ")` makes them). Each sender sits on its receiver's loop, pair i on "
                + "loop i mod " + cores + ", so its messages are handed over in memory: `16pairs` spreads over the loops, while "
                + "`1to1` and `16to1` have one receiver and so one loop's work. `across`: the same " + cores + " loops with every "
                + "sender on the loop after its receiver's, so that every message is handed from one loop to another (a copy "
                + "gathered per cycle into the receiver's loop's queue, no stack, no kernel).\n\n");
        md.append("Apache Pekko 1.7 (typed actors on its default dispatcher, one JVM only: the bench has no Pekko remoting) runs the "
                + "one-JVM shapes with JADE's window of 2,048 (its mailboxes are unbounded); `Concord / Pekko` takes Concord's better "
                + "of one and " + cores + " loops.\n\n");
        md.append("| shape | JVMs | bytes | Concord msg/s | Concord, " + cores + " loops | across | Pekko msg/s | JADE msg/s | UDP msg/s | Concord / JADE | "
                        + "Concord / Pekko | " + cores + " loops / 1 loop | across / 1 loop | Concord / UDP | lost (Concord / JADE) | Concord senders paused |\n")
                .append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        for (String mode : List.of("onejvm", "processes")) {
            for (String shape : List.of("1to1", "16to1", "16pairs")) {
                for (int bytes : List.of(100, 1000)) {
                    Map<String, ThroughputHarness.Result> r = new TreeMap<>();
                    List<String> peers = mode.equals("onejvm") ? List.of("concord", "concord-loops", "concord-across", "pekko", "jade", "udp") : List.of("concord", "jade", "udp");
                    for (String platform : peers) {
                        try {
                            r.put(platform, ThroughputHarness.run(platform, shape, mode.equals("processes"),
                                    bytes, warm, window));
                        } catch (Exception e) {
                            throw new IOException("throughput " + platform + " " + shape + " " + mode + " " + bytes + " failed: " + e, e);
                        }
                    }
                    double c = r.get("concord").msgsPerS();
                    double j = r.get("jade").msgsPerS();
                    double u = r.get("udp").msgsPerS();
                    double cl = r.containsKey("concord-loops") ? r.get("concord-loops").msgsPerS() : Double.NaN;
                    double pk = r.containsKey("pekko") ? r.get("pekko").msgsPerS() : Double.NaN;
                    double ca = r.containsKey("concord-across") ? r.get("concord-across").msgsPerS() : Double.NaN;
                    double best = Double.isNaN(cl) ? c : Math.max(c, cl);
                    System.out.printf(Locale.ROOT, "RESULT throughput %s %s %d concord_msgs_s=%.0f jade_msgs_s=%.0f udp_msgs_s=%.0f ratio=%.2f udp_ratio=%.2f concord_lost=%d%s%n",
                            shape, mode, bytes, c, j, u, c / j, c / u, r.get("concord").lost(),
                            Double.isNaN(cl) ? "" : String.format(Locale.ROOT, " concord_loops=%d concord_loops_msgs_s=%.0f loops_ratio=%.2f loops_lost=%d",
                                    cores, cl, cl / c, r.get("concord-loops").lost())
                            + (Double.isNaN(ca) ? "" : String.format(Locale.ROOT, " across_msgs_s=%.0f across_ratio=%.2f across_lost=%d",
                                    ca, ca / c, r.get("concord-across").lost()))
                            + (Double.isNaN(pk) ? "" : String.format(Locale.ROOT, " pekko_msgs_s=%.0f pekko_ratio=%.2f pekko_lost=%d",
                                    pk, best / pk, r.get("pekko").lost())));
                    md.append(String.format(Locale.ROOT, "| %s | %s | %d | %.0f | %s | %s | %s | %.0f | %.0f | %.2f | %s | %s | %s | %.2f | %d / %d | %d |%n", shape,
                            mode, bytes, c, Double.isNaN(cl) ? "" : String.format(Locale.ROOT, "%.0f", cl),
                            Double.isNaN(ca) ? "" : String.format(Locale.ROOT, "%.0f", ca),
                            Double.isNaN(pk) ? "" : String.format(Locale.ROOT, "%.0f", pk), j, u, c / j,
                            Double.isNaN(pk) ? "" : String.format(Locale.ROOT, "%.2f", best / pk),
                            Double.isNaN(cl) ? "" : String.format(Locale.ROOT, "%.2f", cl / c),
                            Double.isNaN(ca) ? "" : String.format(Locale.ROOT, "%.2f", ca / c), c / u, r.get("concord").lost(), r.get("jade").lost(),
                            r.get("concord").pauses()));
                    String group = shape + " " + bytes + "B";
                    if (!groups.contains(group)) {
                        groups.add(group);
                    }
                    Map<String, List<Double>> perMode = bars.computeIfAbsent(mode, k -> new LinkedHashMap<>());
                    perMode.computeIfAbsent("Concord", k -> new ArrayList<>()).add(c);
                    if (!Double.isNaN(cl)) {
                        perMode.computeIfAbsent("Concord, " + cores + " loops", k -> new ArrayList<>()).add(cl);
                    }
                    if (!Double.isNaN(pk)) {
                        perMode.computeIfAbsent("Pekko", k -> new ArrayList<>()).add(pk);
                    }
                    perMode.computeIfAbsent("JADE", k -> new ArrayList<>()).add(j);
                    perMode.computeIfAbsent("UDP", k -> new ArrayList<>()).add(u);
                }
            }
        }
        for (String mode : List.of("onejvm", "processes")) {
            String png = "throughput-" + mode + ".png";
            Charts.bars(reportDir.resolve(png), "Messages per second, " + (mode.equals("onejvm") ? "one JVM" : "receivers in a second JVM"),
                    "messages per second", groups, bars.get(mode));
            md.append("\n![").append(mode).append("](").append(png).append(")\n");
        }
        Files.writeString(reportDir.resolve("throughput.md"), md.toString());
    }

    /** The platform from 10 to 5,000 agents over 1 to 50 hosts, simulated (see ScaleHarness). */
    private void scale() throws IOException {
        int[][] points = {{10, 1}, {100, 10}, {500, 10}, {1000, 10}, {1000, 20}, {2000, 20}, {5000, 50}};
        StringBuilder md = new StringBuilder(header("Scale beyond one host", "N agents over H hosts in the test kit's "
                + "deterministic simulation (seed 7): each host a runtime with its platform (default configuration, class 3: "
                + "the message counts are those of class 7 but for the handshakes at first contact), its agents started at "
                + "once, the hosts 20 ms apart, finding each other by broadcast on one virtual network (50 µs a datagram, no loss). Every "
                + "agent is taken for a process of its own (the test kit's network can lose frames, so the runtime does not "
                + "vouch for its agents as it does on one real JVM): each gets its container's alive messages. converge: "
                + "virtual time, after the last host started (they start 20 ms apart), until every host has one container "
                + "followed by all its agents, each holding its host's list and every other host's agents; kB to converge: "
                + "everything sent from the first start to then, per agent; msgs and bytes: datagrams (each safety frame is sent twice against loss) "
                + "per agent per maintenance cycle over 5 s, steady; heal: after the last host is lost whole, virtual time "
                + "until the others agree without it (the federation takes a host for gone after 1.5 s of silence). "
                + "Virtual time counts the network, not the CPU.", "Virtual time; wall time of the simulation for scale"));
        md.append("| agents | hosts | converged | converge ms | heal ms | maintenance period ms | datagrams per agent per cycle "
                + "| bytes per agent per cycle | kB per agent to converge | kB per agent to heal | wall s |\n"
                + "|---|---|---|---|---|---|---|---|---|---|---|\n");
        Map<String, TreeMap<Integer, Double>> perAgent = Charts.series(List.of("datagrams", "kB"));
        Map<String, TreeMap<Integer, Double>> times = Charts.series(List.of("converge ms", "heal ms"));
        String heap = System.getProperty("concord.scale.heap", "14g");
        for (int[] p : points) {
            // Each point in a JVM of its own with a large heap: all the simulated hosts' agents live
            // in it, each with the whole list (5,000 agents: 25 million entries, about 8 GB).
            ScaleHarness.Result r;
            try {
                Process child = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx" + heap,
                        "-Dorg.slf4j.simpleLogger.defaultLogLevel=error", "-cp", System.getProperty("java.class.path"),
                        ScaleChild.class.getName(), Integer.toString(p[0]), Integer.toString(p[1]), "7")
                        .redirectErrorStream(true).start();
                String point = null;
                try (var out = new BufferedReader(new InputStreamReader(child.getInputStream()))) {
                    String line;
                    StringBuilder said = new StringBuilder();
                    while ((line = out.readLine()) != null) {
                        if (line.startsWith("POINT ")) {
                            point = line;
                        } else if (said.length() < 4000) {
                            said.append(line).append('\n');
                        }
                    }
                    if (point == null) {
                        throw new IOException("the scale simulation of " + p[0] + " agents over " + p[1] + " hosts ended without "
                                + "a result (heap " + heap + "; -Dconcord.scale.heap=... gives it more): " + said);
                    }
                }
                child.waitFor();
                r = ScaleChild.parse(point);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted", e);
            }
            System.out.println(r.line());
            md.append(String.format(Locale.ROOT, "| %d | %d | %s | %.1f | %.0f | %.0f | %.2f | %.0f | %.1f | %.1f | %.1f |%n", r.agents(),
                    r.hosts(), r.converged() && r.healed() ? "yes" : "NO", r.convergeMs(), r.healMs(), r.periodMs(),
                    r.msgsPerCyclePerAgent(), r.bytesPerCyclePerAgent(), r.convergeKbPerAgent(), r.healKbPerAgent(), r.wallS()));
            perAgent.get("datagrams").put(r.agents(), r.msgsPerCyclePerAgent());
            perAgent.get("kB").put(r.agents(), r.bytesPerCyclePerAgent() / 1000);
            times.get("converge ms").put(r.agents(), r.convergeMs());
            times.get("heal ms").put(r.agents(), r.healMs());
        }
        Charts.line(reportDir.resolve("scale-cost.png"), "Maintenance cost per agent per cycle", "agents", "per agent per cycle", perAgent);
        Charts.line(reportDir.resolve("scale-time.png"), "Converge and heal (virtual time)", "agents", "ms", times);
        md.append("\nEvery simulated agent holds the whole list, as a real one does; here they all live in one JVM (5,000 agents "
                + "hold 25 million entries), which is why each point runs in a JVM of its own with a large heap. On real "
                + "hosts each JVM holds its own agents' copies only.\n");
        md.append("\n![cost](scale-cost.png)\n\n![time](scale-time.png)\n");
        Files.writeString(reportDir.resolve("scale.md"), md.toString());
    }

    private static void sleepMs(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void sleepS(long s) {
        sleepMs(s * 1000);
    }

    /** The chain on a running platform, quiet and under each attack (see AttackHarness). */
    private void attack() throws IOException {
        double seconds = full ? 10 : 3;
        StringBuilder md = new StringBuilder(header("Under attack", "Six agents of one platform (class 7, every defence on, "
                + "real sockets on 127.0.0.1) pass a 500-byte secret round a ring, measured quiet and then while an attacker "
                + "in another JVM floods their ports: forged frames (an outsider: random bytes, Concord headers with random "
                + "ids and bodies), handshakes from new identities (a key holder: a new agent name, so a signed handshake, "
                + "each), TCP streams announcing 1 MiB frames (the platform on TCP), an agent of another platform over the "
                + "HTTP MTP (`foreign`: DF registrations under ever new names, and the observation service's kill and sniff, "
                + "all refused past their bounds: `links_alive` must stay 6) and 300 slow connections to the web console "
                + "(`console`: its answer to a normal request before and during). Forged deliveries are messages a "
                + "link received from anyone but its predecessor; the heap is the platform JVM's used heap, sampled every "
                + "20 ms during the flood. Both processes share the machine's cores: the control `cpu` is an attacker that only "
                + "keeps one core busy and sends nothing, so that the chain's slowdown from sharing the CPU is seen apart. "
                + "The flood runs as long before the measurement as the measurement lasts: its first seconds, before the "
                + "JIT has compiled the paths it takes, cost the chain 3 to 5 times.",
                "Median time per round over batches of 50 rounds"));
        md.append("| attack | attack messages sent | µs per round, quiet | µs per round, attacked | slower | forged delivered "
                + "| heap MB at most | heap MB after GC | drops counted by the agents | more |\n|---|---|---|---|---|---|---|---|---|---|\n");
        // -Dconcord.attack.kinds=handshake,tcp runs only those (to profile one).
        for (String kind : System.getProperty("concord.attack.kinds", "cpu,forged,handshake,tcp,foreign,console").split(",")) {
            AttackHarness.Result r;
            try {
                r = AttackHarness.run(kind, seconds);
            } catch (Exception e) {
                throw new IOException("the attack harness failed for " + kind + ": " + e, e);
            }
            System.out.println(r.line());
            md.append(String.format(Locale.ROOT, "| %s | %d | %.1f | %.1f | %.2f× | %d | %.0f | %.0f | %s | %s |%n", kind,
                    r.attackSent(), r.usBefore(), r.usDuring(), r.usDuring() / r.usBefore(), r.forged(), r.heapMbMax(),
                    r.heapMbAfterGc(), r.drops(), r.extra()));
        }
        Files.writeString(reportDir.resolve("attack.md"), md.toString());
    }

    /** Hosts in network namespaces: join and heal times. Needs root (namespaces). */
    private void network() throws IOException {
        List<Integer> sizes = full ? List.of(2, 3, 4, 6) : List.of(2, 3, 4);
        int runs = full ? 5 : 1;
        StringBuilder md = new StringBuilder(header("Network discovery across hosts", "H hosts as network namespaces "
                + "on a bridge (10.200.0.0/24), one agent per host in its own JVM (Boot, class 7), discovery by "
                + "UDP broadcast every 250 ms, a host gone after 1.5 s of silence. join: from the last host's agent "
                + "start to every host listing every other; heal: from the cut-off host's link coming back up to "
                + "all lists whole again.", "Wall time of the parent reading the JVMs' reports"));
        md.append("| hosts | join ms | heal ms |\n|---|---|---|\n");
        TreeMap<Integer, Double> joins = new TreeMap<>();
        TreeMap<Integer, Double> heals = new TreeMap<>();
        for (int h : sizes) {
            List<NetworkHarness.Result> rs = new ArrayList<>();
            for (int r = 0; r < runs; r++) {
                NetworkHarness.Result res;
                try {
                    res = NetworkHarness.run(h);
                } catch (Exception e) {
                    throw new IOException("the network harness failed for " + h + " hosts: " + e, e);
                }
                if (!res.ok()) {
                    System.out.println("network hosts=" + h + ": " + res.problem());
                    md.append("| ").append(h).append(" | ").append(res.problem()).append(" | |\n");
                    break;
                }
                rs.add(res);
            }
            if (rs.isEmpty()) {
                continue;
            }
            NetworkHarness.Result m = new NetworkHarness.Result(h, true, med(rs, NetworkHarness.Result::joinMs),
                    med(rs, NetworkHarness.Result::healMs), null);
            System.out.println(m.line());
            joins.put(h, m.joinMs());
            heals.put(h, m.healMs());
            md.append(String.format(Locale.ROOT, "| %d | %.1f | %.1f |%n", h, m.joinMs(), m.healMs()));
        }
        md.append("\nTargets (measured, not asserted): join under 1 s, heal under 2 s. For scale: JGroups' MERGE3 takes up "
                + "to about a minute to heal a partition.\n");
        if (!joins.isEmpty()) {
            Charts.line(reportDir.resolve("network.png"), "Network: join and heal", "hosts", "ms",
                    Map.of("join", joins, "heal", heals));
            md.append("\n![network](network.png)\n");
        }
        Files.writeString(reportDir.resolve("network.md"), md.toString());
    }

    /**
     * Experiment 3, per transport: 90 s in quick mode when asked for by name, 10 s as part of a quick
     * run of everything, 10 min in full mode ({@code -Dconcord.stress.seconds} to change: hours if asked).
     */
    private void stress(boolean byName) throws IOException {
        int seconds = Integer.getInteger("concord.stress.seconds", full ? 600 : byName ? 90 : 10);
        StringBuilder md = new StringBuilder(header("Stress (experiment 3)", "A sender and a receiver in two runtimes (real "
                + "sockets, class 7): four 500-byte messages every 2 ms (2000 a second if every tick is on time) for " + seconds + " s per transport; in the second "
                + "half, a message of growing size too, from 64 bytes to twice the frame limit (those over it are refused "
                + "to the sender, which goes on). Rate of the small messages and heap after GC, per window. The heap "
                + "grows while the sequence layer's retransmission buffer (1024 frames a peer) fills with the large "
                + "frames, and stays bounded by it: up to 8 MiB on UDP, 16 MiB on TCP.",
                "Wall-clock windows"));
        for (Transport t : List.of(Transport.UDP, Transport.TCP)) {
            StressHarness.Outcome o;
            try {
                o = StressHarness.run(t, seconds, 10);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
            System.out.println(StressHarness.describe(o));
            md.append("## ").append(t).append("\n\n| window | messages/s | heap MB after GC |\n|---|---|---|\n");
            for (int w = 0; w < o.ratePerWindow().size(); w++) {
                md.append(String.format(Locale.ROOT, "| %d | %.0f | %.1f |%n", w + 1, o.ratePerWindow().get(w),
                        o.heapMbPerWindow().get(w)));
            }
            md.append(String.format(Locale.ROOT, "%nDelivered %d small messages, %d out of order; %d over the limit "
                            + "refused to the sender; the largest delivered was %d bytes. Drops at the receiver: %s.%n%n",
                    o.delivered(), o.outOfOrder(), o.refused(), o.maxSizeDelivered(), o.drops()));
        }
        Files.writeString(reportDir.resolve("stress.md"), md.toString());
    }

    private void sim() throws IOException {
        double seconds = Double.parseDouble(System.getProperty("concord.sim.seconds", full ? "600" : "20"));
        HospitalMap map = HospitalMap.defaultHospital();
        StringBuilder md = new StringBuilder(header("Hospital simulation", "The default hospital (" + map.nodes().size()
                + " nodes, " + map.doors().size() + " doors, " + map.walls().size() + " wall fixtures) stepped at 60 Hz on the test kit's virtual clock, as fast as one core allows, with "
                + "chairs that drive from node to node at random with every sensor on (8 sonars of 5 rays at 10 Hz, 4 "
                + "infrared at 20 Hz, reports at 20 Hz) and doors that open as a chair comes near and close behind it. "
                + "Beside it, in the same run, the bare physics engine with the same walls and as many boxes driven by "
                + "velocity: what the world adds is the difference. Targets: 1,000 times real time with one chair, 50 with "
                + "ten. " + seconds + " s a size, in windows, each with the bytes allocated a step and the heap after a "
                + "collection (`-Dconcord.sim.seconds=600` for the 10-minute run). The chairs know no right of way (the "
                + "control agents will): ten of them meet and push in the corridors, and every contact costs a collision "
                + "record, so bytes a step follow the contacts while the heap stays flat. A chair wedged for 10 s (half "
                + "through a door that met it, nose to nose with another) is lifted back onto the node it came from, so "
                + "that the chairs keep driving, and batteries are recharged every minute of world time (a 500 Wh battery "
                + "lasts about 5 km); the mean speed and the lifts are in the table, and `sim-N.png` shows the paths. "
                + "The walker opens doors on approach but does not wait for them: it touches the revolving door now "
                + "and then (the red crosses).",
                "Wall-clock windows"));
        md.append("| chairs | steps/s | times real time | bare engine steps/s | world / engine | mean speed m/s a chair | lifted out of a jam | bytes a step | heap MB first / last window | collisions | metres driven | door commands |\n");
        md.append("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        StringBuilder windows = new StringBuilder();
        for (int chairs : List.of(1, 10)) {
            SimHarness.Outcome o = SimHarness.run(chairs, seconds, full ? 10 : 4, reportDir.resolve("sim-" + chairs + ".png"));
            System.out.println(SimHarness.describe(o));
            md.append(String.format(Locale.ROOT, "| %d | %.0f | %.0f | %.0f | %.2f | %.2f | %d | %.0f | %.1f / %.1f | %d | %.0f | %d |%n",
                    chairs, o.stepsPerS(), o.realtimeX(), o.engineStepsPerS(), o.stepsPerS() / o.engineStepsPerS(),
                    o.metresDriven() / o.worldSeconds() / chairs, o.resets(),
                    o.windows().get(o.windows().size() - 1).bytesPerStep(), o.windows().get(0).heapMb(),
                    o.windows().get(o.windows().size() - 1).heapMb(), o.collisions(), o.metresDriven(), o.doorMoves()));
            windows.append("\n### ").append(chairs).append(chairs == 1 ? " chair" : " chairs").append("\n\n| window | steps/s | bytes a step | heap MB after GC |\n|---|---|---|---|\n");
            for (int w = 0; w < o.windows().size(); w++) {
                SimHarness.Window x = o.windows().get(w);
                windows.append(String.format(Locale.ROOT, "| %d | %.0f | %.0f | %.1f |%n", w + 1, x.stepsPerS(), x.bytesPerStep(), x.heapMb()));
            }
        }
        md.append("\n## Windows\n").append(windows);
        Files.writeString(reportDir.resolve("sim.md"), md.toString());
    }

    private void fleet() throws IOException {
        double seconds = Double.parseDouble(System.getProperty("concord.fleet.seconds", full ? "7200" : "1800"));
        StringBuilder md = new StringBuilder(header("The fleet's scale curve", "Generated hospitals (`MapGenerator`, seed 37: "
                + "small, medium and large, about 30, 60 and 120 nodes, 10, 20 and 30 parking places) with 1, 5, 10 and 20 chairs "
                + "(as many as the map parks), a stream of transports between random rooms keeping one and a half per chair "
                + "outstanding (a new one as each ends; priorities 0-5, 20 s to get on and off), " + (long) seconds
                + " s of hospital time a point (`-Dconcord.fleet.seconds=N`), on the test kit's virtual clock: one thread runs "
                + "the world, every agent and the network. Each point twice, with the traffic agent's rules in order (the "
                + "default) and with whole routes (the rules before). Patients' wait: from the request to the chair at their "
                + "door. Decision: one call of the traffic agent's rules (a request, a release, a review), wall time. Chair-hours "
                + "waiting: a chair with a task under way standing still (for a route, its turn, a door), sampled each second. "
                + "The medium map is run three times: as generated, with a depot (`Shape.withDepot()`: its lobby's parking places "
                + "behind one node, every chair starting there), and single-lane (`Shape.withOneLane()`: one lane on every edge, "
                + "so that chairs never pass each other, a chair coming the other way or a slower one ahead only waited for). Past estimate: a delivered ride's time from the award to the "
                + "delivery less the cost its chair proposed (the seconds it said the patient would take to be delivered): the "
                + "quote's error, median and p95. Stalls: a chair with a task and no progress for 120 s that raised no alarm.",
                "Simulated time, wall-clock CPU"));
        md.append("| map | nodes | chairs | rules | done / sim h | failed | wait mean s | wait p95 s | decision p99 µs | decisions | "
                + "chair-h waiting | waiting for (chair-h) | contacts | CPU s / sim h | moved aside | deadlocks broken | reviews in an unbroken deadlock | "
                + "past estimate median s | past estimate p95 s | stalls |\n");
        md.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        List<FleetHarness.Outcome> all = new ArrayList<>();
        for (io.concord.sim.maps.Shape shape : List.of(io.concord.sim.maps.Shape.small(), io.concord.sim.maps.Shape.medium(),
                io.concord.sim.maps.Shape.medium().withDepot(), io.concord.sim.maps.Shape.medium().withOneLane(),
                io.concord.sim.maps.Shape.large())) {
            HospitalMap map = FleetHarness.map(shape);
            for (int chairs : List.of(1, 5, 10, 20)) {
                if (chairs > map.parking().size()) {
                    md.append(String.format(Locale.ROOT, "| %s | %d | %d | - | (the map parks %d) | | | | | | | | | | | | | | | |%n", shape.name(),
                            map.nodes().size(), chairs, map.parking().size()));
                    continue;
                }
                for (io.concord.agents.traffic.TrafficRules rules : List.of(io.concord.agents.traffic.TrafficRules.IN_ORDER,
                        io.concord.agents.traffic.TrafficRules.WHOLE_ROUTES)) {
                    FleetHarness.Outcome o = FleetHarness.run(map, chairs, rules, seconds, 37);
                    System.out.println(FleetHarness.describe(o));
                    all.add(o);
                    md.append(String.format(Locale.ROOT, "| %s | %d | %d | %s | %.1f | %d | %.0f | %.0f | %.1f | %d | %.2f | %s | %d | %.1f | %d | %d | %d | %.0f | %.0f | %d |%n",
                            shape.name(), o.nodes(), chairs, rules == io.concord.agents.traffic.TrafficRules.IN_ORDER ? "in order" : "whole routes",
                            o.donePerHour(), o.failed(), o.waitMeanS(), o.waitP95S(), o.decisionP99Us(), o.decisions(),
                            o.chairHoursWaiting(), FleetHarness.hours(o.waitingFor()), o.contacts(), o.cpuSPerSimHour(), o.movedAside(),
                            o.deadlocks(), o.deadlockedReviews(), o.pastMedianS(), o.pastP95S(), o.stalls()));
                }
            }
        }
        FleetHarness.Burst burst = FleetHarness.burst(FleetHarness.map(io.concord.sim.maps.Shape.large()), 20, 50, 37);
        System.out.println(FleetHarness.describe(burst));
        md.append(String.format(Locale.ROOT, "%n## Twenty chairs, fifty transports at once%n%nThe large map, 50 transports asked "
                        + "for in one instant of 20 idle chairs (50 auctions side by side, each CFP to 20 chairs, a 2 s window):%n%n"
                        + "| figure | value |%n|---|---|%n| all 50 awarded, hospital time | %.0f ms |%n| all 50 awarded, wall time | %.0f ms |%n"
                        + "| awarded at their first auction | %d of %d |%n| transports a chair | %d to %d, %d chairs used |%n"
                        + "| all done, hospital time | %.0f s |%n| done | %d |%n| contacts | %d |%n",
                burst.awardSimS() * 1000, burst.awardWallMs(), burst.firstAuction(), burst.tasks(), burst.minPerChair(), burst.maxPerChair(),
                burst.chairsUsed(), burst.allDoneSimS(), burst.done(), burst.contacts()));
        Charts.line(reportDir.resolve("fleet.png"), "Fleet: transports done per simulated hour", "chairs", "transports / hour",
                FleetHarness.series(all, FleetHarness.Outcome::donePerHour), true);
        Charts.line(reportDir.resolve("fleet-wait.png"), "Fleet: patients' wait, p95", "chairs", "seconds",
                FleetHarness.series(all, FleetHarness.Outcome::waitP95S), true);
        md.append("\n![transports per hour](fleet.png)\n\n![patients' wait p95](fleet-wait.png)\n");
        Files.writeString(reportDir.resolve("fleet.md"), md.toString());
    }

    private void blocking() throws IOException {
        BlockingBeside.Outcome o;
        try {
            o = BlockingBeside.run(full);
        } catch (IOException | RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException("the blocking benchmark failed", e);
        }
        System.out.printf(Locale.ROOT, "RESULT blocking echoes=%d without_us=%.1f blocking_us=%.1f ratio=%.2f%s%n",
                o.echoes(), o.withoutUs(), o.blockingUs(), o.ratio(), hogsTag());
        StringBuilder md = new StringBuilder(header("A blocking agent beside 100 non-blocking ones", "A prober pings "
                + o.echoes() + " echo agents one after the other on a class-7 Platform, in batches of 100 pings (one "
                + "sweep), median per ping; phases alternate (" + o.phases() + " of each): the echoes alone, and the "
                + "echoes beside one more agent that blocks (its behaviour, on a thread of its own, sleeps 50 ms then "
                + "waits 50 ms in blockingReceive, again and again). Target (issue 32): the others' latency unchanged, a "
                + "ratio near 1.", "Wall clock"));
        md.append(String.format(Locale.ROOT, "| phase | µs per ping | ratio |%n|---|---|---|%n| echoes alone | %.1f | |%n"
                + "| beside a blocking agent | %.1f | %.2f |%n", o.withoutUs(), o.blockingUs(), o.ratio()));
        Files.writeString(reportDir.resolve("blocking.md"), md.toString());
    }

    private void console() throws IOException {
        ConsoleCost.Outcome o;
        try {
            o = ConsoleCost.run(full);
        } catch (IOException | RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException("the console benchmark failed", e);
        }
        System.out.printf(Locale.ROOT, "RESULT console chain n=%d without_us=%.1f open_us=%.1f sniff_us=%.1f open_cost=%.1f%% sniff_cost=%.1f%%%n",
                o.links(), o.withoutUs(), o.openUs(), o.sniffUs(), o.openCost() * 100, o.sniffCost() * 100);
        StringBuilder md = new StringBuilder(header("What the console costs", "The chain of " + o.links() + " links on a class-7 "
                + "Platform (the container layer and the observer layer on every agent), rounds of 50, median per round; "
                + "phases alternate (" + o.phases() + " of each): no console; the console serving a browser that shows the "
                + "platform and safety views (every agent asked for its status every 2 s); and also sniffing one link. "
                + "Target: under 5 % with the console open.", "Wall clock"));
        md.append(String.format(Locale.ROOT, "| phase | µs per round | cost |%n|---|---|---|%n| no console | %.1f | |%n"
                + "| console open (platform, safety) | %.1f | %+.1f %% |%n| and the sniffer on link3 | %.1f | %+.1f %% |%n",
                o.withoutUs(), o.openUs(), o.openCost() * 100, o.sniffUs(), o.sniffCost() * 100));
        Files.writeString(reportDir.resolve("console.md"), md.toString());
    }

    private void hospital() throws IOException {
        HospitalBench.Outcome o;
        try {
            o = HospitalBench.run(full);
        } catch (IOException | RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException("the hospital benchmark failed", e);
        }
        System.out.println(HospitalBench.describe(o));
        StringBuilder md = new StringBuilder(header("The wheelchair's agents", "A* on the default hospital (31 nodes; four "
                + "routes across it) and on a generated 1,000-node graph (a 32 x 32 grid with 15 % of its edges removed; 64 "
                + "random pairs); the time from the Medical agent's request to its ACCEPT-PROPOSAL over real sockets on "
                + "loopback with class 7 (CFP, two plan requests, every door on both plans asked to confirm, PROPOSE, the "
                + "choice by utility); and the scenario 19 -> 3 -> 9 in simulated seconds. Targets: A* on 1,000 nodes under "
                + "1 ms (Nav2's route server: 0.23 ms on 10,000), an award under 50 ms (Open-RMF's bidding window alone is "
                + "2 s).", "Wall clock"));
        md.append(String.format(Locale.ROOT, "| figure | value |%n|---|---|%n| A* on the default hospital | %.2f µs |%n"
                        + "| A* on 1,000 nodes | %.2f µs |%n| award, median of %d (CFP to ACCEPT, class 7, loopback) | %.2f ms |%n"
                        + "| award, each | %s |%n| the scenario, simulated | %.1f s |%n", o.planUs(), o.plan1000Us(),
                o.awardMs().length, o.awardMedianMs(), Arrays.toString(Arrays.stream(o.awardMs())
                        .map(v -> Math.round(v * 100) / 100.0).toArray()), o.taskS()));
        Files.writeString(reportDir.resolve("hospital.md"), md.toString());
    }

    private void serial() throws IOException {
        SerialBench.Outcome o;
        try {
            o = SerialBench.run(full);
        } catch (IOException | RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException("the serial benchmark failed", e);
        }
        System.out.println(SerialBench.describe(o));
        StringBuilder md = new StringBuilder(header("The serial chair's link", "Over a real pty pair made by socat: the "
                + "board's logic (io.concord.serial.Board) in a thread of its own on one end, reading with a 1 ms timeout and "
                + "ticking after each read; the host's driver (SerialChair) on the other, on a platform's loop. A drive command "
                + "from the loop to the board's motors; a STATE from the board's write to the control agent's listener (one hop "
                + "from the reader thread to the loop); the watchdog, from the host's last frame written to the motors at zero "
                + "(the board's rule is 200 ms without a valid frame). Target: the watchdog within 200 ms of the window, a sensor "
                + "frame at the agent in under 1 ms.", "Wall clock"));
        md.append(String.format(Locale.ROOT, "| figure | median | 99th percentile | samples |%n|---|---|---|---|%n"
                        + "| drive command to motors | %.0f µs | %.0f µs | %d |%n| STATE to the agent | %.0f µs | %.0f µs | %d |%n"
                        + "| host silent to motors at zero | %.1f ms | %.1f ms | %d |%n",
                SerialBench.percentile(o.cmdToMotorUs(), 50), SerialBench.percentile(o.cmdToMotorUs(), 99), o.cmdToMotorUs().length,
                SerialBench.percentile(o.sensorToAgentUs(), 50), SerialBench.percentile(o.sensorToAgentUs(), 99), o.sensorToAgentUs().length,
                SerialBench.percentile(o.watchdogStopMs(), 50), SerialBench.percentile(o.watchdogStopMs(), 99), o.watchdogStopMs().length));
        md.append(String.format(Locale.ROOT, "%nA reopen mid-drive (the board falls silent while the agents drive at 60 %%; the host "
                        + "finds the link down, opens the port again and starts a new session): %d session(s) started, %d host frames "
                        + "taken by the board on it before any resume, **%d of them a DRIVE other than 0, 0** (must be 0: the host "
                        + "forgets its command at every hold, before the port is used again).%n",
                o.reopenSessions(), o.reopenFrames(), o.reopenNonNeutralFrames()));
        HeartbeatBench.Outcome hb;
        try {
            hb = HeartbeatBench.run(full);
        } catch (IOException | RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException("the heartbeat benchmark failed", e);
        }
        System.out.println(HeartbeatBench.describe(hb));
        md.append(String.format(Locale.ROOT, "%n## The heartbeat on a busy host, and the e-stop%n%n"
                        + "The host's driver behind its safety supervisor, the loop confirming a drive command at every STATE; the "
                        + "heartbeat from its own thread every 50 ms. Quiet, then beside 4 busy loops (processes that spin) on the %d "
                        + "cores, %d s each. The board's watchdog trips past 200 ms; the host stops its heartbeat when the loop has "
                        + "not confirmed a command for 300 ms. Then the e-stop, pressed at the board, to the STOP the host sends "
                        + "when its supervisor holds motion (one STATE period of 50 ms at most, plus the way).%n%n"
                        + "| figure | quiet | beside 4 busy loops |%n|---|---|---|%n"
                        + "| heartbeat gap as sent, 99th percentile | %.1f ms | %.1f ms |%n"
                        + "| heartbeat gap as sent, largest | %.1f ms | %.1f ms |%n"
                        + "| host frames taken by the board, gap 99th percentile | %.1f ms | %.1f ms |%n"
                        + "| host frames taken by the board, largest gap | %.1f ms | %.1f ms |%n"
                        + "| watchdog trips | %d | %d |%n%n"
                        + "| e-stop to the host's STOP | median %.1f ms | 99th percentile %.1f ms (%d presses) |%n",
                Runtime.getRuntime().availableProcessors(), full ? 30 : 6,
                SerialBench.percentile(hb.hostQuietMs(), 99), SerialBench.percentile(hb.hostLoadedMs(), 99),
                Arrays.stream(hb.hostQuietMs()).max().orElse(Double.NaN), Arrays.stream(hb.hostLoadedMs()).max().orElse(Double.NaN),
                SerialBench.percentile(hb.boardQuietMs(), 99), SerialBench.percentile(hb.boardLoadedMs(), 99),
                Arrays.stream(hb.boardQuietMs()).max().orElse(Double.NaN), Arrays.stream(hb.boardLoadedMs()).max().orElse(Double.NaN),
                hb.tripsQuiet(), hb.tripsLoaded(), SerialBench.percentile(hb.estopToStopMs(), 50),
                SerialBench.percentile(hb.estopToStopMs(), 99), hb.estopToStopMs().length));
        Files.writeString(reportDir.resolve("serial.md"), md.toString());
    }

    private static String fmt(Double v) {
        return v == null ? "-" : String.format(Locale.ROOT, "%.1f", v);
    }

    private void index() throws IOException {
        StringBuilder md = new StringBuilder("# Concord benchmark report\n\nWritten by `bench/run`. ")
                .append(Machine.describe()).append("\n\n");
        for (String n : NAMES) {
            if (Files.exists(reportDir.resolve(n + ".md"))) {
                md.append("- [").append(n).append("](").append(n).append(".md)\n");
            }
        }
        if (Files.exists(reportDir.resolve("ANALYSIS.md"))) {
            md.append("- [analysis: targets, and where the time goes](ANALYSIS.md) (written by hand from a run)\n");
        }
        Files.writeString(reportDir.resolve("README.md"), md.toString());
    }
}
