package io.concord.layers.platform;

/**
 * The timing of the container layer. The maintenance period grows with the number of agents, as
 * in the dissertation: {@code period = basePeriodMs + perAgentMicros * agents / 1000}; an agent (or
 * the container) not heard for {@code timeoutPeriods} periods is taken for dead.
 *
 * @param discoveryTimeoutMs how long a newcomer waits for its potential peers to answer
 * @param discoveryAttempts  how often it asks those that have not answered
 * @param electionTimeoutMs  how long an agent that excluded itself waits for the winner to announce
 * @param basePeriodMs       the maintenance period with no agents
 * @param perAgentMicros     what each agent adds to the period
 * @param timeoutPeriods     periods of silence after which an agent or the container is dead
 * @param joinRetryMs        how long a newcomer waits for the container to confirm its join
 * @param joinAttempts       join attempts before it asks a random known agent for the last LAL
 * @param pushDelayMs        how long the container gathers changes before distributing the LAL
 * @param maxContentBytes    the most LAL text one message carries
 */
public record PlatformConfig(long discoveryTimeoutMs, int discoveryAttempts, long electionTimeoutMs,
                             long basePeriodMs, long perAgentMicros, int timeoutPeriods, long joinRetryMs,
                             int joinAttempts, long pushDelayMs, int maxContentBytes) {

    public PlatformConfig {
        if (discoveryTimeoutMs <= 0 || electionTimeoutMs <= 0 || basePeriodMs <= 0 || joinRetryMs <= 0
                || pushDelayMs < 0 || perAgentMicros < 0) {
            throw new IllegalArgumentException("the container layer's times must be positive: " + this);
        }
        if (discoveryAttempts < 1 || joinAttempts < 1 || timeoutPeriods < 2) {
            throw new IllegalArgumentException("discoveryAttempts and joinAttempts must be >= 1 and timeoutPeriods >= 2: "
                    + this);
        }
        if (maxContentBytes < 512) {
            throw new IllegalArgumentException("maxContentBytes must be >= 512, got " + maxContentBytes);
        }
    }

    /**
     * The defaults: discovery answers awaited 25, 50, 100 ms (3 attempts), 40 ms + 0.5 ms per agent maintenance period, dead
     * after 3 silent periods (at least 250 ms), joins retried after 60, 120, 240 ms (4 attempts), LAL pushed 5 ms after a
     * change, 3,000 bytes of LAL a message (well within the 8 KiB UDP frame of the safety stack).
     */
    public static PlatformConfig defaults() {
        return new PlatformConfig(25, 3, 60, 40, 500, 3, 60, 4, 5, 3_000);
    }

    /** The maintenance period for a number of agents. */
    public long periodMs(int agents) {
        return basePeriodMs + perAgentMicros * agents / 1000;
    }

    /**
     * The silence after which an agent or the container counts as dead: {@code timeoutPeriods}
     * periods, and never less than {@link #MIN_TIMEOUT_MS}, so that a loop starved for a moment on a
     * busy machine (a JVM starting beside it) is not taken for dead.
     */
    public long timeoutMs(int agents) {
        return Math.max(MIN_TIMEOUT_MS, periodMs(agents) * timeoutPeriods);
    }

    /**
     * The longest silence of an agent whose process still holds its port on the same host (a
     * process paused or starved, not crashed) before it is taken for dead all the same: a slow
     * machine is not a dead one, but one that answers nothing for this long is of no use.
     */
    public static final long SLOW_BOUND_MS = 30_000;

    /** The shortest silence taken for death. */
    public static final long MIN_TIMEOUT_MS = 250;
}
