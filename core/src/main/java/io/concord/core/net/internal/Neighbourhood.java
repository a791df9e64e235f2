package io.concord.core.net.internal;

import io.concord.core.net.Address;
import io.concord.core.net.Endpoint;
import java.util.List;

/**
 * A node's place among the other nodes of its host, for the container layer's discovery: offered
 * by the node as a {@link io.concord.core.layer.StackHost#capability capability}.
 */
public interface Neighbourhood {

    /**
     * The ports of this host that were held by others when this node bound its own in its port
     * range, and those found held in the probe window past it: the potential agents of the
     * port-binding discovery. Empty when the node was bound to a fixed port.
     */
    List<Address> neighbours();

    /**
     * Opens the node's listener on a shared UDP port (the containers' network discovery port):
     * what arrives there goes up this node's stack. Receives broadcasts unless the node is bound
     * to loopback.
     *
     * @return the listener, to close when done; {@code null} if the port cannot be shared
     */
    Endpoint openListener(int port);

    /** The broadcast addresses this node reaches (none on loopback). */
    List<String> broadcastAddresses();

    /**
     * Whether a port of this node's own host is held, checked by binding it and releasing it at
     * once: a process that crashed (killed, exited) holds none of its ports any more, one that is
     * only slow (paused, starved of CPU) still holds them. {@code null} when it cannot be told: the
     * address is on another host, or of another transport.
     */
    default Boolean held(Address address) {
        return null;
    }
}
