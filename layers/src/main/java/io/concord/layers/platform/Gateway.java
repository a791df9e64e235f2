package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;

import java.util.List;

/**
 * A way out of the platform to agents of other platforms (the JADE bridge's FIPA HTTP MTP). Every
 * agent's container layer holds one, but only the container's is started: it serves the endpoint,
 * and the other agents' messages to foreign receivers are relayed to it. After a failover the new
 * container starts its own.
 */
public interface Gateway {

    /** This agent became its host's container: start serving. Called on the loop. */
    void start(GatewayContext context);

    /** This agent is no longer container, or stops. Called on the loop. */
    void stop();

    /** True if this gateway can carry a message to that foreign agent (it has an address it knows). */
    boolean reaches(AID foreign);

    /**
     * Sends a platform agent's message to one foreign receiver. Called on the loop; must not block
     * (hand the work to a thread of the gateway's own). If the receiver cannot be reached, tell the
     * sender with {@link GatewayContext#deliver} of a FAILURE.
     */
    void sendOut(AclMessage message, AID receiver);

    /** The transport addresses of this platform as foreign agents see it (e.g. {@code http://host:7779/acc}). */
    List<String> addresses();
}
