package io.concord.bench.support;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * Drives a batch of rounds from the benchmark thread: the platform's first agent runs them back to
 * back and counts down when the batch is done, so the hand-off between the benchmark thread and
 * the platform is paid once per batch, not once per round.
 */
public final class Rounds {
    private volatile CountDownLatch done;
    private volatile int remaining;
    private volatile String failure;
    private volatile CountDownLatch ready = new CountDownLatch(0);

    /** Expects that many agents to report ready (JADE runs setup() after start() returns). */
    public void expectReady(int agents) {
        ready = new CountDownLatch(agents);
    }

    /** Called by an agent at the end of its setup. */
    public void agentReady() {
        ready.countDown();
    }

    /** Waits until every expected agent is ready. */
    public void awaitReady() throws InterruptedException {
        if (!ready.await(60, TimeUnit.SECONDS)) {
            throw new IllegalStateException(ready.getCount() + " agents did not finish their setup in 60 s");
        }
    }

    /** Called by the benchmark thread: arms a batch. */
    public void arm(int rounds) {
        remaining = rounds;
        done = new CountDownLatch(1);
    }

    /** Called by the platform after each round: true if another round should start. */
    public boolean roundDone() {
        if (--remaining > 0) {
            return true;
        }
        done.countDown();
        return false;
    }

    /** Called by the platform if a round went wrong (content changed, say). */
    public void fail(String why) {
        failure = why;
        done.countDown();
    }

    /** Called by the benchmark thread: waits for the batch. */
    public void await() throws InterruptedException {
        if (!done.await(60, TimeUnit.SECONDS)) {
            throw new IllegalStateException("a batch of rounds did not finish in 60 s; " + remaining + " left");
        }
        if (failure != null) {
            throw new IllegalStateException(failure);
        }
    }
}
