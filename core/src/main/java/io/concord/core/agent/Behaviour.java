package io.concord.core.agent;

/**
 * A task of an agent, with JADE's semantics. The agent runs its behaviours cooperatively: one
 * {@link #action()} step at a time, round-robin, never two at once. A behaviour that has nothing
 * to do calls {@link #block()} (or {@link #block(long)}) and is not scheduled again until a
 * message arrives for its agent, its timeout passes, or someone calls {@link #restart()}.
 *
 * <p>{@code action()} must return quickly: it runs on the loop that serves every agent of the
 * JVM. Work that must block (I/O, {@link Agent#blockingReceive}) belongs in a behaviour wrapped by
 * {@link ThreadedBehaviourFactory}.
 */
public abstract class Behaviour {
    /** The agent this behaviour belongs to (JADE's name for it). */
    protected Agent myAgent;
    Behaviour parent;
    private boolean runnable = true;
    private boolean blockRequested;
    private long wakeTimer = -1;
    private boolean started;
    ThreadedBehaviourFactory.Runner runner;

    protected Behaviour() {
    }

    protected Behaviour(Agent agent) {
        this.myAgent = agent;
    }

    /** One step of work. */
    public abstract void action();

    /** True when the behaviour has finished; checked after every step. */
    public abstract boolean done();

    /** Called once before the first step (and again after {@link #reset()}). */
    public void onStart() {
    }

    /**
     * Called once when the behaviour is done; the value is its exit code (FSM transitions use it).
     */
    public int onEnd() {
        return 0;
    }

    /** The agent. */
    public Agent getAgent() {
        return myAgent;
    }

    /** The composite behaviour this one is a child of, or {@code null}. */
    public Behaviour getParent() {
        return parent;
    }

    /**
     * Stops scheduling this behaviour after the current step, until a message arrives for the
     * agent or {@link #restart()} is called.
     */
    public void block() {
        blockRequested = true;
    }

    /**
     * Like {@link #block()}, but also restarts the behaviour after {@code timeoutMs} of the
     * platform's clock if nothing else did earlier.
     */
    public void block(long timeoutMs) {
        blockRequested = true;
        if (runner != null) {
            runner.wakeAfterMs(timeoutMs);
            return;
        }
        cancelWake();
        long deadline = myAgent.runtime().nowNs() + Math.max(0, timeoutMs) * 1_000_000L;
        wakeTimer = myAgent.runtime().schedule(deadline, this::wake);
    }

    private void wake() {
        wakeTimer = -1;
        restart();
    }

    private void cancelWake() {
        if (wakeTimer >= 0) {
            myAgent.runtime().cancel(wakeTimer);
            wakeTimer = -1;
        }
    }

    /** Makes a blocked behaviour runnable again (and its parents). */
    public void restart() {
        blockRequested = false;
        if (runner != null) {
            runnable = true;
            runner.signal();
            return;
        }
        if (myAgent != null && wakeTimer >= 0) {
            cancelWake();
        }
        if (!runnable) {
            runnable = true;
            if (parent != null) {
                parent.childRestarted();
            } else if (myAgent != null) {
                myAgent.behaviourRestarted();
            }
        }
    }

    /** True unless the behaviour is blocked. */
    public boolean isRunnable() {
        return runnable;
    }

    /** Brings the behaviour back to its initial state, so that it runs again from the start. */
    public void reset() {
        started = false;
        blockRequested = false;
        if (myAgent != null) {
            cancelWake();
        }
        runnable = true;
    }

    /** A composite's child became runnable: so does the composite. */
    void childRestarted() {
        restart();
    }

    /** A message arrived for the agent: JADE restarts every blocked behaviour. */
    void restartOnMessage() {
        if (!runnable) {
            restart();
        }
    }

    /** Sets the agent of this behaviour (and of its children, for composites). */
    void attach(Agent agent) {
        if (myAgent == null) {
            myAgent = agent;
        }
    }

    /** Runs one step: {@code onStart} first time, then {@code action}, then applies a block request. */
    final void step() {
        blockRequested = false;
        if (!started) {
            started = true;
            onStart();
        }
        action();
        if (blockRequested) {
            blockRequested = false;
            runnable = false;
        }
    }

    /** Cancels pending timers when the behaviour is removed. */
    void detach() {
        if (myAgent != null) {
            cancelWake();
        }
    }

    void markRunnable() {
        runnable = true;
    }
}
