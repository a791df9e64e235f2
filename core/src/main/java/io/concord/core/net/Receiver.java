package io.concord.core.net;

/** Receives datagrams arriving at an endpoint, on the loop that polls the network. */
@FunctionalInterface
public interface Receiver {
    /**
     * One datagram. The bytes are valid only during the call.
     *
     * @param nowNs the loop's current time
     */
    void onDatagram(Address from, byte[] data, int offset, int length, long nowNs);

    /**
     * The endpoint refused or dropped something before it became a datagram (a stream over the
     * limit, a connection that never opened): counted with its reason.
     *
     * @param from the peer, or {@code null} if not known yet
     */
    default void onRefused(Address from, String reason, String detail) {
    }
}
