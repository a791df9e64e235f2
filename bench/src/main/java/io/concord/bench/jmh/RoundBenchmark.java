package io.concord.bench.jmh;

import io.concord.bench.support.Rounds;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.TearDown;

/**
 * What the round-based benchmarks share: the driver of the platform under test and its rounds,
 * closed after each trial. A subclass starts its agents in a {@code @Setup} and measures
 * {@link RoundDriver#runBatch} in a {@code @Benchmark} of its own, whose operations per
 * invocation are its number of rounds.
 */
public abstract class RoundBenchmark {
    protected final RoundDriver driver = new RoundDriver();
    protected final Rounds rounds = driver.rounds;

    @TearDown(Level.Trial)
    public void stop() {
        driver.close();
    }
}
