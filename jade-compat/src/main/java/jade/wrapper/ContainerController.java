package jade.wrapper;

import io.concord.jadecompat.internal.Engine;
import jade.core.Agent;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/** A handle on a container: create agents in it, kill it. */
public class ContainerController {
    private final Engine engine;
    private final String containerName;
    private final Map<String, LocalAgentController> agents = new ConcurrentHashMap<>();
    private volatile boolean killed;

    /** A container on a Concord engine (made by {@code jade.core.Runtime}). */
    public ContainerController(Engine engine, String containerName) {
        this.engine = engine;
        this.containerName = containerName;
        engine.addContainer(containerName, this);
    }

    /** The controller of an agent created in this container. */
    public AgentController getAgent(String localName) throws ControllerException {
        return getAgent(localName, false);
    }

    public AgentController getAgent(String name, boolean isGuid) throws ControllerException {
        String local = isGuid && name.contains("@") ? name.substring(0, name.lastIndexOf('@')) : name;
        AgentController c = agents.get(local);
        if (c == null) {
            throw new ControllerException("Agent " + name + " not found in " + containerName);
        }
        return c;
    }

    /**
     * Creates an agent of a class (a {@code jade.core.Agent} with a public no-argument
     * constructor) with arguments; {@link AgentController#start()} starts it.
     */
    public AgentController createNewAgent(String nickname, String className, Object[] args) throws StaleProxyException {
        checkAlive();
        Agent a;
        try {
            ClassLoader cl = Thread.currentThread().getContextClassLoader();
            Class<?> type = Class.forName(className, true, cl != null ? cl : getClass().getClassLoader());
            a = (Agent) type.getDeclaredConstructor().newInstance();
        } catch (ReflectiveOperationException | ClassCastException | LinkageError e) {
            throw new StaleProxyException("cannot create agent " + nickname + " of class " + className + ": " + e);
        }
        return acceptNewAgent(nickname, a, args);
    }

    /** Takes an agent object made by the caller; {@link AgentController#start()} starts it. */
    public AgentController acceptNewAgent(String nickname, Agent anAgent) throws StaleProxyException {
        return acceptNewAgent(nickname, anAgent, anAgent.getArguments());
    }

    private AgentController acceptNewAgent(String nickname, Agent a, Object[] args) throws StaleProxyException {
        checkAlive();
        if (agents.containsKey(nickname) || engine.hosts(nickname)) {
            throw new StaleProxyException("Name-clash: an agent named " + nickname + " already exists");
        }
        a.setArguments(args);
        LocalAgentController c = new LocalAgentController(a, nickname, engine, (AgentContainer) this);
        agents.put(nickname, c);
        return c;
    }

    /**
     * Kills every agent of this container and returns once their {@code takeDown()} has run (as
     * JADE's does), waiting up to 30 s an agent; an agent that kills its own container is not
     * waited for.
     */
    public void kill() throws StaleProxyException {
        killed = true;
        for (LocalAgentController c : agents.values()) {
            c.requestEnd();
        }
        try {
            for (LocalAgentController c : agents.values()) {
                c.killAndWait(KILL_WAIT_MS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new StaleProxyException(e);
        }
    }

    private static final long KILL_WAIT_MS = 30_000;

    /** The platform's name. */
    public String getPlatformName() {
        return engine.platformName();
    }

    public String getContainerName() throws ControllerException {
        return containerName;
    }

    /** True while the container runs. */
    public boolean isJoined() {
        return !killed;
    }

    final String name() {
        return containerName;
    }

    private void checkAlive() throws StaleProxyException {
        if (killed) {
            throw new StaleProxyException("the container " + containerName + " was killed");
        }
    }
}
