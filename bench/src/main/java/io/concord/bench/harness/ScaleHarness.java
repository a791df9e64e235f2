package io.concord.bench.harness;

import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.Platform;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.platform.NetworkConfig;
import io.concord.layers.platform.PlatformConfig;
import io.concord.layers.security.PlatformKey;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The platform at a scale no machine here holds, in the test kit's deterministic simulation: N
 * agents over H hosts on one virtual network (no loss), each host a runtime with its platform
 * (the default configuration, class 3), its agents started at once, the hosts coming up 20 ms
 * apart and finding each other by broadcast. Measured on the virtual clock, from the last host's
 * start: the time until every host has one container and
 * every agent holds its host's list and the other hosts' agents; then, steady, the datagrams and
 * bytes sent per agent per maintenance cycle; then one host is lost whole, and the time until the
 * others agree again without it.
 */
public final class ScaleHarness {
    /** One measured point. */
    public record Result(int agents, int hosts, boolean converged, double convergeMs, boolean healed, double healMs,
                         double msgsPerCyclePerAgent, double bytesPerCyclePerAgent, double periodMs, double convergeKbPerAgent,
                         double healKbPerAgent, double allUpMs, double wallS) {
        public String line() {
            return String.format(Locale.ROOT, "RESULT scale %d %d converge_ms=%.0f heal_ms=%.0f "
                            + "msgs_per_cycle_per_agent=%.2f bytes_per_cycle_per_agent=%.0f converge_kb_per_agent=%.1f "
                            + "heal_kb_per_agent=%.1f", agents, hosts, convergeMs, healMs, msgsPerCyclePerAgent,
                    bytesPerCyclePerAgent, convergeKbPerAgent, healKbPerAgent);
        }
    }

    private static final class Idle extends Agent {
    }

    /** Between two hosts' starts. */
    public static final long STAGGER_MS = 20;

    private final Simulation sim;
    private final Map<String, AgentRuntime> hosts = new LinkedHashMap<>();
    private final Map<String, List<AID>> agents = new LinkedHashMap<>();

    private ScaleHarness(long seed) {
        sim = new Simulation(seed, FaultPlan.NONE).platformName("scale");
    }

    public static Result run(int n, int h, long seed) {
        long wall0 = System.nanoTime();
        ScaleHarness w = new ScaleHarness(seed);
        try {
            int perHost = (n + h - 1) / h;
            PlatformKey key = PlatformKey.of(new byte[32]);
            long t0 = w.sim.clock().nanoTime();
            for (int i = 0; i < h; i++) {
                if (i > 0) {
                    // Hosts come up one after another, 20 ms apart. All at once, every container's
                    // first list for its members is the whole GAL: 5,000 agents times 5,000
                    // entries, twice (class 3 sends each frame twice), 8 GB at one virtual instant
                    // in a simulated network that has no bandwidth to spread it.
                    w.sim.runFor(STAGGER_MS);
                }
                String host = "10.200." + (i / 250) + "." + (1 + i % 250);
                AgentRuntime rt = w.sim.newRuntime(host);
                Platform p = Platform.builder().runtime(rt).ports(new PortRange(7001, perHost + 20, 10))
                        .network(NetworkConfig.defaults())
                        .safetyStack(SafetyStack.builder().profile(Profile.CLASS_3).platformKey(key).build()).build();
                w.hosts.put(host, rt);
                List<AID> mine = new ArrayList<>();
                for (int k = 0; k < perHost && i * perHost + k < n; k++) {
                    mine.add(p.startAgent("a" + (i * perHost + k), new Idle()));
                }
                w.agents.put(host, mine);
            }
            long last = w.sim.clock().nanoTime();
            boolean converged = w.runUntilConverged(120_000);
            double convergeMs = (w.sim.clock().nanoTime() - last) / 1e6;
            double allUpMs = (w.sim.clock().nanoTime() - t0) / 1e6;
            double convergeKb = w.sim.network().sentBytes() / 1000.0 / n;

            // Steady: let the last list changes settle, then count what maintenance sends.
            w.sim.runFor(2_000);
            double periodMs = PlatformConfig.defaults().periodMs(perHost);
            long sent0 = w.sim.network().sentCount();
            long bytes0 = w.sim.network().sentBytes();
            long steadyMs = 5_000;
            w.sim.runFor(steadyMs);
            double cycles = steadyMs / periodMs;
            double msgs = (w.sim.network().sentCount() - sent0) / cycles / n;
            double bytes = (w.sim.network().sentBytes() - bytes0) / cycles / n;

            // A host is lost whole (the last one: not the first to have started).
            String lost = new ArrayList<>(w.hosts.keySet()).get(h - 1);
            boolean healed = true;
            double healMs = 0;
            double healKb = 0;
            if (h > 1) {
                w.sim.crash(w.hosts.remove(lost));
                w.agents.remove(lost);
                long t1 = w.sim.clock().nanoTime();
                long b1 = w.sim.network().sentBytes();
                healed = w.runUntilConverged(120_000);
                healMs = (w.sim.clock().nanoTime() - t1) / 1e6;
                // What the heal sent beyond the steady maintenance of the same time.
                healKb = Math.max(0, (w.sim.network().sentBytes() - b1) - bytes * n * (healMs / periodMs)) / 1000.0 / n;
            }
            return new Result(n, h, converged, convergeMs, healed, healMs, msgs, bytes, periodMs, convergeKb, healKb, allUpMs,
                    (System.nanoTime() - wall0) / 1e9);
        } finally {
            w.sim.close();
        }
    }

    /** Runs until converged, looked at every millisecond of virtual time (each look costs O(N)). */
    private boolean runUntilConverged(long maxMs) {
        long[] next = {sim.clock().nanoTime()};
        return sim.runUntil(() -> {
            long now = sim.clock().nanoTime();
            if (now < next[0]) {
                return false;
            }
            next[0] = now + 1_000_000L;
            return converged();
        }, maxMs);
    }

    /** Every host has one container, followed by all its agents; each holds its host's agents and every other host's. */
    private boolean converged() {
        int total = 0;
        for (List<AID> l : agents.values()) {
            total += l.size();
        }
        for (Map.Entry<String, List<AID>> e : agents.entrySet()) {
            AgentRuntime rt = hosts.get(e.getKey());
            int local = e.getValue().size();
            String container = null;
            for (AID a : e.getValue()) {
                ContainerLayer l = Platform.containerLayer(rt, a);
                if (l == null || l.containerName() == null) {
                    return false;
                }
                if (container == null) {
                    container = l.containerName();
                } else if (!container.equals(l.containerName())) {
                    return false;
                }
                if (l.agentCount() != local || l.globalAgentCount() != total - local) {
                    return false;
                }
            }
        }
        return true;
    }
}
