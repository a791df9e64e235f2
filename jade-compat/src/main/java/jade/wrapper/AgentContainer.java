package jade.wrapper;

import io.concord.jadecompat.internal.Engine;

/** A container made by {@code jade.core.Runtime}: controls its agents. */
public class AgentContainer extends ContainerController implements PlatformController {
    public static final String MAIN_CONTAINER_NAME = "Main-Container";

    /** A container on a Concord engine (made by {@code jade.core.Runtime}). */
    public AgentContainer(Engine engine, String name) {
        super(engine, name);
    }

    /** The platform's name, as JADE's {@code PlatformController.getName()} (the container's: {@link #getContainerName()}). */
    @Override
    public String getName() {
        return getPlatformName();
    }

    /**
     * JADE starts a container made by {@code Runtime} at once, and so does concord-jade: this
     * only checks that it still runs (a killed container cannot start again).
     */
    @Override
    public void start() throws ControllerException {
        if (!isJoined()) {
            throw new ControllerException("the container " + name() + " was killed; it cannot start again");
        }
    }

    @Override
    public void suspend() throws ControllerException {
        throw new ControllerException("suspending a platform is not supported by concord-jade");
    }

    @Override
    public void resume() throws ControllerException {
        throw new ControllerException("suspending a platform is not supported by concord-jade");
    }

    /** {@code "Active"} (code 1) while the container runs, {@code "Killed"} (code 3) after. */
    @Override
    public State getState() {
        return isJoined() ? new State(1, "Active") : new State(3, "Killed");
    }

    @Override
    public void addPlatformListener(Listener aListener) throws ControllerException {
        throw new ControllerException("platform listeners are not supported by concord-jade (" + aListener + ")");
    }

    @Override
    public void removePlatformListener(Listener aListener) throws ControllerException {
        throw new ControllerException("platform listeners are not supported by concord-jade (" + aListener + ")");
    }
}
