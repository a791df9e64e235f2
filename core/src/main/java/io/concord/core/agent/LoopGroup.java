package io.concord.core.agent;

import io.concord.core.net.Address;

import java.util.concurrent.ConcurrentHashMap;

/**
 * The loops of one platform in one JVM ({@link AgentRuntime.Builder#group}; runtimes of another
 * platform name in the group are reached through the stacks, as ever): an application
 * message from an agent of one loop to an agent of another is handed over in memory, a copy into a
 * queue the receiver's loop drains (one consumer, no lock on the way), as it is between two agents
 * of one loop, and neither stack nor the kernel sees it. The receiver's agent stays its own loop's:
 * it is posted into the mailbox on that loop's thread. Flow control holds as on one loop: a sender
 * whose receiver has more than half its mailbox waiting (queued across included) is paused until
 * the receiver has taken it down to half, and one that would overfill it is refused.
 *
 * <p>Thread-safe: each loop adds and removes its own agents; any loop looks others up.
 */
public final class LoopGroup {
    private final ConcurrentHashMap<Address, AgentNode> byAddress = new ConcurrentHashMap<>();
    private final ConcurrentHashMap<String, AgentNode> byName = new ConcurrentHashMap<>();

    /** A group with no loop in it yet. */
    public LoopGroup() {
    }

    void add(AgentNode n) {
        byAddress.put(n.endpoint.localAddress(), n);
        byName.putIfAbsent(n.aid.name(), n);
    }

    void remove(AgentNode n, Address at) {
        byAddress.remove(at, n);
        byName.remove(n.aid.name(), n);
    }

    /** The agent bound at this address on any loop of the group, or null. */
    AgentNode at(Address a) {
        return a == null ? null : byAddress.get(a);
    }

    /** The agent of this name on any loop of the group, or null. */
    AgentNode named(String name) {
        return byName.get(name);
    }
}
