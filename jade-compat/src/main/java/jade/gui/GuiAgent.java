package jade.gui;

import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;

/**
 * JADE's agent with a user interface: the interface's threads call {@link #postGuiEvent}, and
 * {@link #onGuiEvent} runs on the agent's own thread, one event at a time, in the order posted.
 * Nothing here needs a display: an agent whose own code opens no window runs headless.
 */
public abstract class GuiAgent extends Agent {
    private static final long serialVersionUID = 1L;

    public GuiAgent() {
        super();
    }

    /** Hands an event to the agent (from any thread); {@link #onGuiEvent} handles it on the agent's thread. */
    public void postGuiEvent(GuiEvent e) {
        addBehaviour(new OneShotBehaviour(this) {
            private static final long serialVersionUID = 1L;

            @Override
            public void action() {
                onGuiEvent(e);
            }
        });
    }

    /** Handles an event posted by the user interface. */
    protected abstract void onGuiEvent(GuiEvent ev);
}
