package io.concord.core.agent.internal;

import io.concord.core.net.Address;

/**
 * The agents that share this agent's runtime, offered to its layers as a capability of the
 * {@link io.concord.core.layer.StackHost}. Such an agent lives and dies with its runtime's loop,
 * and its frames are handed over in memory, where nothing is lost: a layer need not send it
 * heartbeats to know it is there. It is told at once when that agent leaves.
 */
public interface CoLocated {

    /** True while the agent bound to this address runs in this runtime. */
    boolean here(Address address);

    /**
     * Runs {@code callback} once, on the loop, when the agent at this address leaves this runtime
     * (taken down or crashed), or at once if no agent of this runtime is bound to it.
     *
     * @return cancels the watch (idempotent)
     */
    Runnable whenGone(Address address, Runnable callback);

    /**
     * The layer of this type in the stack of the agent of this runtime bound to this address, for a
     * layer to read the state of its peer in memory instead of asking it by message (call it on the
     * loop only); {@code null} if no such agent or layer is here, or this view offers none.
     */
    default <T> T layer(Address address, Class<T> type) {
        return null;
    }
}
