package io.concord.layers.platform;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.net.Address;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Seeking a container (dissertation figs. 5.6 and 5.7): the potential agents of the port range are
 * asked "who is container", nearest ports first, a batch at a time; the best container claim heard
 * is joined. When every one asked is seeking too, the eldest (after three rounds, the lowest port)
 * becomes container, and the others wait for its announcement, then ask again.
 */
final class SeekingRole extends Follower {
    private final Set<Address> sentTo = new HashSet<>();
    private AgentEntry claim;
    private int attempt;
    private long discoveryTimer = -1;

    SeekingRole(Roles roles) {
        super(roles);
    }

    @Override
    Role kind() {
        return Role.SEEKING;
    }

    /** Starts a round of discovery. */
    void begin() {
        roles.join.claimTerm = -1;
        for (Map.Entry<Address, Boolean> e : st.asked.entrySet()) {
            e.setValue(Boolean.FALSE);
        }
        askNeighbours();
        roles.publish();
    }

    private void askNeighbours() {
        attempt++;
        PlatformMessage ask = new PlatformMessage.WhoIsContainer(st.round, st.selfEntry);
        // The nearest ports first, a batch at a time: any member that answers names the container.
        List<Address> open = new ArrayList<>();
        for (Map.Entry<Address, Boolean> e : st.asked.entrySet()) {
            if (!e.getValue()) {
                open.add(e.getKey());
            }
        }
        int own = st.selfEntry.port();
        open.sort(Comparator.comparingInt(a -> Math.abs(a.port() - own)));
        for (Address a : open.subList(0, Math.min(open.size(), batch()))) {
            sentTo.add(a);
            ctx.send(Performative.QUERY_REF, Protocol.P_DISCOVERY, ctx.anyAt(a), ask);
        }
        discoveryTimer = cancel(discoveryTimer);
        discoveryTimer = after(ctx.config().discoveryTimeoutMs() << Math.min(attempt - 1, 4), this::onDiscoveryTimeout);
    }

    /** Neighbours asked per attempt: a batch that grows with the attempts. */
    private int batch() {
        return 16 << Math.min(attempt - 1, 10);
    }

    private void onDiscoveryTimeout() {
        discoveryTimer = -1;
        if (roles.join.target() != null) {
            return;
        }
        if (claim == null && attempt < ctx.config().discoveryAttempts() && st.asked.containsValue(Boolean.FALSE)) {
            askNeighbours();
            return;
        }
        decide();
    }

    @Override
    public void onSeeking(PlatformMessage.Seeking s, AclMessage m) {
        super.onSeeking(s, m);
        addSeeker(s.by());
        boolean waiting = false;
        for (Address a : sentTo) {
            waiting |= !st.asked.get(a);
        }
        if (roles.join.target() == null && claim == null && !waiting) {
            discoveryTimer = cancel(discoveryTimer);
            if (st.asked.containsValue(Boolean.FALSE)) {
                askNeighbours(); // every one asked is seeking too: ask the next batch now
            } else {
                decide();
            }
        }
    }

    /** The best claim heard is kept, and joined unless a better one is being joined. */
    @Override
    void claimed(AgentEntry container, long t, AclMessage m) {
        Joining join = roles.join;
        if (claim == null || beats(t, container, join.claimTerm, claim)) {
            claim = container;
            join.claimTerm = t;
        }
        // Against the claim being joined with its own term (comparing it with the term just heard
        // kept an elder container of an older term ahead of a later one).
        if (join.target() == null || beats(t, container, join.targetTerm(), join.target())) {
            discoveryTimer = cancel(discoveryTimer);
            join.start(container, t);
        }
    }

    /** Nobody named a container: the election. */
    private void decide() {
        if (claim != null) {
            roles.join.start(claim, roles.join.claimTerm);
            return;
        }
        List<AgentEntry> candidates = new ArrayList<>(st.seekers.values());
        candidates.add(st.selfEntry);
        candidates.sort(st.round < 3 ? AgentEntry.SENIORITY : AgentEntry.BY_PORT);
        if (candidates.get(0).name().equals(ctx.self())) {
            roles.becomeContainer(st.maxTermSeen + 1, st.seekers.isEmpty() ? "no potential agent answered"
                    : "the " + (st.round < 3 ? "oldest" : "lowest port") + " of " + candidates.size() + " seeking agents");
            return;
        }
        // Excluded: wait for the winner to announce itself, then ask again.
        ctx.trace("excluded", "waiting for " + candidates.get(0).name() + " round=" + st.round);
        discoveryTimer = after(ctx.config().electionTimeoutMs(), () -> {
            discoveryTimer = -1;
            if (roles.join.target() == null) {
                st.round++;
                st.seekers.clear();
                roles.beginDiscovery();
            }
        });
    }
}
