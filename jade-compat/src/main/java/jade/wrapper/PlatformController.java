package jade.wrapper;

/**
 * JADE's handle on a platform: the type JADE code often holds {@code getContainerController()}
 * in. {@link AgentContainer} is one. Platform listeners and suspending are not supported
 * (they throw a {@link ControllerException} saying so).
 */
public interface PlatformController {
    String getName();

    void start() throws ControllerException;

    void suspend() throws ControllerException;

    void resume() throws ControllerException;

    void kill() throws ControllerException;

    AgentController getAgent(String localAgentName) throws ControllerException;

    AgentController createNewAgent(String nickname, String className, Object[] args) throws ControllerException;

    State getState();

    void addPlatformListener(Listener aListener) throws ControllerException;

    void removePlatformListener(Listener aListener) throws ControllerException;

    /** Told of a platform's events (not supported by concord-jade: adding one throws). */
    interface Listener extends java.util.EventListener {
        void bornAgent(PlatformEvent anEvent);

        void deadAgent(PlatformEvent anEvent);

        void startedPlatform(PlatformEvent anEvent);

        void suspendedPlatform(PlatformEvent anEvent);

        void resumedPlatform(PlatformEvent anEvent);

        void killedPlatform(PlatformEvent anEvent);
    }
}
