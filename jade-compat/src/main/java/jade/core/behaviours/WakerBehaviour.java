package jade.core.behaviours;

import io.concord.jadecompat.internal.Engine;
import jade.core.Agent;

import java.util.Date;

/** Waits for a time, then calls {@link #handleElapsedTimeout()} (by default {@link #onWake()}) once. */
public abstract class WakerBehaviour extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;

    private long timeout = -1;
    private long wakeupTime;
    private boolean finished;

    /** Wakes at a date. */
    public WakerBehaviour(Agent a, Date wakeupDate) {
        super(a);
        this.wakeupTime = wakeupDate.getTime();
    }

    /** Wakes {@code timeout} milliseconds after it starts. */
    public WakerBehaviour(Agent a, long timeout) {
        super(a);
        this.timeout = timeout;
    }

    @Override
    public void onStart() {
        if (timeout >= 0) {
            wakeupTime = Engine.nowMs() + timeout;
        }
    }

    @Override
    public final void action() {
        if (finished) {
            return;
        }
        long left = wakeupTime - Engine.nowMs();
        if (left <= 0) {
            finished = true;
            handleElapsedTimeout();
        } else {
            block(left);
        }
    }

    /** Called when the time has come; calls {@link #onWake()}. */
    protected void handleElapsedTimeout() {
        onWake();
    }

    /** The work to do when the time has come. */
    protected void onWake() {
        // The documented default: nothing. Subclasses override this or handleElapsedTimeout.
    }

    /** Starts again, waking at a date. */
    public void reset(Date wakeupDate) {
        reset();
        timeout = -1;
        wakeupTime = wakeupDate.getTime();
    }

    /** Starts again, waking {@code timeout} ms after the restart. */
    public void reset(long newTimeout) {
        reset();
        timeout = newTimeout;
    }

    @Override
    public void reset() {
        super.reset();
        finished = false;
    }

    /** Ends the behaviour without waking. */
    public void stop() {
        finished = true;
        restart();
    }

    @Override
    public final boolean done() {
        return finished;
    }

    /** The time it wakes at, in epoch milliseconds. */
    public final long getWakeupTime() {
        return wakeupTime;
    }
}
