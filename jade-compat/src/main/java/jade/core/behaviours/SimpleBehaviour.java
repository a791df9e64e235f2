package jade.core.behaviours;

import jade.core.Agent;

/** A behaviour that is not made of others. */
public abstract class SimpleBehaviour extends Behaviour {
    private static final long serialVersionUID = 1L;

    public SimpleBehaviour() {
    }

    public SimpleBehaviour(Agent a) {
        super(a);
    }

    /** Starts the behaviour over. */
    @Override
    public void reset() {
        super.reset();
    }
}
