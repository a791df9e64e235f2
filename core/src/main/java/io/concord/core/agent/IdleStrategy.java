package io.concord.core.agent;

import io.concord.core.time.Clock;

/**
 * How the event loop waits when a cycle found no work: awake for a while (spinning, then yielding
 * the CPU), then parked on the network until a datagram, a task or a timer. The awake budget adapts
 * between 0 and its configured length: waiting awake pays when work comes back within the window
 * (a quick reply, no kernel wake-up), and only wastes a CPU when it does not. Both outcomes are
 * counted and the budget halved or doubled. Only a task or a datagram counts as work that came
 * while awake: a timer was foreseen, and the park ends for it anyway. Yielding rather than
 * spinning lets other processes of a busy machine run meanwhile: with more agent processes than
 * cores, a spinning one holds a core that a peer needs to answer it.
 *
 * <p>A yield that lasts longer than {@link #CONTENDED_YIELD_NS} shows that the cores are
 * contended: the loop then parks at once, and waits awake no more until waiting awake pays again.
 *
 * <p>Loop thread only, but {@link #contendedYields()}.
 */
final class IdleStrategy {
    /**
     * A yield that lasts longer than this gave the CPU to a thread that used a whole time slice:
     * the machine's cores are busy with other work. An uncontended yield returns in about a
     * microsecond, and one that let a peer process of this machine answer (the one-process-per-agent
     * topology on 2 cores) in tens of microseconds; one behind a busy loop, after a millisecond or
     * more. 50 us took the peers' hand-offs for contention: books across processes went from 28
     * to 150 us on a quiet machine.
     */
    static final long CONTENDED_YIELD_NS = 500_000;

    private final Clock clock;
    private final int spinIterations;
    private final int maxBudget;
    /** Empty cycles since the last work. */
    private int idle;
    private int budget;
    private int wins;
    private int losses;
    /** How long a full wait awake lasts here. */
    private long windowNs;
    private long idleSinceNs;
    private volatile long contendedYields;

    IdleStrategy(Clock clock, int spinIterations, int yieldIterations) {
        this.clock = clock;
        this.spinIterations = spinIterations;
        this.maxBudget = spinIterations + yieldIterations;
        this.budget = maxBudget;
    }

    /** A cycle did work; {@code arrived}: a task or a datagram came (it counts for waiting awake). */
    void worked(boolean arrived) {
        if (idle > 0 && arrived) {
            wins++; // work came while waiting awake
        }
        idle = 0;
    }

    /**
     * A cycle found no work: waits awake once (a spin or a yield) and answers true, or answers
     * false when the loop is to park now.
     */
    boolean waitAwake() {
        if (idle == 0) {
            idleSinceNs = clock.nanoTime();
        }
        if (idle >= budget) {
            return false;
        }
        if (idle < spinIterations) {
            Thread.onSpinWait();
        } else {
            long y0 = clock.nanoTime();
            Thread.yield();
            if (clock.nanoTime() - y0 > CONTENDED_YIELD_NS) {
                // Another thread ran in this one's place: the cores are contended (more runnable
                // threads than cores). Waiting awake then only delays this loop: a yielding thread
                // is runnable, and a datagram that comes waits behind the others' time slices,
                // where a parked one is woken at once by the kernel. Park now, and wait awake no
                // more until waiting awake pays again.
                contendedYields++;
                budget = 0;
                wins = 0;
                losses = 0;
                return true;
            }
        }
        idle++;
        return true;
    }

    /** The loop parks now: returns the time it parked at, for {@link #woke}. */
    long parking() {
        if (budget == maxBudget && idle > 0) {
            windowNs = clock.nanoTime() - idleSinceNs;
        }
        return clock.nanoTime();
    }

    /**
     * The park that began at {@code parkedAtNs} ended. Woken sooner than a full wait awake would
     * have lasted: waiting awake would have caught it. (A timer cannot end a park that soon: the
     * park lasts at least one unit of the wait.)
     */
    void woke(long parkedAtNs) {
        if (clock.nanoTime() - parkedAtNs < Math.max(windowNs, 20_000)) {
            wins++;
        } else {
            losses++;
        }
        if (wins + losses >= 32) {
            budget = wins * 4 < wins + losses ? budget / 2 : Math.min(maxBudget, Math.max(1, budget * 2));
            wins = 0;
            losses = 0;
        }
        idle = 0;
    }

    /** Idle waits cut short because yielding found the cores contended. Any thread. */
    long contendedYields() {
        return contendedYields;
    }
}
