package jade.domain.JADEAgentManagement;

/** The AMS action that shuts the platform down: every container of this JVM is killed, then the platform stops. */
public class ShutdownPlatform implements jade.content.AgentAction {
    private static final long serialVersionUID = 1L;

    public ShutdownPlatform() {
    }
}
