package io.concord.core.net;

/** A bound datagram socket, real or virtual. Used only from the loop that polls its network. */
public interface Endpoint {

    /** The address others send to. */
    Address localAddress();

    /**
     * Sends one datagram.
     *
     * @return true if it was handed to the network; false if it could not be (buffer full, closed,
     *         no route), which the caller counts as a drop
     */
    boolean send(Address to, byte[] data, int offset, int length);

    /** Releases the port. Idempotent. */
    void close();

    boolean isOpen();
}
