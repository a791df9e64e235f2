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

    /**
     * True when a datagram to this address is handed over in memory, within this process: it
     * cannot be lost, so repeating it against loss would only cost work. False by default.
     */
    default boolean inMemoryTo(Address to) {
        return false;
    }

    /** Releases the port. Idempotent. */
    void close();

    boolean isOpen();
}
