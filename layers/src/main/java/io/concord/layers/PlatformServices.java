package io.concord.layers;

import io.concord.core.agent.Agent;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.platform.Role;
import io.concord.layers.platform.ServiceDescription;

import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * The white and yellow pages for an agent, in plain Java. Reads come from the agent's own copy of
 * the LAL, which the container keeps equal on every agent: no message is sent. Changes go to the
 * platform's DF, wherever the container is; their futures complete when the DF has taken them.
 * Call from the agent's behaviours (its loop); the futures complete there too.
 */
public final class PlatformServices {
    private final Agent agent;
    private final ContainerLayer layer;

    PlatformServices(Agent agent, ContainerLayer layer) {
        this.agent = agent;
        this.layer = layer;
    }

    /** True if this agent is its host's container now. */
    public boolean isContainer() {
        return layer.role() == Role.CONTAINER;
    }

    /** The container's name, or {@code null} while none is known. */
    public String container() {
        return layer.containerName();
    }

    /** The white pages: every agent of the platform on this host, as this agent knows them. */
    public List<AgentEntry> agents() {
        return List.copyOf(layer.agents());
    }

    /**
     * The agents whose services match the template, as the platform's DF holds them: the future
     * completes once the container has answered (it waits while none is elected, as JADE's
     * {@code DFService.search} blocks), so every registration the DF took before, by any agent of
     * this platform, is in it. Works from {@code setup()} and {@code takeDown()}.
     */
    public CompletableFuture<List<AgentEntry>> search(ServiceDescription template) {
        return searchAtDf(template);
    }

    /**
     * The yellow pages in this agent's own copy of the list: no message, at once, for behaviours
     * that look often (the copy is kept equal to the container's; a registration made elsewhere a
     * moment ago reaches it with the next push, within the maintenance period).
     */
    public List<AgentEntry> searchCopy(ServiceDescription template) {
        return layer.search(template);
    }

    /**
     * Registers services of this agent with the DF (added to those it has). The registration is
     * the agent's own: whenever its container does not hold it (a flap dropped the agent and added
     * it back, a new container after a failover, a refusal while the agent was not yet listed), the
     * agent sends it again, for as long as it lives. The future completes once the DF took it.
     */
    public CompletableFuture<Void> register(ServiceDescription... services) {
        return layer.registerServices(List.of(services), true);
    }

    /** Replaces this agent's services with these (kept as {@link #register} keeps them). */
    public CompletableFuture<Void> modify(ServiceDescription... services) {
        return layer.registerServices(List.of(services), false);
    }

    /** Removes every service of this agent. Works from {@code takeDown()}, as JADE code deregisters there. */
    public CompletableFuture<Void> deregister() {
        return layer.registerServices(List.of(), false);
    }

    /** Asks the DF itself (not this agent's copy); the same as {@link #search}. */
    public CompletableFuture<List<AgentEntry>> searchAtDf(ServiceDescription template) {
        return layer.searchAtDf(template);
    }

    /** The agent these services are for. */
    public Agent agent() {
        return agent;
    }
}
