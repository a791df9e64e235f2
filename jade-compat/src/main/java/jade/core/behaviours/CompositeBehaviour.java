package jade.core.behaviours;

import jade.core.Agent;
import jade.util.leap.Collection;

/**
 * A behaviour made of children. Each {@link #action()} runs one step of the child
 * {@link #getCurrent()} names; subclasses say which comes first and next and when it ends. It
 * is runnable while the child it would run is.
 */
public abstract class CompositeBehaviour extends Behaviour {
    private static final long serialVersionUID = 1L;

    /** True if the last action ran a step of the current child. */
    protected boolean currentExecuted = true;
    private boolean starting = true;
    private boolean finished;

    protected CompositeBehaviour() {
    }

    protected CompositeBehaviour(Agent a) {
        super(a);
    }

    @Override
    public final void action() {
        if (starting) {
            scheduleFirst();
            starting = false;
        }
        Behaviour current = getCurrent();
        currentExecuted = false;
        if (current == null) {
            finished = checkTermination(false, 0) || getChildren().isEmpty();
            return;
        }
        if (!current.isRunnable()) {
            return;
        }
        current.actionWrapper();
        currentExecuted = true;
        boolean currentDone = current.done();
        int result = currentDone ? current.onEnd() : 0;
        finished = checkTermination(currentDone, result);
        if (!finished) {
            scheduleNext(currentDone, result);
        }
    }

    @Override
    public final boolean done() {
        return finished;
    }

    /** Picks the first child to run. */
    protected abstract void scheduleFirst();

    /** Picks the next child to run after the current one ran a step. */
    protected abstract void scheduleNext(boolean currentDone, int currentResult);

    /** True if the composite is over after the current child's step. */
    protected abstract boolean checkTermination(boolean currentDone, int currentResult);

    /** The child to run now, or null. */
    protected abstract Behaviour getCurrent();

    /** The children. */
    public abstract Collection getChildren();

    /** Runnable if not blocked itself and the child it would run is runnable. */
    @Override
    public boolean isRunnable() {
        if (!super.isRunnable()) {
            return false;
        }
        if (starting) {
            return true;
        }
        Behaviour c = getCurrent();
        return c == null || c.isRunnable();
    }

    /** A restart reaches every child. */
    @Override
    public void handleRestartEvent() {
        super.handleRestartEvent();
        for (Object o : getChildren().toArray()) {
            ((Behaviour) o).handleRestartEvent();
        }
    }

    @Override
    protected void handleBlockEvent() {
        super.handleBlockEvent();
    }

    /** Starts over: the children are reset too. */
    @Override
    public void reset() {
        resetChildren();
        starting = true;
        finished = false;
        super.reset();
    }

    protected void resetChildren() {
        for (Object o : getChildren().toArray()) {
            ((Behaviour) o).reset();
        }
    }

    /** Makes a behaviour a child of this one (its parent and, if it has none, its agent). */
    protected void registerAsChild(Behaviour b) {
        b.setParentInternal(this);
        if (myAgent != null) {
            b.setAgent(myAgent);
        }
    }

    /** The agent of this behaviour and of all its children. */
    @Override
    public void setAgent(Agent a) {
        super.setAgent(a);
        for (Object o : getChildren().toArray()) {
            ((Behaviour) o).setAgent(a);
        }
    }
}
