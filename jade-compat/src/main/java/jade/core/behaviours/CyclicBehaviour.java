package jade.core.behaviours;

import jade.core.Agent;

/** A behaviour that never ends; its {@link #action()} usually blocks when there is nothing to do. */
public abstract class CyclicBehaviour extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;

    public CyclicBehaviour() {
    }

    public CyclicBehaviour(Agent a) {
        super(a);
    }

    /** Always false. */
    @Override
    public final boolean done() {
        return false;
    }
}
