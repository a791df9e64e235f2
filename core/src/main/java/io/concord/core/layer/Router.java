package io.concord.core.layer;

import io.concord.core.acl.AID;
import io.concord.core.net.Address;

/**
 * Name-based addressing, given to a node by the layer that keeps the platform's agent lists (the
 * container layer): where an agent, known only by its name, is reached. Called on the loop for
 * every receiver that is not an agent of the same runtime, before the AID's own addresses.
 */
@FunctionalInterface
public interface Router {

    /**
     * @return the route to the receiver, or {@code null} if the lists do not know it
     */
    Route route(AID receiver);

    /**
     * Where to send: the address, and the agent whose node is there (the receiver itself, or the
     * agent that serves a platform name such as {@code df@platform}).
     */
    record Route(Address address, AID node) {
    }
}
