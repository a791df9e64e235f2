package jade.wrapper;

import io.concord.jadecompat.internal.AgentAccess;
import io.concord.jadecompat.internal.Engine;
import jade.core.Agent;
import jade.core.Location;

/** The controller of an agent of this JVM. */
final class LocalAgentController implements AgentController {
    private final Agent agent;
    private final String localName;
    private final Engine engine;
    private final AgentContainer container;
    private volatile boolean startedOnce;

    LocalAgentController(Agent agent, String localName, Engine engine, AgentContainer container) {
        this.agent = agent;
        this.localName = localName;
        this.engine = engine;
        this.container = container;
    }

    @Override
    public String getName() {
        return localName + "@" + engine.platformName();
    }

    @Override
    public synchronized void start() throws StaleProxyException {
        if (startedOnce) {
            throw new StaleProxyException("agent " + localName + " was started already");
        }
        startedOnce = true;
        try {
            AgentAccess.get().start(agent, engine, container, localName);
        } catch (RuntimeException e) {
            throw new StaleProxyException(e);
        }
    }

    /** Asks the agent to end, without waiting. */
    void requestEnd() {
        if (agent.getState() != Agent.AP_DELETED) {
            agent.doDelete();
        }
    }

    /** Deletes the agent and waits (up to {@code timeoutMs}) until its takeDown has run, unless called from its own thread. */
    void killAndWait(long timeoutMs) throws InterruptedException {
        if (agent.getState() == Agent.AP_DELETED) {
            return;
        }
        agent.doDelete();
        if (startedOnce && !AgentAccess.get().onOwnThread(agent)) {
            AgentAccess.get().awaitEnd(agent, timeoutMs);
        }
    }

    @Override
    public void suspend() throws StaleProxyException {
        throw new StaleProxyException("suspending agents is not supported by concord-jade yet");
    }

    @Override
    public void activate() throws StaleProxyException {
        throw new StaleProxyException("suspending agents is not supported by concord-jade yet");
    }

    @Override
    public void kill() throws StaleProxyException {
        if (agent.getState() == Agent.AP_DELETED) {
            throw new StaleProxyException("agent " + localName + " is gone");
        }
        agent.doDelete();
    }

    @Override
    public void move(Location destination) throws StaleProxyException {
        throw new StaleProxyException("agent mobility is not supported by concord-jade");
    }

    @Override
    public void clone(Location destination, String newName) throws StaleProxyException {
        throw new StaleProxyException("agent cloning is not supported by concord-jade");
    }

    @Override
    public void putO2AObject(Object o, boolean blocking) throws StaleProxyException {
        try {
            agent.putO2AObject(o, blocking);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new StaleProxyException(e);
        }
    }

    @Override
    public <T> T getO2AInterface(Class<T> type) throws StaleProxyException {
        throw new StaleProxyException("O2A interfaces are not supported by concord-jade yet; use putO2AObject");
    }

    @Override
    public State getState() {
        int s = agent.getState();
        String[] names = {"", "Initiated", "Active", "Idle", "Suspended", "Waiting", "Deleted"};
        return new State(s, s >= 0 && s < names.length ? names[s] : "Unknown");
    }
}
