package io.concord.core.agent;

import io.concord.core.net.Address;

import java.util.concurrent.ConcurrentHashMap;

/**
 * The loops of one platform in one JVM ({@link AgentRuntime.Builder#group}; runtimes of another
 * platform name in the group are reached through the stacks, as ever): an application message
 * from an agent of one loop to an agent of another is handed over in memory, as it is between two
 * agents of one loop, and neither stack nor the kernel sees it. The sender's loop gathers what it
 * hands another loop in one cycle and puts it, at the cycle's end, on that loop's lock-free queue
 * of tasks; the receiver's agent stays its own loop's: its loop posts the messages into the
 * mailbox. Flow control holds as on one loop: a sender whose receiver's mailbox is over half full,
 * or holds with what other loops have queued for it more than half its capacity, is paused until
 * the mailbox is down to a quarter and the two are at most half; one that would overfill it is refused
 * ({@code SendRejectedException("flow-control")}), and one that agents of the receiver's own loop
 * overfilled meanwhile is dropped there and counted ({@code mailbox-full}). Only agents whose
 * network hands frames over in memory are in a group (never the test kit's network).
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
