package io.concord.core.agent;

/** Calls {@link #onWake()} once, {@code timeoutMs} of the platform's clock after it starts. */
public abstract class WakerBehaviour extends Behaviour {
    private final long timeoutMs;
    private long wakeupNs;
    private boolean finished;

    protected WakerBehaviour(Agent agent, long timeoutMs) {
        super(agent);
        if (timeoutMs < 0) {
            throw new IllegalArgumentException("a waker needs a timeout >= 0 ms, got " + timeoutMs);
        }
        this.timeoutMs = timeoutMs;
    }

    /** The work done on waking. */
    protected abstract void onWake();

    @Override
    public void onStart() {
        wakeupNs = myAgent.runtime().nowNs() + timeoutMs * 1_000_000L;
    }

    @Override
    public final void action() {
        if (finished) {
            return;
        }
        long now = myAgent.runtime().nowNs();
        if (now >= wakeupNs) {
            finished = true;
            onWake();
        } else {
            block((wakeupNs - now + 999_999) / 1_000_000L);
        }
    }

    @Override
    public final boolean done() {
        return finished;
    }

    /** Cancels the wake-up; the behaviour ends without calling {@link #onWake()}. */
    public void stop() {
        finished = true;
        restart();
    }

    @Override
    public void reset() {
        super.reset();
        finished = false;
    }
}
