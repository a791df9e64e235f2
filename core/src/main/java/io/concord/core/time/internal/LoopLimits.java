package io.concord.core.time.internal;

import java.util.HashMap;
import java.util.Map;

/**
 * Rate limits shared by every agent of one loop (an {@link io.concord.core.agent.AgentRuntime}):
 * work that strangers can cause, such as signature checks, is bounded per loop thread, whatever
 * the number of agents it runs, and not only per agent. Offered to the layers as a
 * {@link io.concord.core.layer.StackHost#capability capability}. Loop thread only.
 */
public final class LoopLimits {
    private final Map<String, TokenBucket> buckets = new HashMap<>();

    /** The loop's limit of that name; the first agent to ask sets its burst and rate. */
    public TokenBucket bucket(String name, int burst, double perSecond) {
        return buckets.computeIfAbsent(name, k -> new TokenBucket(burst, perSecond));
    }
}
