package jade.wrapper;

import io.concord.jadecompat.internal.Engine;

/** A container made by {@code jade.core.Runtime}: controls its agents. */
public class AgentContainer extends ContainerController {
    public static final String MAIN_CONTAINER_NAME = "Main-Container";

    /** A container on a Concord engine (made by {@code jade.core.Runtime}). */
    public AgentContainer(Engine engine, String name) {
        super(engine, name);
    }

    /** The container's name. */
    public String getName() {
        return name();
    }
}
