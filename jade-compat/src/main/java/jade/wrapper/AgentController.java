package jade.wrapper;

import jade.core.Location;

/** A handle on an agent from outside it: start it, kill it, hand it objects. */
public interface AgentController {
    boolean ASYNC = false;
    boolean SYNC = true;

    String getName() throws StaleProxyException;

    /** Starts the agent; returns once it is reachable and its thread runs {@code setup()}. */
    void start() throws StaleProxyException;

    void suspend() throws StaleProxyException;

    void activate() throws StaleProxyException;

    /** Deletes the agent ({@code takeDown()} runs). */
    void kill() throws StaleProxyException;

    void move(Location destination) throws StaleProxyException;

    void clone(Location destination, String newName) throws StaleProxyException;

    /** Hands an object to the agent (see {@code Agent.putO2AObject}). */
    void putO2AObject(Object o, boolean blocking) throws StaleProxyException;

    <T> T getO2AInterface(Class<T> type) throws StaleProxyException;

    State getState() throws StaleProxyException;
}
