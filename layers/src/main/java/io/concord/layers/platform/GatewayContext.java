package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.net.Channels;

import java.util.List;

/** What the container gives its gateway. Methods marked "any thread" may be called from the gateway's threads. */
public interface GatewayContext {

    /** The platform name (the part after {@code @}). */
    String platformName();

    /** Runs a task on the platform's loop. Any thread. */
    void execute(Runnable task);

    /**
     * The loop's selector, to serve the gateway's sockets on the loop itself (no thread hand-off
     * between the socket and the agents); {@code null} where the platform's network has none (the
     * test kit's virtual network): the gateway then runs a selector thread of its own.
     */
    default Channels channels() {
        return null;
    }

    /**
     * Runs a task on the loop after {@code ms} milliseconds (by the platform's clock). Loop only;
     * offered wherever {@link #channels()} is.
     */
    default void after(long ms, Runnable task) {
        throw new UnsupportedOperationException("this platform lends no loop to its gateway");
    }

    /**
     * Whether the platform's policy refuses this foreign agent's message (the observation
     * service, the platform protocol, unless an operator exposed it): the reason to answer it with
     * (a REFUSE), or null if {@link #deliver} may take it. Loop only.
     */
    default String refuses(AclMessage message, AID receiver) {
        return null;
    }

    /**
     * Delivers a message from a foreign agent to an agent of this platform by name (relayed by the
     * container to wherever the agent runs). Loop only.
     *
     * @return false if no agent of that name is known, or the policy refuses the message (answer the sender with a FAILURE)
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
