package jade.domain.FIPAAgentManagement;

import jade.content.AgentAction;

/** FIPA's {@code get-description} action (of a platform); it has no slot. */
public class GetDescription implements AgentAction {
    private static final long serialVersionUID = 1L;
}
