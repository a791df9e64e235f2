package io.concord.core.agent;

/** A behaviour whose {@link #action()} runs once. */
public abstract class OneShotBehaviour extends Behaviour {
    protected OneShotBehaviour() {
    }

    protected OneShotBehaviour(Agent agent) {
        super(agent);
    }

    @Override
    public final boolean done() {
        return true;
    }
}
