package io.concord.bench.harness;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.plan.AStar;
import io.concord.agents.plan.Route;
import io.concord.agents.plan.RouteGraph;
import io.concord.agents.proto.Services;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.Platform;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.platform.ServiceDescription;
import io.concord.layers.security.PlatformKey;
import io.concord.sim.Hospital;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

/**
 * The wheelchair's figures: A* on the default hospital and on a generated 1,000-node graph (Nav2's
 * route server searches 10,000 nodes in 0.23 ms), the time from a CFP to its ACCEPT-PROPOSAL over
 * real sockets with class 7 (two plans, every door on them asked, a proposal, the choice; Open-RMF's
 * bidding window alone is 2 s), and the scenario's duration in simulated seconds.
 */
public final class HospitalBench {
    public record Outcome(double planUs, double plan1000Us, double[] awardMs, double taskS) {
        public double awardMedianMs() {
            double[] a = awardMs.clone();
            Arrays.sort(a);
            return a[a.length / 2];
        }
    }

    private HospitalBench() {
    }

    public static Outcome run(boolean full) throws Exception {
        HospitalMap map = HospitalMap.defaultHospital();
        double planUs = astar(RouteGraph.of(map), new int[][] {{19, 3}, {3, 9}, {14, 31}, {30, 15}}, full);
        RouteGraph grid = RouteGraph.grid(32, 32, 0.15, 9);
        SplittableRandom r = new SplittableRandom(3);
        int[][] pairs = new int[64][];
        for (int i = 0; i < pairs.length; i++) {
            pairs[i] = new int[] {r.nextInt(1024), r.nextInt(1024)};
        }
        double plan1000Us = astar(grid, pairs, full);
        double[] award = award(full ? 50 : 20);
        double taskS = task();
        return new Outcome(planUs, plan1000Us, award, taskS);
    }

    /** Mean microseconds a search, after the JIT has compiled it. */
    private static double astar(RouteGraph g, int[][] pairs, boolean full) {
        AStar a = new AStar(g, 4);
        long sink = 0;
        long warm = System.nanoTime() + (full ? 5_000_000_000L : 2_000_000_000L);
        int k = 0;
        while (System.nanoTime() < warm) {
            Route route = a.find(pairs[k % pairs.length][0], pairs[k % pairs.length][1]);
            sink += route == null ? 0 : route.nodes().size();
            k++;
        }
        int n = 0;
        long t0 = System.nanoTime();
        long end = t0 + (full ? 5_000_000_000L : 2_000_000_000L);
        long t;
        do {
            for (int i = 0; i < 100; i++) {
                Route route = a.find(pairs[n % pairs.length][0], pairs[n % pairs.length][1]);
                sink += route == null ? 0 : route.nodes().size();
                n++;
            }
            t = System.nanoTime();
        } while (t < end);
        if (sink == 42) {
            System.out.println();
        }
        return (t - t0) / 1e3 / n;
    }

    /**
     * Milliseconds from a transport's start to its ACCEPT-PROPOSAL, over real sockets on loopback
     * with class 7: the ward's agents in this JVM's platform, one chair; the first rounds warm up.
     */
    private static double[] award(int rounds) throws Exception {
        try (Platform platform = Platform.builder().name("bench-hospital-" + ProcessHandle.current().pid())
                .ports(new PortRange(7401, 200, 10)).build()) {
            AgentRuntime rt = platform.runtime();
            HospitalWorld world = HospitalWorld.builder(HospitalMap.defaultHospital()).seed(1).build();
            world.addChair("chair1", ChairConfig.standard().withWatchdog(0.3), world.poseAt(19, 90));
            world.attach(rt);
            CompletableFuture<Hospital> h = new CompletableFuture<>();
            rt.execute(() -> h.complete(Hospital.start(platform, world, s -> { })));
            Hospital hospital = h.get(60, TimeUnit.SECONDS);
            ConcurrentHashMap<String, Long> accepted = new ConcurrentHashMap<>();
            MedicalAgent medical = new MedicalAgent(line -> {
                if (line.contains(": ACCEPT ")) {
                    accepted.put(line.substring(line.lastIndexOf(' ') + 1), System.nanoTime());
                }
            });
            platform.startAgent("medical", medical);
            waitUntil(rt, () -> hospital.ready()
                    && !Platform.of(medical).searchCopy(ServiceDescription.ofType(Services.TRANSPORT)).isEmpty(), 60);
            int warm = rounds / 2;
            double[] out = new double[rounds - warm];
            for (int i = 0; i < rounds; i++) {
                long t0 = System.nanoTime();
                medical.transport(3, 9, 3, 30);
                String id = "T" + (i + 1);
                long deadline = t0 + 10_000_000_000L;
                while (!accepted.containsKey(id) && System.nanoTime() < deadline) {
                    Thread.onSpinWait();
                }
                Long t1 = accepted.get(id);
                if (t1 == null) {
                    throw new IllegalStateException("no ACCEPT for " + id + " within 10 s");
                }
                if (i >= warm) {
                    out[i - warm] = (t1 - t0) / 1e6;
                }
            }
            return out;
        }
    }

    private static void waitUntil(AgentRuntime rt, BooleanSupplier c, int seconds) throws Exception {
        long end = System.nanoTime() + seconds * 1_000_000_000L;
        while (System.nanoTime() < end) {
            CompletableFuture<Boolean> f = new CompletableFuture<>();
            rt.execute(() -> f.complete(c.getAsBoolean()));
            if (f.get(10, TimeUnit.SECONDS)) {
                return;
            }
            Thread.sleep(50);
        }
        throw new IllegalStateException("the hospital's agents did not find each other within " + seconds + " s");
    }

    /** The scenario on the virtual clock: simulated seconds from the request to the INFORM done. */
    private static double task() {
        try (Simulation sim = new Simulation(2010, FaultPlan.NONE)) {
            sim.platformName("hospital");
            AgentRuntime rt = sim.newRuntime("h1");
            Platform platform = Platform.builder().runtime(rt).ports(new PortRange(7001, 200, 10))
                    .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(
                            PlatformKey.of(new byte[32])).build()).build();
            HospitalWorld world = HospitalWorld.builder(HospitalMap.defaultHospital()).seed(2010).build();
            world.addChair("chair1", ChairConfig.standard().withWatchdog(0.3), world.poseAt(19, 90));
            world.attach(rt);
            Hospital hospital = Hospital.start(platform, world, s -> { });
            MedicalAgent medical = new MedicalAgent(s -> { });
            platform.startAgent("medical", medical);
            sim.runUntil(hospital::ready, 60_000);
            long t0 = sim.clock().nanoTime();
            var f = medical.transport(3, 9, 3, 60);
            sim.runUntil(f::isDone, 1_800_000);
            if (!f.isDone() || !f.join().done()) {
                throw new IllegalStateException("the scenario did not end done: " + (f.isDone() ? f.join() : "still running"));
            }
            return (sim.clock().nanoTime() - t0) / 1e9;
        }
    }

    public static String describe(Outcome o) {
        return String.format(Locale.ROOT, "RESULT hospital plan_us=%.2f plan1000_us=%.2f award_ms=%.2f task_s=%.1f",
                o.planUs(), o.plan1000Us(), o.awardMedianMs(), o.taskS());
    }
}
