package io.concord.core.net;

/**
 * A datagram network with its port space: real sockets, UDP and TCP ({@link SocketNetwork}), or the
 * deterministic virtual network of the test kit. One loop polls it; {@link #wakeup()} is the only
 * method other threads may call.
 */
public interface Network extends AutoCloseable {

    /**
     * Binds a port.
     *
     * @param host the local host (an IP literal, or a virtual host name)
     * @param port the port, or 0 for any free one
     * @return the endpoint, or {@code null} if the port is already bound (the expected outcome that
     *         port-binding discovery relies on)
     * @throws java.io.UncheckedIOException for any other failure to bind, with its cause
     */
    Endpoint tryBind(String host, int port, Receiver receiver);

    /**
     * Binds a port of the given transport. UDP and TCP ports are separate spaces.
     *
     * @see #tryBind(String, int, Receiver)
     */
    default Endpoint tryBind(Transport transport, String host, int port, Receiver receiver) {
        if (transport == Transport.UDP) {
            return tryBind(host, port, receiver);
        }
        throw new UnsupportedOperationException(getClass().getSimpleName() + " has no " + transport);
    }

    /**
     * True if a port is held by someone (a socket of this network or of another program), checked
     * by binding it and releasing it at once; the port-binding discovery probes with it.
     */
    default boolean isHeld(Transport transport, String host, int port) {
        Endpoint e = tryBind(transport, host, port, (from, d, o, l, n) -> { });
        if (e == null) {
            return true;
        }
        e.close();
        return false;
    }

    /**
     * Binds a listener that shares its UDP port with others on the host (SO_REUSEADDR) and
     * receives broadcasts: the network discovery port of the containers.
     *
     * @param host      the local host address the node is bound to
     * @param port      the port
     * @param broadcast true to receive broadcasts (bind the wildcard address), false to bind the host only
     * @return the endpoint, or {@code null} if the port cannot be shared
     */
    default Endpoint bindListener(String host, int port, boolean broadcast, Receiver receiver) {
        throw new UnsupportedOperationException(getClass().getSimpleName() + " has no shared listeners");
    }

    /**
     * The broadcast addresses a node bound to {@code host} reaches: the subnet broadcast of the
     * host's interface, then the limited broadcast 255.255.255.255. Empty for loopback, where
     * nothing is broadcast.
     */
    default java.util.List<String> broadcastAddresses(String host) {
        return java.util.List.of();
    }

    /**
     * Delivers the datagrams that have arrived by {@code nowNs} to their receivers.
     *
     * @return how many were delivered
     */
    int poll(long nowNs);

    /** The time of the next scheduled delivery, or {@link Long#MAX_VALUE} if none is known. */
    long nextEventNs();

    /**
     * Waits up to {@code timeoutNs} for datagrams or a {@link #wakeup()}; returns at once on a
     * virtual network.
     */
    void await(long timeoutNs);

    /**
     * The unit in which {@link #await} counts: a loop waits whole units on the network and the
     * rest of a timer's wait by parking the thread. 0 (exact) by default.
     */
    default long awaitResolutionNs() {
        return 0;
    }

    /** Makes a pending or the next {@link #await} return. Thread-safe. */
    void wakeup();

    /**
     * Sends what the endpoints gathered during this cycle of the loop (see
     * {@link Endpoint#send(Address, byte[], int, int, int)}); the loop calls it at the end of each
     * cycle. Nothing by default.
     */
    default void flush() {
    }

    /** Closes every endpoint and the network itself. */
    @Override
    void close();

    /**
     * A capability this network lends the nodes on it (for one of Concord's own components, such as
     * the loop's selector for the JADE bridge's sockets), or {@code null} if it has none of that type.
     */
    default <T> T capability(Class<T> type) {
        return null;
    }
}
