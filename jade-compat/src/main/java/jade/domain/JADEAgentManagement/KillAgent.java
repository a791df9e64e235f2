package jade.domain.JADEAgentManagement;

import jade.core.AID;

/** The AMS action that kills an agent of the platform. */
public class KillAgent implements jade.content.AgentAction {
    private static final long serialVersionUID = 1L;
    private AID agent;
    private String password;

    public KillAgent() {
    }

    public void setAgent(AID a) {
        agent = a;
    }

    public AID getAgent() {
        return agent;
    }

    public void setPassword(String p) {
        password = p;
    }

    public String getPassword() {
        return password;
    }
}
