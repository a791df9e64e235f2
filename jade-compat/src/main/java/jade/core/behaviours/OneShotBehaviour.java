package jade.core.behaviours;

import jade.core.Agent;

/** A behaviour whose {@link #action()} runs once. */
public abstract class OneShotBehaviour extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;

    public OneShotBehaviour() {
    }

    public OneShotBehaviour(Agent a) {
        super(a);
    }

    /** Always true: one action and the behaviour is over. */
    @Override
    public final boolean done() {
        return true;
    }
}
