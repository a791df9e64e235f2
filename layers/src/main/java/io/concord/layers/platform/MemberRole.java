package io.concord.layers.platform;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import java.util.ArrayList;
import java.util.List;

/**
 * A member of a container (dissertation figs. 5.9 and 5.10): it watches for the container's alive
 * messages, and when the container stays silent for the timeout (or leaves), the eldest agent left
 * in the list takes over; if that one stays silent too, it is suspected in turn. A member that has
 * no container yet (after failed joins, or waiting for the successor) is a member all the same.
 */
final class MemberRole extends Follower {
    private long watchTimer = -1;
    /** Cancels the watch on the container's leaving this runtime; null when not watching. */
    private Runnable watchingLocal;

    MemberRole(Roles roles) {
        super(roles);
    }

    @Override
    Role kind() {
        return Role.MEMBER;
    }

    @Override
    void resetWatch() {
        watchTimer = cancel(watchTimer);
        unwatchLocal();
        long t = st.timeoutMs > 0 ? st.timeoutMs : ctx.config().timeoutMs(Math.max(1, st.lists.lal.size()));
        AgentEntry c = st.container;
        if (c != null && roles.join.target() == null && ctx.here(c)) {
            // The container runs in this runtime: told at once when it leaves. It sends no alive
            // where this agent can read it in memory (which it does at the end of this watch), else
            // one every few cycles, rarer while nothing changes (ContainerRole.localCycleMs): the
            // watch covers the longest wait.
            String name = c.name();
            watchingLocal = ctx.coLocated().whenGone(c.transportAddress(), () -> {
                watchingLocal = null;
                if (st.container != null && st.container.name().equals(name)) {
                    watchTimer = cancel(watchTimer);
                    failover("the container " + name + " left this runtime");
                }
            });
            long period = Math.max(1, st.periodMs > 0 ? st.periodMs : ctx.config().periodMs(st.lists.lal.size()));
            t += ContainerRole.maxLocalCycleMs(period);
            // Ending on a whole second of the loop's clock, the watches of a runtime's members end
            // together: one wake of the loop checks them all.
            long nowMs = ctx.nowNs() / 1_000_000L;
            t = (nowMs + t + 999) / 1_000 * 1_000 - nowMs;
        }
        long deadline = ctx.nowNs() + t * 1_000_000L;
        long timeout = t;
        watchStartNs = ctx.nowNs();
        slowReported = false;
        watchTimer = after(t, () -> onWatch(deadline, timeout));
    }

    /** When the current watch began: the container's silence since. */
    private long watchStartNs;
    /** The container's slowness was logged in this watch. */
    private boolean slowReported;

    /** Cancels the watch on a container of this runtime, if any. */
    private void unwatchLocal() {
        if (watchingLocal != null) {
            watchingLocal.run();
            watchingLocal = null;
        }
    }

    @Override
    void leave() {
        unwatchLocal();
        super.leave();
    }

    /**
     * The container stayed silent until the deadline. If this loop itself ran late (a stall: GC,
     * a starved CPU, a paused process), the silence is partly its own: it probes the container and
     * watches again from now. A container of this host whose port is held is waited for (up to the
     * bound); one whose port is free is given up at once.
     */
    private void onWatch(long deadline, long t) {
        watchTimer = -1;
        if (roles.join.target() != null || (st.container == null && st.successor == null)) {
            return;
        }
        if (stillContainerHere()) {
            resetWatch();
            return;
        }
        long period = Math.max(1, st.periodMs > 0 ? st.periodMs : ctx.config().periodMs(st.lists.lal.size()));
        long now = ctx.nowNs();
        // Checked before it is given up: a container of this host whose process still holds its
        // port is slow (paused, starved), not dead; one whose port is free is gone.
        AgentEntry watched = st.container != null ? st.container : st.successor;
        Boolean held = ctx.here(watched) ? null : ctx.portHeld(watched); // one of this runtime was read in memory
        if (!Boolean.FALSE.equals(held) && now - deadline > period * 500_000L) {
            // Local health: this watch ran late, so this loop stalled (its process paused, its
            // CPU starved). What the container sent meanwhile was read before this timer; the
            // silence this agent can vouch for starts now, not when it last heard. A member paused
            // for longer than the bound blamed a healthy container for its own silence and took
            // over. Probe it, and watch again.
            if (!slowReported) {
                slowReported = true;
                ctx.trace("late", "this agent's loop ran " + (now - deadline) / 1_000_000L + " ms late: it accuses nobody of that silence");
            }
            watchStartNs = now;
            probe();
            rearm(held == null ? period : t, t);
            return;
        }
        long silentMs = (now - watchStartNs) / 1_000_000L;
        if (Boolean.TRUE.equals(held) && silentMs <= PlatformConfig.SLOW_BOUND_MS) {
            if (!slowReported) {
                slowReported = true;
                ctx.trace("slow", watched.name() + " silent for " + silentMs + " ms, but its process holds its port: waited for");
            }
            probe();
            rearm(t, t);
            return;
        }
        failover("no word from " + (st.container != null ? "the container " + st.container.name()
                : "the expected successor " + st.successor.name()) + " for " + silentMs + " ms"
                + (Boolean.FALSE.equals(held) ? ", and its port is free: its process is gone" : Boolean.TRUE.equals(held) ? " though its process holds its port: hung" : ""));
    }

    /**
     * A direct probe of the container: it answers when its loop turns again, and one that dropped
     * this agent (silent to it, not slow) answers with its list, which tells this agent to join again.
     */
    private void probe() {
        if (st.container != null) {
            AgentLists l = st.lists;
            ctx.send(Performative.CONFIRM, Protocol.P_MAINTENANCE, st.container.aid(),
                    new PlatformMessage.Held(true, st.term, st.seq, l.gseq, l.galFrom));
        }
    }

    /** Watches again for {@code ms}, from now (the watch's timeout, for what it says, stays {@code t}). */
    private void rearm(long ms, long t) {
        long deadline = ctx.nowNs() + ms * 1_000_000L;
        watchTimer = after(ms, () -> onWatch(deadline, t));
    }

    /**
     * True if the container runs in this runtime and, read in memory, is container still, of this
     * agent's term: its silence is no sign of anything (it sends members of its runtime no alive,
     * see ContainerRole.cycle). Holding an older version of its list, this agent says so, and is
     * sent what it misses, as after an alive.
     */
    private boolean stillContainerHere() {
        AgentEntry c = st.container;
        ContainerLayer there = c == null || roles.join.target() != null || !ctx.here(c) ? null : ctx.peerLayer(c);
        if (there == null || there.role() != Role.CONTAINER || there.term() != st.term) {
            return false;
        }
        if (there.lalSequence() != st.seq) {
            probe(); // as if to an alive
        }
        return true;
    }

    /** The container is gone: the eldest agent left in the list takes over. */
    private void failover(String why) {
        if (st.container != null) {
            st.suspects.add(st.container.name());
        }
        if (st.successor != null) {
            st.suspects.add(st.successor.name());
        }
        st.successor = null;
        st.failoverRounds++;
        List<AgentEntry> candidates = new ArrayList<>();
        for (AgentEntry e : st.lists.lal.values()) {
            if (!st.suspects.contains(e.name())) {
                candidates.add(e);
            }
        }
        if (!candidates.contains(st.selfEntry) && !st.suspects.contains(ctx.self())) {
            candidates.add(st.selfEntry);
        }
        candidates.sort(st.failoverRounds <= 3 ? AgentEntry.SENIORITY : AgentEntry.BY_PORT);
        // The first candidate whose process is not known gone (its port on this host free: it
        // crashed with the container, as agents of one process do): waiting for a dead successor
        // would cost another timeout.
        AgentEntry next = st.selfEntry;
        for (AgentEntry c : candidates) {
            if (c.name().equals(ctx.self()) || ctx.here(c) || !Boolean.FALSE.equals(ctx.portHeld(c))) {
                next = c;
                break;
            }
            st.suspects.add(c.name());
        }
        ctx.trace("failover", why + "; next container: " + next.name());
        if (next.name().equals(ctx.self())) {
            roles.becomeContainer(Math.max(st.term, st.maxTermSeen) + 1, why);
            return;
        }
        // Wait for the successor; if it stays silent too, it is suspected in turn. Until it speaks
        // there is no container (requests to the DF wait).
        st.successor = next;
        st.container = null;
        roles.publish();
        resetWatch();
    }

    /** A better claim is joined; a worse one is told of the container this member follows. */
    @Override
    void claimed(AgentEntry container, long t, AclMessage m) {
        if (st.container == null || beats(t, container, st.term, st.container)) {
            roles.join.start(container, t);
        } else if (!container.name().equals(st.container.name())) {
            tellBetter(container.aid());
        }
    }

    /** A join sent to a member: it is told which container to join. */
    @Override
    public void onJoin(PlatformMessage.Join j, AclMessage m) {
        tellBetter(j.by().aid());
    }

    @Override
    public void onLeave(PlatformMessage.Leave l, AclMessage m) {
        String from = m.getSender().name();
        if (st.container != null && st.container.name().equals(from)) {
            st.lists.lal.remove(from);
            roles.rebuildRoutes();
            failover(from + " left");
        }
    }

    /**
     * A page of what changed in the GAL: applied, once all its pages are in, by a member that
     * holds the version it starts from, from the container it follows; ignored otherwise (the
     * member's next confirmation shows it behind, and the container sends the whole list).
     */
    @Override
    public void onGalDelta(PlatformMessage.GalDelta d, AclMessage m) {
        String from = m.getSender().name();
        AgentLists lists = st.lists;
        if (st.container == null || !st.container.name().equals(from) || !from.equals(lists.galFrom) || lists.gseq != d.from()) {
            return;
        }
        List<AgentEntry> changed = roles.galAssembler.add(from + "/" + d.from() + ">" + d.gseq(), d.page());
        if (changed == null) {
            return;
        }
        List<String> names = AgentLists.apply(changed, d.removed(), lists.gal, name -> !lists.lal.containsKey(name));
        lists.gseq = d.gseq();
        roles.routesChanged(names);
        roles.publish();
    }

    /** A page of the GAL: only the container this agent follows gives it. */
    @Override
    public void onGal(PlatformMessage.GalPage p, AclMessage m) {
        String from = m.getSender().name();
        if (st.container == null || !st.container.name().equals(from)) {
            return;
        }
        AgentLists lists = st.lists;
        long g = p.gseq();
        if (from.equals(lists.galFrom) && g <= lists.gseq) {
            return;
        }
        List<AgentEntry> all = roles.galAssembler.add(from + "/" + g, p.page());
        if (all == null) {
            return;
        }
        lists.gal.clear();
        for (AgentEntry e : all) {
            lists.gal.put(e.name(), e);
        }
        lists.gseq = g;
        lists.galFrom = from;
        roles.rebuildRoutes();
        roles.publish();
    }
}
