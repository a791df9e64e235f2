package jade.domain.FIPAAgentManagement;

import jade.content.AgentAction;

/** FIPA's {@code deregister} action: its description is a {@link DFAgentDescription} (for a DF). */
public class Deregister implements AgentAction {
    private static final long serialVersionUID = 1L;

    private Object description;

    /** An empty action. */
    public Deregister() {
    }

    /** Sets what to deregister. */
    public void setDescription(Object description) {
        this.description = description;
    }

    /** What to deregister. */
    public Object getDescription() {
        return description;
    }
}
