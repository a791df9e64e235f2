package io.concord.core.agent;

import java.util.Collection;

/**
 * A behaviour made of children. It is runnable while one of its active children is; a message for
 * the agent restarts its blocked children; a child that is restarted restarts its parents.
 */
public abstract class CompositeBehaviour extends Behaviour {
    protected CompositeBehaviour() {
    }

    protected CompositeBehaviour(Agent agent) {
        super(agent);
    }

    /** The children that are scheduled now. */
    protected abstract Collection<Behaviour> activeChildren();

    /** All children, for attaching and resetting. */
    protected abstract Collection<Behaviour> allChildren();

    void adopt(Behaviour child) {
        child.parent = this;
        if (myAgent != null) {
            child.attach(myAgent);
        }
    }

    @Override
    void attach(Agent agent) {
        super.attach(agent);
        for (Behaviour c : allChildren()) {
            c.attach(agent);
        }
    }

    @Override
    void restartOnMessage() {
        boolean any = false;
        for (Behaviour c : activeChildren()) {
            if (!c.isRunnable()) {
                c.restartOnMessage();
            }
            any |= c.isRunnable();
        }
        if (!isRunnable() && (any || activeChildren().isEmpty())) {
            restart();
        }
    }

    @Override
    void detach() {
        super.detach();
        for (Behaviour c : allChildren()) {
            c.detach();
        }
    }

    /** Runs one step of a child; returns true if it finished (its {@code onEnd} has been called). */
    static boolean stepChild(Behaviour child) {
        child.step();
        return child.done();
    }

    /** Blocks this composite when none of its active children can run. */
    protected void blockIfNoChildRunnable() {
        for (Behaviour c : activeChildren()) {
            if (c.isRunnable()) {
                return;
            }
        }
        if (!activeChildren().isEmpty()) {
            block();
        }
    }

    @Override
    public void reset() {
        super.reset();
        for (Behaviour c : allChildren()) {
            c.reset();
        }
    }
}
