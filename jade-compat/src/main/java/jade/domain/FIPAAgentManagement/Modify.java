package jade.domain.FIPAAgentManagement;

import jade.content.AgentAction;

/** FIPA's {@code modify} action: its description is a {@link DFAgentDescription} (for a DF). */
public class Modify implements AgentAction {
    private static final long serialVersionUID = 1L;
    /** The slot's name. */
    public static final String MODIFY_DESCRIPTION = "description";
    private Object description;

    /** An empty action. */
    public Modify() {
    }

    /** Sets what to modify. */
    public void setDescription(Object description) {
        this.description = description;
    }

    /** What to modify. */
    public Object getDescription() {
        return description;
    }
}
