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
     * Sends one frame on a lane. A network may gather the frames of one lane to one address sent in
     * one cycle of the loop into one datagram, sent when the loop calls {@link Network#flush()}; the
     * copies of a frame go on different lanes, so that no datagram carries two of them.
     *
     * @return as {@link #send(Address, byte[], int, int)}; a gathered frame that cannot be sent at
     *         the flush is reported to {@link #onSendFailure}
     */
    default boolean send(Address to, byte[] data, int offset, int length, int lane) {
        return send(to, data, offset, length);
    }

    /** Told how many gathered frames to an address the network refused when they went out. */
    default void onSendFailure(java.util.function.ObjIntConsumer<Address> failed) {
    }

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
