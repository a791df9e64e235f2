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
}
