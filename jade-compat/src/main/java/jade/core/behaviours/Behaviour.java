package jade.core.behaviours;

import jade.core.Agent;

/**
 * JADE's behaviour: a task of an agent, run one {@link #action()} at a time by the agent's
 * scheduler (round robin, on the agent's own thread), until {@link #done()}. {@link #block()}
 * takes it out of the schedule until a message arrives for the agent, {@link #restart()} is
 * called, or (with {@link #block(long)}) the time passes.
 */
public abstract class Behaviour implements jade.util.leap.Serializable {
    private static final long serialVersionUID = 1L;

    public static final String STATE_READY = "READY";
    public static final String STATE_BLOCKED = "BLOCKED";
    public static final String STATE_RUNNING = "RUNNING";

    protected static final int NOTIFY_UP = 0;
    protected static final int NOTIFY_DOWN = 1;


    /** The agent this behaviour belongs to. */
    protected Agent myAgent;
    /** Set on a behaviour that runs on a thread of its own: wakes that thread when the behaviour is restarted. */
    transient Runnable wakeUp;
    /** The composite behaviour this one is a child of, or null. */
    protected CompositeBehaviour parent;

    private String myName;
    private volatile boolean runnableState = true;
    private boolean startFlag = true;
    private volatile long restartCounter;
    private volatile String executionState = STATE_READY;
    private DataStore dataStore;

    /**
     * A behaviour named, as JADE names it by default, after its class's name without the package
     * and enclosing classes ({@code Outer$Inner}: {@code Inner}; an anonymous class {@code Outer$1}: {@code 1}).
     */
    public Behaviour() {
        String className = getClass().getName();
        myName = className.substring(Math.max(className.lastIndexOf('.'), className.lastIndexOf('$')) + 1);
    }

    public Behaviour(Agent a) {
        this();
        myAgent = a;
    }

    public final void setBehaviourName(String name) {
        myName = name;
    }

    public final String getBehaviourName() {
        return myName;
    }

    /** One step of the task. */
    public abstract void action();

    /** True once the task is over; asked after each {@link #action()}. */
    public abstract boolean done();

    /** Called once, after the last action; its value is the behaviour's exit value (for FSMs). */
    public int onEnd() {
        return 0;
    }

    /** Called once, before the first action. */
    public void onStart() {
    }

    /** Runs one step: {@link #onStart()} first if the behaviour has not started. */
    public final void actionWrapper() {
        if (startFlag) {
            onStart();
            startFlag = false;
        }
        if (STATE_READY.equals(executionState)) {
            executionState = STATE_RUNNING;
        }
        action();
        if (STATE_RUNNING.equals(executionState)) {
            executionState = STATE_READY;
        }
    }

    public final void setExecutionState(String s) {
        executionState = s;
    }

    public final String getExecutionState() {
        return executionState;
    }

    /** Makes the behaviour start again from the beginning ({@link #onStart()} runs again). */
    public void reset() {
        startFlag = true;
        restart();
    }

    /** The outermost behaviour this one is part of. */
    public Behaviour root() {
        return parent == null ? this : parent.root();
    }

    protected CompositeBehaviour getParent() {
        return parent;
    }

    /** True if the scheduler may run it now (not blocked). */
    public boolean isRunnable() {
        return runnableState;
    }

    /** How many times the behaviour was restarted. */
    public final long getRestartCounter() {
        return restartCounter;
    }

    /**
     * Takes the behaviour out of the schedule (after the current action) until a message arrives
     * for the agent or {@link #restart()} is called.
     */
    public void block() {
        runnableState = false;
        executionState = STATE_BLOCKED;
        handleBlockEvent();
    }

    /** As {@link #block()}, and the behaviour is restarted after {@code millis} at the latest. */
    public void block(long millis) {
        block();
        if (millis > 0 && myAgent != null) {
            myAgent.restartLater(this, millis);
        }
    }

    /** Puts the behaviour back into the schedule, and its parents with it. */
    public void restart() {
        Behaviour top = root();
        if (top.wakeUp != null) {
            // A threaded behaviour (ThreadedBehaviourFactory): its own thread looks again.
            top.wakeUp.run();
        }
        if (myAgent != null) {
            myAgent.removeTimer(this);
        }
        markRunnable();
        for (CompositeBehaviour p = parent; p != null; p = p.parent) {
            p.markRunnable();
        }
        if (myAgent != null) {
            myAgent.notifyRestarted(this);
        }
    }

    /**
     * What a restart does to this behaviour itself (a message arrived for the agent): it becomes
     * runnable again; a composite restarts its children too.
     */
    public void handleRestartEvent() {
        if (!runnableState && myAgent != null) {
            myAgent.removeTimer(this);
        }
        markRunnable();
    }

    /** What blocking does besides marking the behaviour blocked; nothing by default. */
    protected void handleBlockEvent() {
        // A composite's runnability follows its children's (see isRunnable there): nothing to pass up.
        executionState = STATE_BLOCKED;
    }

    final void markRunnable() {
        if (!runnableState) {
            restartCounter++;
        }
        runnableState = true;
        if (STATE_BLOCKED.equals(executionState)) {
            executionState = STATE_READY;
        }
    }

    public void setAgent(Agent a) {
        myAgent = a;
    }

    public Agent getAgent() {
        return myAgent;
    }

    /** The behaviour's data store, made on first use. */
    public DataStore getDataStore() {
        if (dataStore == null) {
            dataStore = new DataStore();
        }
        return dataStore;
    }

    public void setDataStore(DataStore ds) {
        dataStore = ds;
    }

    final void setParentInternal(CompositeBehaviour p) {
        parent = p;
    }
}
