package io.concord.testkit;

import io.concord.core.agent.AgentRuntime;
import io.concord.core.layer.Layer;
import io.concord.core.time.ManualClock;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

/**
 * A deterministic world: a virtual clock, a virtual network with a seeded fault plan, and any
 * number of runtimes (hosts) on it, all driven from the caller's thread. Time jumps from one
 * event to the next, so an hour of platform time may take a second. Same seed, same program:
 * same trace ({@link #trace()}).
 *
 * <pre>{@code
 * try (Simulation sim = new Simulation(42, FaultPlan.lossy(0.2, 0.1, 0.1, 0.02))) {
 *     AgentRuntime host = sim.newRuntime("h1");
 *     host.startAgent("alice", new Alice());
 *     sim.runUntil(() -> alice.done, 10_000);
 * }
 * }</pre>
 */
public final class Simulation implements AutoCloseable {
    private final long seed;
    private final ManualClock clock = new ManualClock();
    private final SplittableRandom random;
    private final VirtualNetwork network;
    private final TraceRecorder trace = new TraceRecorder();
    private final List<AgentRuntime> runtimes = new ArrayList<>();
    private String platformName = "sim";
    /** Runtimes paused (no loop turn) until when, on the virtual clock. */
    private final java.util.Map<AgentRuntime, Long> pausedUntil = new java.util.IdentityHashMap<>();
    /** Runtimes whose every loop turn with work costs this much virtual time (a slow or starved process). */
    private final java.util.Map<AgentRuntime, Long> turnCostNs = new java.util.IdentityHashMap<>();

    public Simulation(long seed, FaultPlan plan) {
        this.seed = seed;
        this.random = new SplittableRandom(seed);
        this.network = new VirtualNetwork(random.split(), plan, clock);
    }

    public long seed() {
        return seed;
    }

    public ManualClock clock() {
        return clock;
    }

    public VirtualNetwork network() {
        return network;
    }

    public TraceRecorder trace() {
        return trace;
    }

    /** The platform name given to runtimes created from now on. */
    public Simulation platformName(String name) {
        this.platformName = name;
        return this;
    }

    /** A runtime on a virtual host, with the default stack. */
    public AgentRuntime newRuntime(String host) {
        return newRuntime(host, null);
    }

    /** A runtime on a virtual host, with the given stack factory (top first), or the default if null. */
    public AgentRuntime newRuntime(String host, Supplier<List<Layer>> stack) {
        return newRuntime(host, stack, b -> b);
    }

    /** ... with more settings of the runtime (its mailboxes' capacity, say). */
    public AgentRuntime newRuntime(String host, Supplier<List<Layer>> stack, java.util.function.UnaryOperator<AgentRuntime.Builder> more) {
        AgentRuntime.Builder b = AgentRuntime.builder().clock(clock).network(network).host(host)
                .platformName(platformName).random(random.split()).tracer(trace);
        if (stack != null) {
            b.stack(stack);
        }
        AgentRuntime rt = more.apply(b).build();
        runtimes.add(rt);
        return rt;
    }

    /** Crashes a host: its agents die without takeDown, its ports close. */
    public void crash(AgentRuntime rt) {
        rt.crash();
        runtimes.remove(rt);
    }

    /**
     * One step: every runtime does a work cycle; if none had work, the clock jumps to the next
     * event (a delivery or a timer).
     *
     * @param limitNs do not move the clock past this time
     * @return false if nothing is left to do before the limit
     */
    public boolean step(long limitNs) {
        int work = 0;
        long now0 = clock.nanoTime();
        for (int i = 0; i < runtimes.size(); i++) {
            AgentRuntime rt = runtimes.get(i);
            Long until = pausedUntil.get(rt);
            if (until != null) {
                if (until > now0) {
                    continue;
                }
                pausedUntil.remove(rt);
            }
            int w = rt.doWork();
            work += w;
            Long cost = turnCostNs.get(rt);
            if (w > 0 && cost != null) {
                hold(rt, now0 + cost);
            }
        }
        if (work > 0) {
            return true;
        }
        long next = network.nextEventNs();
        for (AgentRuntime rt : runtimes) {
            Long until = pausedUntil.get(rt);
            next = Math.min(next, until != null ? Math.max(until, rt.nextDeadlineNs()) : rt.nextDeadlineNs());
        }
        long now = clock.nanoTime();
        if (next == Long.MAX_VALUE || next > limitNs) {
            if (limitNs != Long.MAX_VALUE && limitNs > now) {
                clock.setNanoTime(limitNs);
            }
            return false;
        }
        if (next > now) {
            clock.setNanoTime(next);
        }
        return true;
    }

    /**
     * Pauses a runtime, as a stopped or starved process is (SIGSTOP, a long GC, a machine
     * swapping): for {@code ms} its loop turns no more, its timers are late, what arrives for its
     * agents waits in their sockets, and its ports stay held; the clock runs on for everyone.
     */
    public void pause(AgentRuntime rt, long ms) {
        hold(rt, clock.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ms));
    }

    /**
     * Makes a runtime slow: each turn of its loop that does work then holds it for {@code turnMs}
     * (a process given a fraction of a core); 0 makes it normal again.
     */
    public void slow(AgentRuntime rt, double turnMs) {
        if (turnMs <= 0) {
            turnCostNs.remove(rt);
        } else {
            turnCostNs.put(rt, (long) (turnMs * 1_000_000L));
        }
    }

    private void hold(AgentRuntime rt, long untilNs) {
        pausedUntil.merge(rt, untilNs, Math::max);
        network.holdUntil(rt.boundAddresses(), untilNs);
    }

    /** Runs for the given virtual milliseconds. */
    public void runFor(long ms) {
        long end = clock.nanoTime() + TimeUnit.MILLISECONDS.toNanos(ms);
        while (clock.nanoTime() < end) {
            if (!step(end)) {
                break;
            }
        }
    }

    /**
     * Runs until the condition holds (checked after every step) or {@code maxMs} of virtual time
     * pass.
     *
     * @return true if the condition held
     */
    public boolean runUntil(BooleanSupplier condition, long maxMs) {
        long end = clock.nanoTime() + TimeUnit.MILLISECONDS.toNanos(maxMs);
        while (!condition.getAsBoolean()) {
            if (clock.nanoTime() >= end || !step(end)) {
                return condition.getAsBoolean();
            }
        }
        return true;
    }

    /** Runs until nothing is left to do: no datagram in flight, no timer, no runnable agent. */
    public void runUntilQuiet(long maxMs) {
        long end = clock.nanoTime() + TimeUnit.MILLISECONDS.toNanos(maxMs);
        while (clock.nanoTime() < end && step(end)) {
            // keep going
        }
    }

    @Override
    public void close() {
        for (AgentRuntime rt : runtimes) {
            rt.close();
        }
        runtimes.clear();
    }
}
