package io.concord.core.net;

import java.io.IOException;
import java.nio.channels.SelectableChannel;
import java.nio.channels.SelectionKey;

/**
 * The loop's own selector, lent to a component that serves sockets of its own (the JADE bridge's
 * HTTP MTP): its channels are then read and written by the thread that runs the agents, with no
 * hand-off to a thread of its own and back. Loop only; the handler must not block. A network lends
 * it through {@link Network#capability(Class)}; a gateway (an MTP) is given it by its context.
 */
public interface Channels {

    /**
     * Registers a non-blocking channel with the loop's selector.
     *
     * @return the key, whose interest set the caller changes as it needs (on the loop)
     * @throws IOException if the channel cannot be registered (it is closed, or blocking)
     */
    SelectionKey register(SelectableChannel channel, int ops, Ready ready) throws IOException;

    /** What to do when a registered channel is ready. */
    @FunctionalInterface
    interface Ready {
        /** On the loop; an exception closes nothing by itself: the handler closes what failed. */
        void onReady(SelectionKey key, long nowNs);
    }
}
