package io.concord.layers.platform;

import io.concord.core.net.Address;

import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;

/**
 * What every role of an agent shares and hands on to the next: the term, the container followed,
 * the lists, and what discovery and failover learnt. A role's own fields and timers live in its
 * class and end with it.
 */
final class PlatformState {
    /** This agent's entry; its services change through the DF. */
    AgentEntry selfEntry;
    long term;
    /** The LAL's sequence in the current term. */
    long seq;
    /** The highest term heard of: a new container takes the next. */
    long maxTermSeen;
    /** The container this agent follows (itself when container), or {@code null}. */
    AgentEntry container;
    long periodMs;
    long timeoutMs;
    /** The election round: after three, the lowest port wins instead of the eldest. */
    int round;
    final AgentLists lists = new AgentLists();
    /** The potential agents of the port range, and whether each answered discovery. */
    final Map<Address, Boolean> asked = new LinkedHashMap<>();
    /** Agents heard seeking a container too: the candidates of an election. */
    final Map<String, AgentEntry> seekers = new HashMap<>();
    /** Candidates held at most: more than a host's port range holds (anyone with the key can ask in any name). */
    static final int MAX_SEEKERS = 1024;

    /** Takes a candidate, unless {@link #MAX_SEEKERS} others are held already. */
    boolean addSeeker(AgentEntry e) {
        if (seekers.size() >= MAX_SEEKERS && !seekers.containsKey(e.name())) {
            return false;
        }
        seekers.put(e.name(), e);
        return true;
    }
    /** Agents taken for gone by a failover: no longer candidates. */
    final Set<String> suspects = new HashSet<>();
    /** After a failover, the agent expected to take over, or {@code null}. */
    AgentEntry successor;
    int failoverRounds;
    /**
     * The message being handled came in a frame for any agent at a port, sealed with the platform
     * key alone: its sender is whatever its sender wrote, so it is a hint at most.
     */
    boolean fromAny;
    /** Claims are taken only on the claimed container's own authenticated word (off only in threat tests). */
    boolean claimCheck = true;
    /** A silent agent of this host is checked by its port before it is taken for dead (off only in tests). */
    boolean portCheck = true;
    /** The agent last heard from each transport address (bounded): a port taken by another agent tells its former holder gone. */
    final Map<Address, String> heardAt = new LinkedHashMap<>(64, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<Address, String> eldest) {
            return size() > 1_024;
        }
    };
    /**
     * The copy of the last LAL this agent asked for after failed joins: from whom (a name, or the
     * agent at an address), and until when it is taken. A copy nobody asked for is refused: only
     * the container distributes lists.
     */
    String lalCopyFrom;
    Address lalCopyAt;
    long lalCopyUntilNs;
    /** How long the container's last complete maintenance cycle took, in ns; -1 if none yet. */
    volatile long lastCycleNs = -1;

    String self() {
        return selfEntry.name();
    }
}
