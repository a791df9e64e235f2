package io.concord.bench.jmh;

import io.concord.bench.child.Children;
import io.concord.bench.jade.JadePlatform;
import io.concord.bench.support.Rounds;
import io.concord.core.agent.AgentRuntime;
import jade.wrapper.AgentController;

/**
 * What every round-based benchmark shares: the platform under test (a Concord runtime, or a JADE
 * main container), the child processes if any, and the way a batch of rounds is started and
 * awaited. A benchmark sets the starter of its first agent, then runs batches.
 */
public final class RoundDriver implements AutoCloseable {
    public final Rounds rounds = new Rounds();
    public final Children children = new Children();
    public AgentRuntime concord;
    public Runnable concordStart;
    public JadePlatform jade;
    public AgentController jadeStarter;

    /** Runs one batch of rounds from the benchmark thread and waits for it. */
    public void runBatch(int count) throws Exception {
        rounds.arm(count);
        if (jade != null) {
            jadeStarter.putO2AObject("go", false);
        } else {
            concord.execute(concordStart);
        }
        rounds.await();
    }

    @Override
    public void close() {
        if (concord != null) {
            concord.close();
        }
        if (jade != null) {
            jade.close();
        }
        children.close();
    }
}
