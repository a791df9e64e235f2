package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;

import java.util.List;

/** What the container gives its gateway. Methods marked "any thread" may be called from the gateway's threads. */
public interface GatewayContext {

    /** The platform name (the part after {@code @}). */
    String platformName();

    /** Runs a task on the platform's loop. Any thread. */
    void execute(Runnable task);

    /**
     * Delivers a message from a foreign agent to an agent of this platform by name (relayed by the
     * container to wherever the agent runs). Loop only.
     *
     * @return false if no agent of that name is known (answer the sender with a FAILURE)
     */
    boolean deliver(AclMessage message, AID receiver);

    /**
     * The yellow pages: agents of the platform (this host and the others) that offer a service
     * matching each template (see {@link ServiceDescription#offersAll}). Loop only.
     */
    List<AgentEntry> search(List<ServiceDescription> templates);

    /** Every agent of the platform, this host's and the others'. Loop only. */
    List<AgentEntry> agents();
}
