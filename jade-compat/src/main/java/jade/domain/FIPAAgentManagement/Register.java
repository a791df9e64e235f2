package jade.domain.FIPAAgentManagement;

import jade.content.AgentAction;

/** FIPA's {@code register} action: its description is a {@link DFAgentDescription} (for a DF). */
public class Register implements AgentAction {
    private static final long serialVersionUID = 1L;
    /** The slot's name. */
    public static final String REGISTER_DESCRIPTION = "description";
    private Object description;

    /** An empty action. */
    public Register() {
    }

    /** Sets what to register. */
    public void setDescription(Object description) {
        this.description = description;
    }

    /** What to register. */
    public Object getDescription() {
        return description;
    }
}
