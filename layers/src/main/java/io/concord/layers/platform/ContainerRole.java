package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.net.Address;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The container (dissertation figs. 5.7 to 5.12): it registers those who join, distributes the LAL
 * in pages, tells every member each period that it is alive and removes the silent, keeps the GAL
 * of the other hosts (through the federation) for its members, and yields to a better container.
 */
final class ContainerRole extends RoleBase {
    private final Map<String, Long> lastHeard = new HashMap<>();
    private final Map<String, Long> heldSeq = new HashMap<>();
    private final Set<String> cycleAwaiting = new HashSet<>();
    private long cycleTimer = -1;
    /** How long GAL changes are gathered before they go to the members. */
    static final long GAL_PUSH_DELAY_MS = 20;
    private long galPushTimer = -1;
    /** The GAL as last sent to the members, and its version; null before the first. */
    private Map<String, AgentEntry> galSent;
    private long galSentSeq;
    /** Cancels the watch on each listed member of this runtime, by name. */
    private final Map<String, Runnable> localWatches = new HashMap<>();
    private long pushTimer = -1;
    /** The LAL as last pushed to the members, its version, and the version that push started from. */
    private Map<String, AgentEntry> lalSent;
    private long lalSentSeq = -1;
    private long lalSentFrom = -1;
    private long lalPushedNs;
    private int cycles;
    /** Cycles in a row with no member elsewhere and the list unchanged. */
    private int quietCycles;
    private long seqAtLastCycle = -1;
    private long cycleStartNs;
    private long cycleDueNs;
    /** This loop's recent lag (how late its cycles ran), fading by a period each cycle. */
    private long ownLagNs;
    /** Members silent past the timeout but holding their ports: slow, not dead. */
    private final Set<String> slow = new HashSet<>();
    /** Members found slow rather than dead, since this agent took the role. */
    private long slowSuspicions;

    ContainerRole(Roles roles) {
        super(roles);
    }

    @Override
    Role kind() {
        return Role.CONTAINER;
    }

    /** Takes the role: announces it, and asks every listed agent for its information (fig. 5.11). */
    void begin(String why) {
        AgentLists lists = st.lists;
        long now = ctx.nowNs();
        for (String n : lists.lal.keySet()) {
            lastHeard.put(n, now);
        }
        roles.rebuildRoutes();
        ctx.trace("container", "term=" + st.term + " agents=" + lists.lal.size() + ": " + why);
        // Announce to those who wait, and ask every listed agent for its information (rebuild).
        for (AgentEntry s : st.seekers.values()) {
            ctx.send(Performative.INFORM, Protocol.P_DISCOVERY, s.aid(), new PlatformMessage.ContainerIs(st.term, st.selfEntry, null));
        }
        st.seekers.clear();
        for (AgentEntry e : lists.lal.values()) {
            if (!e.name().equals(ctx.self())) {
                ctx.send(Performative.REQUEST, Protocol.P_LAL, e.aid(), new PlatformMessage.AgentInfoRequest(st.term, st.selfEntry));
            }
        }
        if (lists.lal.size() > 1) {
            schedulePush();
        }
        st.periodMs = ctx.config().periodMs(lists.lal.size());
        st.timeoutMs = ctx.config().timeoutMs(lists.lal.size());
        cycleDueNs = ctx.nowNs() + st.periodMs * 1_000_000L;
        cycleTimer = after(st.periodMs, this::cycle);
    }

    // ---- who is container ---------------------------------------------------------------------

    @Override
    void claimed(AgentEntry container, long term, AclMessage m) {
        contest(container, term);
    }

    /** Another agent claims to be container: the better claim wins; the loser yields, or is told of the winner. */
    void contest(AgentEntry other, long t) {
        if (other.name().equals(ctx.self())) {
            return;
        }
        if (beats(t, other, st.term, st.selfEntry)) {
            roles.yieldTo(other, t);
        } else {
            tellBetter(other.aid());
        }
    }

    @Override
    public void onLal(PlatformMessage.LalPage p, AclMessage m) {
        contest(roles.lalClaimant(p, m), p.term());
    }

    @Override
    public void onAlive(PlatformMessage.Alive a, AclMessage m) {
        contest(a.by(), a.term());
    }

    @Override
    public void onAgentInfoRequest(PlatformMessage.AgentInfoRequest r, AclMessage m) {
        if (beats(r.term(), r.by(), st.term, st.selfEntry)) {
            roles.yieldTo(r.by(), r.term());
        } else {
            tellBetter(m.getSender());
        }
    }

    // ---- the LAL --------------------------------------------------------------------------------

    /** A newcomer registers (fig. 5.7): listed, confirmed with the period and timeout for the list's size. */
    @Override
    public void onJoin(PlatformMessage.Join j, AclMessage m) {
        AgentEntry e = j.by();
        AgentLists lists = st.lists;
        replacedAt(e);
        AgentEntry old = lists.lal.put(e.name(), keepServices(lists.lal.get(e.name()), e));
        lastHeard.put(e.name(), ctx.nowNs());
        listed(e);
        if (old == null || !old.equals(lists.lal.get(e.name()))) {
            st.seq++;
            roles.routesChanged(e.name());
            schedulePush();
            ctx.trace("registered", e.name() + " agents=" + lists.lal.size());
        }
        st.periodMs = ctx.config().periodMs(lists.lal.size());
        st.timeoutMs = ctx.config().timeoutMs(lists.lal.size());
        ctx.sendQuietly(roles.replyOf(m, Performative.CONFIRM, new PlatformMessage.Joined(st.term, st.periodMs, st.timeoutMs, st.selfEntry)));
        roles.publish();
    }

    /**
     * A member was listed: one of this runtime is watched for leaving it; one of another runtime
     * needs the cycle at its period (the cycle may be waiting longer, with only members of this
     * runtime listed).
     */
    private void listed(AgentEntry e) {
        if (e.name().equals(ctx.self())) {
            return;
        }
        if (ctx.here(e)) {
            watchLocal(e);
        } else if (cycleTimer >= 0 && cycleDueNs - ctx.nowNs() > st.periodMs * 1_000_000L) {
            cycleTimer = cancel(cycleTimer);
            cycleDueNs = ctx.nowNs() + st.periodMs * 1_000_000L;
            cycleTimer = after(st.periodMs, this::cycle);
        }
    }

    /** A member of this runtime is watched for leaving it: removed at once when it does (crashed). */
    private void watchLocal(AgentEntry e) {
        String name = e.name();
        if (localWatches.containsKey(name)) {
            return;
        }
        Address at = e.transportAddress();
        localWatches.put(name, ctx.coLocated().whenGone(at, () -> {
            localWatches.remove(name);
            AgentEntry now = st.lists.lal.get(name);
            if (now != null && at.equals(now.transportAddress())) {
                forget(name);
                st.seq++;
                roles.routesChanged(name);
                ctx.trace("removed", name + " left this runtime");
                schedulePush();
                roles.publish();
            }
        }));
    }

    @Override
    void leave() {
        for (Runnable w : localWatches.values()) {
            w.run();
        }
        localWatches.clear();
        super.leave();
    }

    /**
     * A newcomer holds the port of a listed agent of another name: that one's process is gone (a
     * port has one holder), though it may still be within its timeout.
     */
    private void replacedAt(AgentEntry e) {
        Address at = e.transportAddress();
        if (at == null) {
            return;
        }
        List<String> gone = new ArrayList<>();
        for (AgentEntry l : st.lists.lal.values()) {
            if (!l.name().equals(e.name()) && !l.name().equals(ctx.self()) && at.equals(l.transportAddress())) {
                gone.add(l.name());
            }
        }
        for (String n : gone) {
            forget(n);
            st.seq++;
            roles.routesChanged(n);
            ctx.trace("removed", n + ": " + e.name() + " now holds its port " + at);
        }
    }

    /** Removes a member from the list and from what is kept of it; false if it was not listed. */
    private boolean forget(String name) {
        lastHeard.remove(name);
        heldSeq.remove(name);
        slow.remove(name);
        return st.lists.lal.remove(name) != null;
    }

    /** Members found slow (silent past the timeout, their process alive) rather than dead, since this agent took the role. */
    long slowSuspicions() {
        return slowSuspicions;
    }

    /** A rejoining agent that lost its own copy keeps the services the list holds for it. */
    private static AgentEntry keepServices(AgentEntry known, AgentEntry joining) {
        if (known != null && joining.services().isEmpty() && !known.services().isEmpty()
                && known.address().equals(joining.address()) && known.startMs() == joining.startMs()) {
            return joining.withServices(known.services());
        }
        return joining;
    }

    /** The answer to the request for information: the agent's entry, listed. */
    @Override
    public void onAgentInfo(PlatformMessage.AgentInfo i, AclMessage m) {
        if (i.entries().size() != 1 || !i.entries().get(0).name().equals(m.getSender().name())) {
            return;
        }
        AgentEntry e = i.entries().get(0);
        lastHeard.put(e.name(), ctx.nowNs());
        listed(e);
        AgentEntry was = st.lists.lal.put(e.name(), e);
        if (!e.equals(was)) {
            st.seq++;
            roles.routesChanged(e.name());
            schedulePush();
            roles.publish();
        }
    }

    /** A member leaves: removed at once, and the list distributed. */
    @Override
    public void onLeave(PlatformMessage.Leave l, AclMessage m) {
        String from = m.getSender().name();
        if (forget(from)) {
            st.seq++;
            roles.routesChanged(from);
            ctx.trace("removed", from + " left");
            schedulePush();
            roles.publish();
        }
    }

    /** A member's services changed through the DF. */
    void servicesChanged(AgentEntry entry, List<ServiceDescription> services) {
        AgentEntry updated = entry.withServices(services);
        if (!updated.equals(entry)) {
            st.lists.lal.put(entry.name(), updated);
            if (entry.name().equals(ctx.self())) {
                st.selfEntry = updated;
            }
            st.seq++;
            roles.routesChanged(entry.name());
            schedulePush();
            roles.publish();
        }
    }

    private void schedulePush() {
        if (pushTimer < 0) {
            pushTimer = after(ctx.config().pushDelayMs(), () -> {
                pushTimer = -1;
                pushAll();
            });
        }
    }

    /**
     * The LAL to every member: what changed since the version last pushed ({@code lal-delta}) to
     * those who were sent that version, the whole list to those who joined since; the whole list to
     * all at the first push of a term, or when more than half of it changed. The whole list at
     * every change cost N members times N entries while N agents joined one by one: 1,000 agents
     * in one JVM took 77 s to converge.
     */
    private void pushAll() {
        AgentLists lists = st.lists;
        List<AgentEntry> delta = new ArrayList<>();
        int removed = lalSent == null ? 0 : AgentLists.diff(lalSent, lists.lal, delta);
        boolean whole = lalSent == null || delta.size() * 2 > lists.lal.size();
        List<String> all = null;
        List<String> changes = whole ? null : AgentLists.pages(delta, ctx.config().maxContentBytes());
        for (AgentEntry e : lists.lal.values()) {
            if (e.name().equals(ctx.self()) || slow.contains(e.name())) {
                continue; // a slow one is sent the whole list when it confirms an old version again
            }
            if (whole || !lalSent.containsKey(e.name())) {
                if (all == null) {
                    all = roles.lalPages();
                }
                pushTo(e.aid(), all);
            } else {
                for (int i = 0; i < changes.size(); i++) {
                    ctx.send(Performative.INFORM_REF, Protocol.P_LAL, e.aid(), new PlatformMessage.LalDelta(st.term, lalSentSeq,
                            st.seq, st.periodMs, st.timeoutMs, removed, PlatformMessage.Page.of(i, changes.size(), changes.get(i))));
                }
            }
        }
        lalSentFrom = lalSent == null ? st.seq : lalSentSeq;
        lalPushedNs = ctx.nowNs();
        lalSent = new HashMap<>(lists.lal);
        lalSentSeq = st.seq;
        ctx.trace("distribute", "term=" + st.term + " seq=" + st.seq + " agents=" + lists.lal.size()
                + (whole ? " whole" : " changes=" + delta.size()));
        if (roles.federation != null) {
            roles.federation.localChanged();
            globalChanged();
        }
        roles.publish();
    }

    private void pushTo(AID to, List<String> p) {
        for (int i = 0; i < p.size(); i++) {
            ctx.send(Performative.INFORM_REF, Protocol.P_LAL, to, new PlatformMessage.LalPage(st.term, st.seq, st.periodMs,
                    st.timeoutMs, PlatformMessage.Page.of(i, p.size(), p.get(i))));
        }
    }

    /** A member's confirmation of the version it holds (after a LAL or an alive). */
    @Override
    public void onHeld(PlatformMessage.Held h, AclMessage m) {
        String from = m.getSender().name();
        AgentLists lists = st.lists;
        if (!lists.lal.containsKey(from)) {
            // Removed while silent: its list is outdated; our list tells it to join again.
            pushTo(m.getSender(), roles.lalPages());
            return;
        }
        long now = ctx.nowNs();
        lastHeard.put(from, now);
        heldSeq.put(from, h.seq());
        boolean otherSource = h.gfrom() != null && !ctx.self().equals(h.gfrom());
        if (h.gseq() != null && (otherSource || h.gseq() < galSentSeq) && pushTimer < 0 && galPushTimer < 0
                && ctx.self().equals(lists.galFrom)) {
            pushGalTo(lists.lal.get(from).aid(), AgentLists.pages(lists.gal.values(), ctx.config().maxContentBytes()));
        }
        if (cycleAwaiting.remove(from) && cycleAwaiting.isEmpty()) {
            st.lastCycleNs = now - cycleStartNs;
        }
        // Behind: it holds neither the version last pushed nor the one that push started from (what
        // is in flight to it brings it up from either: a confirmation that crossed the last push is
        // not behind); or it answers an alive sent after the last push and still holds an older
        // version (the change was lost on its way, where the profile does not resend).
        boolean behind = h.term() != st.term || h.seq() < Math.min(st.seq, lalSentFrom < 0 ? st.seq : lalSentFrom)
                || h.alive() && cycleStartNs > lalPushedNs && h.seq() < st.seq;
        if (behind && pushTimer < 0) {
            pushTo(lists.lal.get(from).aid(), roles.lalPages());
        }
    }

    // ---- maintenance (fig. 5.9) -----------------------------------------------------------------

    /**
     * A member in this agent's runtime that cannot read this agent in memory gets an alive every
     * this many cycles (one that can gets none): it needs none to know this agent is alive, and
     * watches for it to leave the runtime (see {@link MemberRole}).
     */
    static final int LOCAL_ALIVE_EVERY = 25;
    /** A slow member (silent past the timeout, its port held) gets an alive, as a probe, every this many cycles. */
    static final int SLOW_ALIVE_EVERY = 25;
    /**
     * With no member elsewhere, each cycle that finds nothing changed doubles the wait for the next
     * (from {@link #LOCAL_ALIVE_EVERY} periods) up to this, so that an idle JVM of agents wakes
     * next to never; any change of the list starts again from the shortest wait.
     */
    static final long LOCAL_CYCLE_MAX_MS = 20_000;

    /** The wait before the next cycle with members only in this runtime, after so many quiet cycles. */
    static long localCycleMs(long periodMs, int quietCycles) {
        long base = periodMs * LOCAL_ALIVE_EVERY;
        return Math.min(maxLocalCycleMs(periodMs), base << Math.min(quietCycles, 16));
    }

    /** The longest wait between two cycles with members only in this runtime (what they allow for). */
    static long maxLocalCycleMs(long periodMs) {
        return Math.max(periodMs * LOCAL_ALIVE_EVERY, LOCAL_CYCLE_MAX_MS);
    }

    private void cycle() {
        cycleTimer = -1;
        roles.gatewayRetry(); // its port may have been held by the previous container a moment ago
        cycles++;
        long now = ctx.nowNs();
        AgentLists lists = st.lists;
        // A cycle that runs late (this loop stalled) removes nobody: the agents' confirmations may
        // be waiting to be read.
        long lagNs = cycleDueNs > 0 ? Math.max(0, now - cycleDueNs) : 0;
        boolean late = lagNs > st.periodMs * 500_000L;
        // Local health (Lifeguard): a loop that ran late lately accuses nobody of silence it may
        // have caused itself: the lag it measured, fading by a period a cycle, lengthens the
        // timeout of those it cannot check otherwise.
        ownLagNs = Math.max(lagNs, ownLagNs - st.periodMs * 1_000_000L);
        List<String> dead = new ArrayList<>();
        boolean remote = false; // a member elsewhere: the cycle keeps its period
        for (AgentEntry e : lists.lal.values()) {
            String n = e.name();
            if (n.equals(ctx.self())) {
                continue;
            }
            if (ctx.here(e)) {
                lastHeard.put(n, now); // alive while it is in this runtime: it is watched for leaving
                continue;
            }
            remote = true;
            Long heard = lastHeard.get(n);
            if (heard == null) {
                lastHeard.put(n, now);
            } else if (!late && now - heard > st.timeoutMs * 1_000_000L) {
                String why = suspect(e, now - heard);
                if (why != null) {
                    dead.add(n);
                    ctx.trace("removed", n + " " + why);
                }
            } else {
                slow.remove(n);
            }
        }
        for (String n : dead) {
            forget(n);
        }
        if (!dead.isEmpty()) {
            st.seq++;
            roles.routesChanged(dead);
            pushAll();
        }
        st.periodMs = ctx.config().periodMs(lists.lal.size());
        st.timeoutMs = ctx.config().timeoutMs(lists.lal.size());
        cycleStartNs = now;
        cycleAwaiting.clear();
        PlatformMessage alive = new PlatformMessage.Alive(st.term, st.seq, st.periodMs, st.timeoutMs, st.selfEntry);
        // A member in this runtime lives and dies with this loop, and is told at once when this
        // agent leaves it: it is heard by being here. It reads this agent's layer in memory at the
        // end of its watch (the list's version, and whether this agent is still its container), so
        // it gets no alive; where the runtime offers no such view, an alive every few cycles. An
        // idle JVM of agents then exchanges nothing. With no member elsewhere, the cycle itself
        // comes only every few periods, rarer while nothing changes.
        boolean localAlive = !remote || cycles % LOCAL_ALIVE_EVERY == 0;
        for (AgentEntry e : lists.lal.values()) {
            if (e.name().equals(ctx.self())) {
                continue;
            }
            if (ctx.here(e)) {
                watchLocal(e);
                if (!localAlive || ctx.peerLayer(e) != null) {
                    continue; // it reads this agent's state in memory when it wants to check (MemberRole)
                }
            } else if (slow.contains(e.name()) && cycles % SLOW_ALIVE_EVERY != 0) {
                // A slow member (silent, its process alive) reads nothing meanwhile: an alive every
                // period would pile up unacknowledged until the flow window to it shut, and flow
                // control then paused this agent's own behaviours (a 35 s pause froze the container).
                continue;
            } else {
                cycleAwaiting.add(e.name());
            }
            ctx.send(Performative.INFORM, Protocol.P_MAINTENANCE, e.aid(), alive);
        }
        // Keep asking the potential agents of the range that are not listed: a container elected
        // while one of them was slow to answer finds the other container this way.
        if (remote || st.seq != seqAtLastCycle) {
            quietCycles = 0;
        } else {
            quietCycles++;
        }
        seqAtLastCycle = st.seq;
        // (Once the cycles are rarer, at each.)
        if (cycles % 4 == 1 || quietCycles >= 2) {
            PlatformMessage q = new PlatformMessage.WhoIsContainer(st.round, st.selfEntry);
            Set<Address> listed = new HashSet<>();
            for (AgentEntry e : lists.lal.values()) {
                listed.add(e.transportAddress());
            }
            for (Address a : st.asked.keySet()) {
                if (!listed.contains(a)) {
                    ctx.send(Performative.QUERY_REF, Protocol.P_DISCOVERY, ctx.anyAt(a), q);
                }
            }
        }
        long next = remote ? st.periodMs : localCycleMs(st.periodMs, quietCycles);
        cycleDueNs = now + next * 1_000_000L;
        cycleTimer = after(next, this::cycle);
        if (!dead.isEmpty()) {
            roles.publish();
        }
    }

    /**
     * A member silent past the timeout is suspected, and checked before it is removed (as SWIM
     * probes a suspect): where its port is on this host, binding it tells a crash (the port is
     * free: removed now) from a slow process (still held: kept, and sent alives, which it answers
     * when its loop turns again, refuting the suspicion), up to {@link PlatformConfig#SLOW_BOUND_MS}.
     * Where it cannot be checked, the timeout is lengthened by this loop's own recent lag.
     *
     * @return why it is taken for dead, or null while it is kept
     */
    private String suspect(AgentEntry e, long silentNs) {
        long silentMs = silentNs / 1_000_000L;
        Boolean held = ctx.portHeld(e);
        if (Boolean.FALSE.equals(held)) {
            return "silent for " + silentMs + " ms, and its port is free: its process is gone";
        }
        if (Boolean.TRUE.equals(held)) {
            if (silentMs > PlatformConfig.SLOW_BOUND_MS) {
                return "silent for " + silentMs + " ms though its process holds its port: hung";
            }
            if (slow.add(e.name())) {
                slowSuspicions++;
                ctx.trace("slow", e.name() + " silent for " + silentMs + " ms, but its process holds its port: kept");
            }
            return null;
        }
        if (silentNs > st.timeoutMs * 1_000_000L + Math.min(ownLagNs, PlatformConfig.SLOW_BOUND_MS * 1_000_000L)) {
            return "silent for more than " + st.timeoutMs + " ms";
        }
        return null;
    }

    // ---- the global agent list (fig. 5.12) ------------------------------------------------------

    /**
     * The federation's lists changed: recompute the GAL (this agent's routes use it at once) and
     * give it to every agent a moment later, so that the changes of many hosts arriving together
     * (a network starting, a host's agents joining one by one) go out as one. What goes out is
     * what changed since the version last sent (the whole list if that is more than half of it).
     * Sending the whole list at every change cost N agents times N entries per change: at 2,000
     * agents over 20 hosts the simulation ran out of 6 GB with a million datagrams in flight.
     */
    void globalChanged() {
        if (roles.federation == null) {
            return;
        }
        AgentLists lists = st.lists;
        List<AgentEntry> now = roles.federation.globalAgents(lists.lal.keySet());
        if (now.equals(List.copyOf(lists.gal.values()))) {
            return;
        }
        lists.gal.clear();
        for (AgentEntry e : now) {
            lists.gal.put(e.name(), e);
        }
        lists.gseq++;
        lists.galFrom = ctx.self();
        roles.rebuildRoutes();
        ctx.trace("gal", "gseq=" + lists.gseq + " agents=" + lists.gal.size());
        roles.publish();
        if (galPushTimer < 0) {
            galPushTimer = after(Math.max(GAL_PUSH_DELAY_MS, ctx.config().pushDelayMs()), this::pushGal);
        }
    }

    /** The GAL's changes since the version last sent, to every member. */
    private void pushGal() {
        galPushTimer = -1;
        AgentLists lists = st.lists;
        if (galSentSeq == lists.gseq && galSent != null) {
            return;
        }
        List<AgentEntry> delta = new ArrayList<>();
        int removed = galSent == null ? 0 : AgentLists.diff(galSent, lists.gal, delta);
        long from = galSentSeq;
        boolean whole = galSent == null || delta.size() * 2 > lists.gal.size();
        galSent = new HashMap<>(lists.gal);
        galSentSeq = lists.gseq;
        List<String> pages = AgentLists.pages(whole ? lists.gal.values() : delta, ctx.config().maxContentBytes());
        for (AgentEntry e : lists.lal.values()) {
            if (e.name().equals(ctx.self()) || slow.contains(e.name())) {
                continue; // a slow one shows an old GAL version when it confirms again, and is sent the whole
            }
            if (whole) {
                pushGalTo(e.aid(), pages);
            } else {
                for (int i = 0; i < pages.size(); i++) {
                    ctx.send(Performative.INFORM_REF, Protocol.P_LAL, e.aid(), new PlatformMessage.GalDelta(st.term, from,
                            lists.gseq, removed, PlatformMessage.Page.of(i, pages.size(), pages.get(i))));
                }
            }
        }
    }

    private void pushGalTo(AID to, List<String> p) {
        for (int i = 0; i < p.size(); i++) {
            ctx.send(Performative.INFORM_REF, Protocol.P_LAL, to,
                    new PlatformMessage.GalPage(st.term, st.lists.gseq, PlatformMessage.Page.of(i, p.size(), p.get(i))));
        }
    }
}
