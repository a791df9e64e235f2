package jade.core;

/** What a platform service gives an agent through {@code Agent.getHelper}. */
public interface ServiceHelper {
    /** Binds the helper to the agent that asked for it. */
    void init(Agent a);
}
