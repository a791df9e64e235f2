package io.concord.core.agent;

/** A behaviour that never finishes; it usually blocks when it has nothing to do. */
public abstract class CyclicBehaviour extends Behaviour {
    protected CyclicBehaviour() {
    }

    protected CyclicBehaviour(Agent agent) {
        super(agent);
    }

    @Override
    public final boolean done() {
        return false;
    }
}
