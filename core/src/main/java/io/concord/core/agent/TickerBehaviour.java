package io.concord.core.agent;

/**
 * Calls {@link #onTick()} every {@code periodMs} of the platform's clock (the next tick counted
 * from the end of the last one, as JADE does), until {@link #stop()}.
 */
public abstract class TickerBehaviour extends Behaviour {
    private final long periodMs;
    private long wakeupNs;
    private int tickCount;
    private boolean finished;

    protected TickerBehaviour(Agent agent, long periodMs) {
        super(agent);
        if (periodMs <= 0) {
            throw new IllegalArgumentException("a ticker needs a period > 0 ms, got " + periodMs);
        }
        this.periodMs = periodMs;
    }

    /** The work done on each tick. */
    protected abstract void onTick();

    @Override
    public void onStart() {
        wakeupNs = myAgent.runtime().nowNs() + periodMs * 1_000_000L;
    }

    @Override
    public final void action() {
        if (finished) {
            return;
        }
        long now = myAgent.runtime().nowNs();
        if (now >= wakeupNs) {
            tickCount++;
            onTick();
            wakeupNs = myAgent.runtime().nowNs() + periodMs * 1_000_000L;
            now = myAgent.runtime().nowNs();
        }
        if (!finished) {
            block(Math.max(0, (wakeupNs - now + 999_999) / 1_000_000L));
        }
    }

    @Override
    public final boolean done() {
        return finished;
    }

    /** Ticks so far. */
    public int getTickCount() {
        return tickCount;
    }

    public long getPeriod() {
        return periodMs;
    }

    /** No more ticks; the behaviour ends after its current step. */
    public void stop() {
        finished = true;
        restart();
    }

    @Override
    public void reset() {
        super.reset();
        tickCount = 0;
        finished = false;
    }
}
