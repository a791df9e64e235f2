package jade.core.behaviours;

import jade.core.Agent;

/** A composite that runs one child at a time (sequential, FSM). */
public abstract class SerialBehaviour extends CompositeBehaviour {
    private static final long serialVersionUID = 1L;

    protected SerialBehaviour() {
    }

    protected SerialBehaviour(Agent a) {
        super(a);
    }
}
