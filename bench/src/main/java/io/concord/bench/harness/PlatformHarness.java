package io.concord.bench.harness;

import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.layers.Platform;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.platform.Role;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Supplier;

/**
 * Experiments 1 and 2 of the dissertation on real UDP sockets in one JVM, with the class-7 stack:
 * N agents started in one loop turn (the same instant), and the container's crash.
 * Every time is taken on the loop, in the container layers' change callbacks.
 */
public final class PlatformHarness {
    static final PortRange PORTS = new PortRange(7801, 190, 10);

    public record Bootstrap(int agents, boolean converged, double electMs, double collectMs, double distributeMs,
                     double totalMs, double cycleMs) {
        public String line() {
            return String.format(Locale.ROOT,
                    "RESULT bootstrap agents=%d converged=%s elect_ms=%.1f collect_ms=%.1f distribute_ms=%.1f total_ms=%.1f",
                    agents, converged, electMs, collectMs, distributeMs, totalMs);
        }
    }

    public record Failover(int agents, boolean converged, double detectedMs, double newContainerMs, double lalCompleteMs) {
        public String line() {
            return String.format(Locale.ROOT,
                    "RESULT failover agents=%d detected_ms=%.1f new_container_ms=%.1f lal_complete_ms=%.1f",
                    agents, detectedMs, newContainerMs, lalCompleteMs);
        }
    }

    static final class Idle extends Agent {
    }

    private PlatformHarness() {
    }

    /** What one run measured. */
    public record Run(Bootstrap bootstrap, Failover failover) {
    }

    /** Runs bootstrap, one maintenance cycle, and failover for N agents. */
    public static Run run(int n) throws Exception {
        String name = "bench" + ProcessHandle.current().pid() + "n" + n;
        try (AgentRuntime rt = AgentRuntime.builder().platformName(name).build().start()) {
            Platform p = Platform.builder().runtime(rt).ports(PORTS)
                    .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(PlatformKey.random())
                            .identities(IdentityStore.ephemeral()).build()).build();
            List<AID> aids = new ArrayList<>();
            List<ContainerLayer> layers = new ArrayList<>();
            long[] t = new long[3]; // elect, collect, distribute
            CompletableFuture<Long> boot = new CompletableFuture<>();
            long[] t0 = new long[1];
            rt.execute(() -> {
                t0[0] = System.nanoTime();
                for (int i = 0; i < n; i++) {
                    aids.add(p.startAgent("a" + i, new Idle()));
                }
                for (AID a : aids) {
                    layers.add(Platform.containerLayer(rt, a));
                }
                Runnable check = () -> {
                    if (boot.isDone()) {
                        return;
                    }
                    long now = System.nanoTime();
                    ContainerLayer c = single(layers, null);
                    if (c == null) {
                        return;
                    }
                    if (t[0] == 0 && allFollow(layers, c)) {
                        t[0] = now;
                    }
                    if (t[1] == 0 && c.agents().size() == n) {
                        t[1] = now;
                    }
                    if (t[0] != 0 && t[1] != 0 && allHold(layers, c, n)) {
                        t[2] = now;
                        boot.complete(now);
                    }
                };
                for (ContainerLayer l : layers) {
                    l.addListener(x -> check.run());
                }
                check.run();
            });
            boolean ok;
            try {
                boot.get(20, TimeUnit.SECONDS);
                ok = true;
            } catch (TimeoutException e) {
                ok = false;
            }
            double elect = ms(t[0] - t0[0]);
            double collect = ms(Math.max(0, t[1] - t[0]));
            double dist = ms(Math.max(0, t[2] - Math.max(t[0], t[1])));
            // One maintenance cycle, measured by the container.
            double cycle = -1;
            if (ok) {
                ContainerLayer c = onLoop(rt, () -> single(layers, null));
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
                while (c.lastCycleNs() < 0 && System.nanoTime() < end) {
                    Thread.sleep(5);
                }
                cycle = c.lastCycleNs() < 0 ? -1 : c.lastCycleNs() / 1e6;
            }
            Bootstrap b = new Bootstrap(n, ok, elect, collect, dist, ok ? ms(t[2] - t0[0]) : -1, cycle);
            Failover f = ok && n > 1 ? failover(rt, aids, layers, n) : new Failover(n, false, -1, -1, -1);
            return new Run(b, f);
        }
    }

    private static Failover failover(AgentRuntime rt, List<AID> aids, List<ContainerLayer> layers, int n) throws Exception {
        CompletableFuture<Void> done = new CompletableFuture<>();
        long[] t = new long[4]; // kill, detected, new container, complete
        rt.execute(() -> {
            ContainerLayer old = single(layers, null);
            String oldName = old.containerName();
            int i = layers.indexOf(old);
            List<ContainerLayer> rest = new ArrayList<>(layers);
            rest.remove(i);
            AID victim = aids.get(i);
            Runnable check = () -> {
                if (done.isDone() || t[0] == 0) {
                    return;
                }
                long now = System.nanoTime();
                if (t[1] == 0) {
                    for (ContainerLayer l : rest) {
                        if (!oldName.equals(l.containerName())) {
                            t[1] = now;
                            break;
                        }
                    }
                }
                ContainerLayer c = single(rest, oldName);
                if (c == null) {
                    return;
                }
                if (t[2] == 0) {
                    t[2] = now;
                }
                if (c.agents().size() == n - 1 && allHold(rest, c, n - 1)) {
                    t[3] = now;
                    done.complete(null);
                }
            };
            for (ContainerLayer l : rest) {
                l.addListener(x -> check.run());
            }
            t[0] = System.nanoTime();
            rt.crashAgent(victim);
        });
        boolean ok;
        try {
            done.get(20, TimeUnit.SECONDS);
            ok = true;
        } catch (TimeoutException e) {
            ok = false;
        }
        return new Failover(n, ok, ms(t[1] - t[0]), ms(t[2] - t[0]), ok ? ms(t[3] - t[0]) : -1);
    }

    /** The one container among the layers (not the excluded name), or null if there is not exactly one. */
    private static ContainerLayer single(List<ContainerLayer> layers, String exclude) {
        ContainerLayer found = null;
        for (ContainerLayer l : layers) {
            if (l.role() == Role.CONTAINER && !l.selfEntry().name().equals(exclude)) {
                if (found != null) {
                    return null;
                }
                found = l;
            }
        }
        return found;
    }

    private static boolean allFollow(List<ContainerLayer> layers, ContainerLayer c) {
        for (ContainerLayer l : layers) {
            if (l.role() == Role.SEEKING || !c.containerName().equals(l.containerName())) {
                return false;
            }
        }
        return true;
    }

    private static boolean allHold(List<ContainerLayer> layers, ContainerLayer c, int n) {
        if (c.agents().size() != n) {
            return false;
        }
        for (ContainerLayer l : layers) {
            if (!c.containerName().equals(l.containerName()) || l.term() != c.term() || l.lalSequence() != c.lalSequence()) {
                return false;
            }
        }
        return true;
    }

    private static double ms(long ns) {
        return ns / 1e6;
    }

    /** What the supplier returns, computed on the runtime's loop. */
    static <T> T onLoop(AgentRuntime rt, Supplier<T> s) throws Exception {
        CompletableFuture<T> f = new CompletableFuture<>();
        rt.execute(() -> f.complete(s.get()));
        return f.get(10, TimeUnit.SECONDS);
    }
}
