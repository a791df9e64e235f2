package io.concord.bench.harness;

import io.concord.bench.child.IdleAgent;

import io.concord.testkit.NetnsHosts;
import io.concord.layers.Boot;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/**
 * The network benchmark: H hosts as network namespaces on a bridge (10.200.0.0/24), one agent per
 * host in a JVM of its own started with {@link Boot}, class 7, broadcast discovery. join: from the
 * moment the last host's agent has started to the moment every host lists every other;
 * heal: from the moment a host's link comes back up (after the others dropped it) to the moment all
 * lists are whole again. Times are the parent's wall clock on reading each JVM's report.
 */
public final class NetworkHarness {
    public record Result(int hosts, boolean ok, double joinMs, double healMs, String problem) {
        public String line() {
            return String.format(java.util.Locale.ROOT, "RESULT network hosts=%d join_ms=%.1f heal_ms=%.1f", hosts, joinMs, healMs);
        }
    }

    /** One JVM's last report: how many agents it lists here and on other hosts. */
    private static final class Jvm {
        final Process process;
        volatile int here = -1;
        volatile int elsewhere = -1;
        volatile boolean started;

        Jvm(Process p) {
            this.process = p;
            Thread t = new Thread(() -> {
                try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                    String l;
                    while ((l = r.readLine()) != null) {
                        if (l.startsWith("started ")) {
                            started = true;
                        }
                        int h = l.indexOf(" agents here");
                        int a = l.indexOf(" agent here");
                        int cut = h >= 0 ? h : a;
                        if (cut > 0) {
                            int comma = l.lastIndexOf(", ", cut);
                            here = Integer.parseInt(l.substring(comma + 2, cut));
                            int o = l.indexOf(" on other hosts");
                            elsewhere = o < 0 ? 0 : Integer.parseInt(l.substring(l.lastIndexOf(", ", o) + 2, o));
                        }
                    }
                } catch (IOException | RuntimeException ignored) {
                    // the JVM ended
                }
            });
            t.setDaemon(true);
            t.start();
        }
    }

    private NetworkHarness() {
    }

    public static Result run(int hosts) throws Exception {
        String prefix = "cb" + (ProcessHandle.current().pid() % 100_000);
        Map<Integer, Jvm> jvms = new LinkedHashMap<>();
        Path home = Files.createTempDirectory("concord-bench-net");
        NetnsHosts net = null;
        try {
            try {
                net = new NetnsHosts(prefix, hosts);
            } catch (IOException e) {
                return new Result(hosts, false, -1, -1, "cannot create network namespaces (needs root and iproute2): "
                        + e.getMessage());
            }
            io.concord.layers.security.PlatformKey.loadOrCreate(home.resolve("platform.key"));
            for (int i = 1; i < hosts; i++) {
                jvms.put(i, spawn(net, i, home));
            }
            if (!await(jvms, j -> j.here == 1 && j.elsewhere == hosts - 2, 60)) {
                return new Result(hosts, false, -1, -1, "the first hosts did not find each other");
            }
            Jvm last = spawn(net, hosts, home);
            jvms.put(hosts, last);
            if (!await(Map.of(hosts, last), j -> j.started, 60)) {
                return new Result(hosts, false, -1, -1, "the last host's JVM did not start");
            }
            long t0 = System.nanoTime();
            if (!await(jvms, j -> j.here == 1 && j.elsewhere == hosts - 1, 60)) {
                return new Result(hosts, false, -1, -1, "the new host did not join");
            }
            double join = (System.nanoTime() - t0) / 1e6;
            net.link(hosts, false);
            if (!await(jvms, j -> j == last ? j.elsewhere == 0 : j.elsewhere == hosts - 2, 60)) {
                return new Result(hosts, false, join, -1, "the others did not drop the cut-off host");
            }
            long t1 = System.nanoTime();
            net.link(hosts, true);
            if (!await(jvms, j -> j.here == 1 && j.elsewhere == hosts - 1, 60)) {
                return new Result(hosts, false, join, -1, "the partition did not heal");
            }
            double heal = (System.nanoTime() - t1) / 1e6;
            return new Result(hosts, true, join, heal, null);
        } finally {
            for (Jvm j : jvms.values()) {
                j.process.destroyForcibly();
            }
            for (Jvm j : jvms.values()) {
                j.process.waitFor(10, TimeUnit.SECONDS);
            }
            if (net != null) {
                net.close();
            }
        }
    }

    private static Jvm spawn(NetnsHosts net, int host, Path home) throws IOException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(net.exec(host));
        cmd.addAll(List.of(java, "-Dconcord.home=" + home, "-Dorg.slf4j.simpleLogger.defaultLogLevel=error", "-cp",
                System.getProperty("java.class.path"), Boot.class.getName(), "-name", "netbench", "-host",
                NetnsHosts.address(host), "-watch", "-agents", "a" + host + ":" + IdleAgent.class.getName()));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        return new Jvm(p);
    }

    private static boolean await(Map<Integer, Jvm> jvms, Predicate<Jvm> ok, int seconds) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (System.nanoTime() < end) {
            if (jvms.values().stream().allMatch(ok)) {
                return true;
            }
            Thread.sleep(1); // polling the JVMs' reports; the resolution of the measurement
        }
        return false;
    }
}
