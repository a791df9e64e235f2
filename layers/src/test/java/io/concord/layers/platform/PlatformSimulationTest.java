package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.core.agent.AgentRuntime;
import io.concord.testkit.FaultPlan;
import io.concord.layers.Profile;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The container layer in deterministic simulation: for each seed, 1 to 100 agents on one virtual
 * host, started at the same instant or staggered, with loss, duplication, reordering, delay and
 * corruption; random crashes (the container's included), restarts and clean stops; sometimes an
 * agent of a foreign platform in the same port range. After the faults stop and the stabilisation
 * time passes: exactly one container, every live agent holds the container's list, which lists
 * exactly the live agents; no platform message was ever accepted from a non-member.
 *
 * <p>Replay one seed: {@code mvn -pl layers test -Dtest=PlatformSimulationTest -Dconcord.sim.seed=N -Dconcord.sim.seeds=1}.
 */
class PlatformSimulationTest {
    static final long STABILISATION_MS = 5_000;

    @Test
    void manySeedsConvergeToOneContainerWithOneList() {
        int seeds = Integer.getInteger("concord.sim.seeds", 1000);
        long first = Long.getLong("concord.sim.seed", 1);
        List<String> failures = new ArrayList<>();
        for (long seed = first; seed < first + seeds; seed++) {
            String f = scenario(seed);
            if (f != null) {
                failures.add("seed " + seed + ": " + f);
                if (failures.size() >= 3) {
                    break;
                }
            }
        }
        assertTrue(failures.isEmpty(), "failing seeds (replay with -Dconcord.sim.seed=N -Dconcord.sim.seeds=1):\n"
                + String.join("\n", failures));
    }

    @Test
    void sameSeedSameTrace() {
        assertEquals(traceOf(77), traceOf(77));
        assertTrue(traceOf(77) != traceOf(78));
    }

    private static long traceOf(long seed) {
        try (PlatformWorld w = new PlatformWorld(seed, FaultPlan.lossy(0.05, 0.05, 0.05, 0), Profile.CLOSED)) {
            for (int i = 0; i < 8; i++) {
                w.start("a" + i);
            }
            w.sim.runFor(1_000);
            w.crash(w.containers().get(0));
            w.sim.runFor(2_000);
            return w.sim.trace().hash();
        }
    }

    static String scenario(long seed) {
        SplittableRandom r = new SplittableRandom(seed * 0x9E3779B97F4A7C15L);
        int n = r.nextInt(10) == 0 ? 50 + r.nextInt(51) : 1 + r.nextInt(20);
        Profile profile = seed % 50 == 0 ? Profile.CLASS_7 : seed % 10 == 5 ? Profile.CLASS_3 : Profile.CLOSED;
        FaultPlan plan = FaultPlan.lossy(r.nextDouble() * 0.15, r.nextDouble() * 0.1, r.nextDouble() * 0.1,
                r.nextDouble() * 0.01).withLatency(20_000 + r.nextInt(2_000_000), r.nextInt(1_000_000));
        boolean sameInstant = r.nextBoolean();
        try (PlatformWorld w = new PlatformWorld(seed, plan, profile)) {
            AgentRuntime foreign = null;
            if (seed % 10 == 3) {
                // Another platform on the same host, holding ports of the same range.
                w.sim.platformName("other");
                foreign = w.sim.newRuntime(PlatformWorld.HOST, null);
                Platform other = Platform.builder().runtime(foreign).ports(w.platform.ports())
                        .safetyStack(io.concord.layers.SafetyStack.builder().profile(Profile.CLOSED).build()).build();
                for (int i = 0; i < 3; i++) {
                    other.startAgent("f" + i, new PlatformWorld.Idle());
                }
            }
            List<String> names = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                names.add("a" + i);
            }
            for (String name : names) {
                w.start(name);
                if (!sameInstant) {
                    w.sim.runFor(r.nextInt(300));
                }
            }
            int events = r.nextInt(7);
            List<String> dead = new ArrayList<>();
            for (int e = 0; e < events; e++) {
                w.sim.runFor(50 + r.nextInt(800));
                int what = r.nextInt(10);
                if (what < 5 && !w.live.isEmpty()) {
                    List<String> cs = w.containers();
                    String victim = !cs.isEmpty() && r.nextInt(3) == 0 ? cs.get(0)
                            : new ArrayList<>(w.live.keySet()).get(r.nextInt(w.live.size()));
                    w.crash(victim);
                    dead.add(victim);
                    w.log.add("crash " + victim);
                } else if (what < 8 && !dead.isEmpty()) {
                    String back = dead.remove(r.nextInt(dead.size()));
                    w.start(back);
                    w.log.add("restart " + back);
                } else if (w.live.size() > 1) {
                    String leaver = new ArrayList<>(w.live.keySet()).get(r.nextInt(w.live.size()));
                    w.stop(leaver);
                    dead.add(leaver);
                    w.log.add("stop " + leaver);
                }
            }
            if (w.live.isEmpty()) {
                w.start("last");
            }
            w.sim.network().setFaultPlan(FaultPlan.NONE);
            if (!w.sim.runUntil(w::converged, STABILISATION_MS)) {
                return "no convergence after " + STABILISATION_MS + " ms of quiet (n=" + n + " " + profile + " "
                        + (sameInstant ? "same instant" : "staggered") + ", events " + w.log + "):\n" + w.describe();
            }
            w.sim.runFor(1_000);
            if (!w.converged()) {
                return "converged, then diverged on a quiet network:\n" + w.describe();
            }
            if (!w.violations.isEmpty()) {
                return w.violations.get(0);
            }
            // The seed's trace hash, kept in the surefire report: a refactoring that must not
            // change behaviour leaves every seed's hash as it was.
            System.out.printf("seed %d trace %016x%n", seed, w.sim.trace().hash());
            return null;
        }
    }
}
