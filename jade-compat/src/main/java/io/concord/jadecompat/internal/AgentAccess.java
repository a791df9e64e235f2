package io.concord.jadecompat.internal;

import jade.core.Agent;
import jade.wrapper.AgentContainer;

/**
 * What {@code jade.wrapper} needs of {@code jade.core.Agent} beyond JADE's public API (start an
 * agent on the engine, wait for its end), without making it public on the agent. The agent class
 * installs the implementation when it loads.
 */
public abstract class AgentAccess {
    private static volatile AgentAccess instance;

    /** Installed once by {@code jade.core.Agent}. */
    public static void install(AgentAccess a) {
        instance = a;
    }

    /** The implementation (loads {@code jade.core.Agent} if needed). */
    public static AgentAccess get() {
        if (instance == null) {
            try {
                Class.forName(Agent.class.getName(), true, Agent.class.getClassLoader());
            } catch (ClassNotFoundException e) {
                throw new IllegalStateException(e);
            }
        }
        return instance;
    }

    /** Starts the agent on the engine, in a container, under a local name; returns once it runs. */
    public abstract void start(Agent a, Engine e, AgentContainer c, String localName);

    /** Waits up to {@code timeoutMs} for the agent to end. */
    public abstract void awaitEnd(Agent a, long timeoutMs) throws InterruptedException;

    /** The Concord agent under a JADE agent, or null before it starts. */
    public abstract Host host(Agent a);

    /** The engine a JADE agent runs on, or null before it starts. */
    public abstract Engine engine(Agent a);

    /** True if the caller runs on the agent's own thread. */
    public abstract boolean onOwnThread(Agent a);

    /** True once the agent was asked to end ({@code doDelete}, a kill): the AMS no longer lists it. */
    public abstract boolean ending(Agent a);
}
