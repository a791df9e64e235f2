package jade.core.behaviours;

import io.concord.jadecompat.internal.Engine;
import jade.core.Agent;

/** Calls {@link #onTick()} every period, until {@link #stop()}. */
public abstract class TickerBehaviour extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;

    private long period;
    private long wakeupTime;
    private boolean finished;
    private int tickCount;
    private boolean fixedPeriod;

    /** A ticker with a period in milliseconds (more than 0). */
    public TickerBehaviour(Agent a, long period) {
        super(a);
        if (period <= 0) {
            throw new IllegalArgumentException("Period must be greater than 0");
        }
        this.period = period;
    }

    /** The first tick is one period after the start. */
    @Override
    public void onStart() {
        wakeupTime = Engine.nowMs() + period;
    }

    @Override
    public final void action() {
        if (finished) {
            return;
        }
        long now = Engine.nowMs();
        long left = wakeupTime - now;
        if (left <= 0) {
            tickCount++;
            onTick();
            // As JADE's: the next tick a period after this one ended (a tick longer than the period
            // does not make the next one due at once and starve the agent's other behaviours).
            wakeupTime = fixedPeriod ? wakeupTime + period : Engine.nowMs() + period;
            left = wakeupTime - Engine.nowMs();
            if (left <= 0) {
                left = 1;
            }
        }
        if (!finished) {
            block(left);
        }
    }

    /** The periodic work. */
    protected abstract void onTick();

    @Override
    public final boolean done() {
        return finished;
    }

    /** Ticks at fixed times (each a period after the previous due time) rather than a period after each tick. */
    public void setFixedPeriod(boolean fixed) {
        fixedPeriod = fixed;
    }

    /** Starts again with a new period. */
    public void reset(long newPeriod) {
        this.period = newPeriod;
        reset();
    }

    @Override
    public void reset() {
        super.reset();
        finished = false;
        tickCount = 0;
    }

    /** Ends the ticker (after the current tick). */
    public void stop() {
        finished = true;
        restart();
    }

    /** Ticks done since the start or the last reset. */
    public final int getTickCount() {
        return tickCount;
    }

    protected long getPeriod() {
        return period;
    }
}
