package io.concord.bench.harness;

import io.concord.bench.child.AttackChild;
import io.concord.bench.child.Children;
import io.concord.bench.concord.ConcordChainLink;
import io.concord.bench.support.Chain;
import io.concord.bench.support.Rounds;
import io.concord.core.acl.AID;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.core.net.Address;
import io.concord.core.net.Transport;
import io.concord.layers.Platform;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * {@code bench/run attack}: a platform of six agents passing a 500-byte secret round a ring (the
 * chain benchmark) on real sockets, class 7 with every defence on, measured quiet and then while
 * an attacker in another JVM floods its agents' ports ({@link AttackChild}). Reports the time per
 * round before and during, the messages the chain's agents received from anyone but their
 * predecessor (forged deliveries, which must stay 0), the JVM's heap at most, and the drops the
 * agents counted by reason.
 */
public final class AttackHarness {
    static final int AGENTS = 6;
    static final int ROUNDS = 50;
    static final String SECRET = Chain.SECRET;

    /** What one attack measured. */
    public record Result(String kind, double usBefore, double usDuring, long forged, double heapMbMax, double heapMbAfterGc,
                         long attackSent, Map<String, Long> drops, String extra) {
        public String line() {
            return String.format(Locale.ROOT, "RESULT attack %s chain_us_before=%.1f chain_us_during=%.1f delivered_forged=%d "
                    + "heap_mb_max=%.0f heap_mb_after_gc=%.0f sent=%d", kind, usBefore, usDuring, forged, heapMbMax, heapMbAfterGc,
                    attackSent) + (extra.isEmpty() ? "" : " " + extra);
        }
    }

    private AttackHarness() {
    }

    public static Result run(String kind, double seconds) throws Exception {
        Transport transport = kind.equals("tcp") ? Transport.TCP : Transport.UDP;
        PlatformKey key = PlatformKey.random();
        String name = "attack" + ProcessHandle.current().pid() + kind;
        try (AgentRuntime rt = AgentRuntime.builder().platformName(name).build().start()) {
            int web = kind.equals("foreign") || kind.equals("console") ? freePort() : 0;
            List<io.concord.jade.HttpMtp> mtp = new java.util.concurrent.CopyOnWriteArrayList<>();
            Platform.Builder pb = Platform.builder().runtime(rt).ports(new PortRange(7851, 20, 10)).transport(transport)
                    .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(key).transport(transport)
                            .identities(IdentityStore.ephemeral()).build());
            if (kind.equals("foreign")) {
                // Every agent may become container and serve the ACC; the one that does is the one attacked.
                pb.gateway(() -> {
                    io.concord.jade.HttpMtp m = new io.concord.jade.HttpMtp("127.0.0.1", web);
                    mtp.add(m);
                    return m;
                });
            }
            Platform p = pb.build();
            Rounds rounds = new Rounds();
            List<ConcordChainLink> links = new ArrayList<>();
            List<AID> aids = new ArrayList<>();
            CountDownLatch started = new CountDownLatch(1);
            rt.execute(() -> {
                for (int i = 0; i < AGENTS; i++) {
                    ConcordChainLink l = new ConcordChainLink(rounds, i == 0, SECRET);
                    links.add(l);
                    aids.add(p.startAgent("link" + i, l));
                }
                started.countDown();
            });
            started.await();
            for (int i = 0; i < AGENTS; i++) {
                links.get(i).next = aids.get((i + 1) % AGENTS);
                links.get(i).previous = aids.get((i + AGENTS - 1) % AGENTS);
            }
            List<ContainerLayer> layers = new ArrayList<>();
            for (AID a : aids) {
                layers.add(PlatformHarness.onLoop(rt, () -> Platform.containerLayer(rt, a)));
            }
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (!PlatformHarness.onLoop(rt, () -> layers.stream().allMatch(l -> l.agents().size() == AGENTS))) {
                if (System.nanoTime() > end) {
                    throw new IllegalStateException("the attack platform did not converge in 20 s");
                }
                Thread.sleep(20);
            }
            io.concord.console.Console console = kind.equals("console")
                    ? io.concord.console.Console.start(p, io.concord.console.Console.Config.parse("127.0.0.1:" + web)) : null;
            if (kind.equals("foreign")) {
                awaitHttp(web);
            }
            ConcordChainLink first = links.get(0);
            measure(rt, rounds, first, seconds / 2); // warm-up
            double consoleBefore = console == null ? 0 : consoleMs(web);
            double before = measure(rt, rounds, first, seconds);
            List<String> targets = new ArrayList<>();
            for (int i = 0; i < AGENTS; i++) {
                Address at = PlatformHarness.onLoop(rt, layers.get(i)::selfEntry).transportAddress();
                targets.add(aids.get(i).name() + "=" + at.host() + ":" + at.port());
            }
            List<String> args = new ArrayList<>(List.of(kind, name, HexFormat.of().formatHex(key.bytes())));
            if (web != 0) {
                args.add("http=127.0.0.1:" + web);
            }
            args.addAll(targets);
            double[] heapMax = new double[1];
            double[] consoleDuring = new double[1];
            long sent;
            double during;
            try (Children attacker = new Children()) {
                // -Dconcord.attack.cpus=1 pins the attacker (taskset -c): its CPU use apart from the victims' work.
                attacker.startOn(System.getProperty("concord.attack.cpus"), AttackChild.class, args.toArray(new String[0]));
                attacker.awaitReady();
                Thread sampler = new Thread(() -> {
                    while (!Thread.currentThread().isInterrupted()) {
                        double mb = ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed() / 1048576.0;
                        heapMax[0] = Math.max(heapMax[0], mb);
                        try {
                            Thread.sleep(20);
                        } catch (InterruptedException e) {
                            return;
                        }
                    }
                }, "heap-sampler");
                sampler.setDaemon(true);
                sampler.start();
                // The flood builds up for as long as it is then measured: meanwhile the JIT compiles
                // the paths the attack takes (its first seconds, interpreted, cost the chain 3-5x).
                Thread.sleep(Long.getLong("concord.attack.buildupMs", (long) (seconds * 1_000)));
                during = measure(rt, rounds, first, seconds);
                consoleDuring[0] = console == null ? 0 : consoleMs(web);
                sampler.interrupt();
                sent = attacker.finish(0);
            }
            Thread.sleep(2_500); // messages held for the lists are dropped after 2 s: count them too
            long forged = 0;
            String stranger = null;
            for (ConcordChainLink l : links) {
                forged += l.strangers.get();
                stranger = l.lastStranger != null ? l.lastStranger : stranger;
            }
            Map<String, Long> drops = new TreeMap<>();
            for (AID a : aids) {
                PlatformHarness.onLoop(rt, () -> rt.drops(a)).forEach((k, v) -> drops.merge(k, v, Long::sum));
            }
            String extra = stranger == null ? "" : "last_forged=\"" + stranger + "\"";
            if (!mtp.isEmpty()) {
                for (io.concord.jade.HttpMtp m : mtp) {   // one per agent; the container's served
                    m.drops().forEach((k, v) -> drops.merge(k, v, Long::sum));
                }
                int alive = PlatformHarness.onLoop(rt, () -> (int) aids.stream().filter(a -> rt.agents().contains(a)).count());
                extra = extra + (extra.isEmpty() ? "" : " ") + "links_alive=" + alive + " df_limit=" + drops.getOrDefault("df-limit", 0L) + " not_authorized="
                        + drops.getOrDefault("not-authorized", 0L);
            }
            if (console != null) {
                extra = String.format(Locale.ROOT, "console_ms_before=%.1f console_ms_during=%.1f", consoleBefore, consoleDuring[0]);
                console.close();
            }
            System.gc();
            double retained = ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed() / 1048576.0;
            return new Result(kind, before, during, forged, heapMax[0], retained, sent, drops, extra);
        }
    }

    private static int freePort() throws java.io.IOException {
        try (java.net.ServerSocket s = new java.net.ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    /** Waits until the container serves the ACC (a GET answers 405: it takes POSTs). */
    private static void awaitHttp(int port) throws Exception {
        java.net.http.HttpClient c = java.net.http.HttpClient.newHttpClient();
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (System.nanoTime() < end) {
            try {
                c.send(java.net.http.HttpRequest.newBuilder(java.net.URI.create("http://127.0.0.1:" + port + "/acc")).GET().build(),
                        java.net.http.HttpResponse.BodyHandlers.discarding());
                return;
            } catch (java.io.IOException e) {
                Thread.sleep(20);
            }
        }
        throw new IllegalStateException("the platform's ACC did not serve in 20 s");
    }

    /** The console's answer to a normal request (GET /api/platform), median of 20, in ms; fails if it does not answer in 10 s. */
    private static double consoleMs(int port) throws Exception {
        java.net.http.HttpClient c = java.net.http.HttpClient.newBuilder().connectTimeout(java.time.Duration.ofSeconds(10)).build();
        double[] ms = new double[20];
        for (int i = 0; i < ms.length; i++) {
            long t0 = System.nanoTime();
            java.net.http.HttpResponse<String> r = c.send(java.net.http.HttpRequest.newBuilder(
                    java.net.URI.create("http://127.0.0.1:" + port + "/api/platform")).timeout(java.time.Duration.ofSeconds(10)).GET().build(),
                    java.net.http.HttpResponse.BodyHandlers.ofString());
            if (r.statusCode() != 200) {
                throw new IllegalStateException("the console answered " + r.statusCode() + ": " + r.body());
            }
            ms[i] = (System.nanoTime() - t0) / 1e6;
        }
        Arrays.sort(ms);
        return ms[ms.length / 2];
    }

    /** Median time per round over batches of {@link #ROUNDS}, for about that many seconds. */
    private static double measure(AgentRuntime rt, Rounds rounds, ConcordChainLink first, double seconds) throws Exception {
        List<Double> us = new ArrayList<>();
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < end || us.size() < 5) {
            long t0 = System.nanoTime();
            rounds.arm(ROUNDS);
            rt.execute(first::startRound);
            rounds.await();
            us.add((System.nanoTime() - t0) / 1e3 / ROUNDS);
        }
        double[] a = us.stream().mapToDouble(Double::doubleValue).toArray();
        Arrays.sort(a);
        return a[a.length / 2];
    }
}
