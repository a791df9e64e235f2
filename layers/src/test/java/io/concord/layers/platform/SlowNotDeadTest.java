package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.defence.Defence;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.security.PlatformKey;
import org.junit.jupiter.api.Test;
import org.opentest4j.AssertionFailedError;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.TreeSet;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A slow machine is not a dead one. Three processes (runtimes) of one platform on one simulated
 * host, two agents each; one process, chosen by the seed (the container's or another), is paused
 * (no loop turn, its clock running, its ports held) for 100 ms to 3 s, or made slow (each turn of
 * its loop costs 5 to 40 ms) for 3 s. Nobody is removed from the list, nobody runs for container.
 * Then a process is killed (its ports freed): the lists are complete again, without its agents,
 * within 500 ms of simulated time. 200 seeds ({@code -Dconcord.slow.seeds}).
 */
class SlowNotDeadTest {
    static final int SEEDS = Integer.getInteger("concord.slow.seeds", 200);

    static final class Idle extends Agent {
    }

    @Test
    void pausedOrSlowProcessesAreKeptAndCrashedOnesRemovedWithin500ms() {
        for (int seed = 1; seed <= SEEDS; seed++) {
            run(seed, false);
        }
    }

    @Test
    void withoutThePortCheckAPauseEvicts() {
        AssertionFailedError e = assertThrows(AssertionFailedError.class, () -> {
            for (int seed = 1; seed <= 20; seed++) {
                run(seed, true, Defence.PORT_CHECK);
            }
        });
        assertTrue(e.getMessage().startsWith("nobody removed") || e.getMessage().startsWith("nobody runs for container"), e.getMessage());
    }

    /**
     * Past the bound: a member's process paused for 35 s is taken for hung and removed at 30 s (as
     * documented), and when it wakes it does not blame the container for its own silence: no
     * election, the same container and term, and it joins again. Meanwhile the container's process
     * is not held back by the alives it would have piled up for the silent member (flow control
     * paused the container's behaviours before).
     */
    @Test
    void aMemberPausedPastTheBoundIsRemovedThenJoinsAgainWithoutAnElection() {
        try (Simulation sim = new Simulation(7, FaultPlan.NONE).platformName("sim")) {
            List<String> elections = new ArrayList<>();
            List<String> removals = new ArrayList<>();
            sim.trace().addListener((ns, node, event, detail) -> {
                if (event.equals("platform-failover") || event.equals("platform-container")) {
                    elections.add(node + ": " + event + " " + detail);
                } else if (event.equals("platform-removed")) {
                    removals.add(node + ": " + detail);
                }
            });
            List<AgentRuntime> processes = new ArrayList<>();
            Map<AID, AgentRuntime> agents = new LinkedHashMap<>();
            for (int p = 0; p < 2; p++) {
                AgentRuntime rt = sim.newRuntime("h1");
                processes.add(rt);
                Platform platform = Platform.builder().runtime(rt).ports(new PortRange(7001, 40, 10))
                        .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(PlatformKey.of(new byte[32]))
                                .identities(PlatformWorld.sharedIdentities()).build()).build();
                agents.put(platform.startAgent("p" + p, new Idle()), rt);
                sim.runFor(200);
            }
            assertTrue(sim.runUntil(() -> converged(agents), 30_000));
            assertEquals("p0@sim", containerOf(agents));
            elections.clear();
            long pausesBefore = processes.get(0).pauses();
            sim.pause(processes.get(1), 35_000);
            sim.runFor(36_000);
            assertTrue(sim.runUntil(() -> converged(agents), 5_000), "it joined again: " + removals);
            assertEquals(List.of(), elections, "the member that was paused took over instead of joining again");
            assertEquals("p0@sim", containerOf(agents));
            assertEquals(1, removals.size(), "removed once, at the bound: " + removals);
            assertTrue(removals.get(0).contains("hung"), removals.get(0));
            assertEquals(pausesBefore, processes.get(0).pauses(), "the container's behaviours were never held back by flow control");
        }
    }

    private static void run(long seed, boolean pauseOnly, Defence... off) {
        SplittableRandom r = new SplittableRandom(seed);
        try (Simulation sim = new Simulation(seed, FaultPlan.NONE).platformName("sim")) {
            List<String> removals = new ArrayList<>();
            List<String> elections = new ArrayList<>();
            sim.trace().addListener((ns, node, event, detail) -> {
                if (event.equals("platform-removed") || event.equals("platform-host-gone")) {
                    removals.add(node + ": " + detail);
                } else if (event.equals("platform-failover") || event.equals("platform-container")) {
                    elections.add(node + ": " + event + " " + detail);
                }
            });
            List<AgentRuntime> processes = new ArrayList<>();
            Map<AID, AgentRuntime> agents = new LinkedHashMap<>();
            for (int p = 0; p < 3; p++) {
                AgentRuntime rt = sim.newRuntime("h1");
                processes.add(rt);
                Platform platform = Platform.builder().runtime(rt).ports(new PortRange(7001, 40, 10)).withoutDefences(off)
                        .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(PlatformKey.of(new byte[32]))
                                .identities(PlatformWorld.sharedIdentities()).build()).build();
                for (int i = 0; i < 2; i++) {
                    agents.put(platform.startAgent("p" + p + "a" + i, new Idle()), rt);
                    sim.runFor(r.nextInt(1, 60));
                }
            }
            assertTrue(sim.runUntil(() -> converged(agents), 30_000), "seed " + seed + ": converged first");
            String container = containerOf(agents);
            long term = layer(agents, agents.keySet().iterator().next()).term();
            removals.clear();
            elections.clear();

            AgentRuntime victim = processes.get(r.nextInt(processes.size()));
            boolean pause = pauseOnly || r.nextBoolean();
            String fault;
            if (pause) {
                long ms = r.nextLong(100, 3_001);
                fault = "paused " + ms + " ms";
                sim.pause(victim, ms);
                sim.runFor(ms + 2_000);
            } else {
                double turnMs = 5 + r.nextInt(36);
                fault = "slowed to " + turnMs + " ms a turn";
                sim.slow(victim, turnMs);
                sim.runFor(3_000);
                sim.slow(victim, 0);
                sim.runFor(2_000);
            }
            boolean hadContainer = agents.entrySet().stream().anyMatch(a -> a.getValue() == victim && a.getKey().name().equals(container));
            String where = "seed " + seed + ", the process " + (hadContainer ? "of the container" : "of two members") + " " + fault;
            assertEquals(List.of(), removals, "nobody removed: " + where);
            assertEquals(List.of(), elections, "nobody runs for container: " + where);
            assertTrue(converged(agents), "the lists are whole: " + where);
            assertEquals(container + " t" + term, containerOf(agents) + " t" + layer(agents, agents.keySet().iterator().next()).term(),
                    "the same container, the same term: " + where);

            // A real crash: the process is killed, its ports freed.
            AgentRuntime killed = processes.get(r.nextInt(processes.size()));
            agents.values().removeIf(rt -> rt == killed);
            sim.crash(killed);
            long before = sim.clock().nanoTime();
            boolean whole = sim.runUntil(() -> converged(agents), 5_000);
            long tookMs = (sim.clock().nanoTime() - before) / 1_000_000L;
            assertTrue(whole && tookMs <= 500, "seed " + seed + ": the lists are whole again " + tookMs
                    + " ms after a process was killed (at most 500)");
        }
    }

    private static ContainerLayer layer(Map<AID, AgentRuntime> agents, AID a) {
        return Platform.containerLayer(agents.get(a), a);
    }

    private static String containerOf(Map<AID, AgentRuntime> agents) {
        for (AID a : agents.keySet()) {
            ContainerLayer l = layer(agents, a);
            if (l != null && l.role() == Role.CONTAINER) {
                return a.name();
            }
        }
        return null;
    }

    /** One container; every live agent holds its list, which lists exactly the live agents. */
    private static boolean converged(Map<AID, AgentRuntime> agents) {
        String c = null;
        TreeSet<String> expected = new TreeSet<>();
        for (AID a : agents.keySet()) {
            expected.add(a.name());
            ContainerLayer l = layer(agents, a);
            if (l == null) {
                return false;
            }
            if (l.role() == Role.CONTAINER) {
                if (c != null) {
                    return false;
                }
                c = a.name();
            }
        }
        if (c == null) {
            return false;
        }
        for (AID a : agents.keySet()) {
            ContainerLayer l = layer(agents, a);
            TreeSet<String> listed = new TreeSet<>();
            for (AgentEntry e : l.agents()) {
                listed.add(e.name());
            }
            if (!c.equals(l.containerName()) || !listed.equals(expected)) {
                return false;
            }
        }
        return true;
    }
}
