package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.net.Address;

import java.util.List;

/**
 * What an agent that is not container does alike whether it seeks one or follows one: it takes
 * the LAL and the alive messages of its container (or of a better one), answers a new container's
 * request for its information, and uses a copy of the last list after failed joins.
 */
abstract class Follower extends RoleBase {

    Follower(Roles roles) {
        super(roles);
    }

    /** The container was heard: wait a timeout again before taking it for gone (members only). */
    void resetWatch() {
    }

    /** A page of the LAL: applied once every page of its version is in, and confirmed (fig. 5.8). */
    @Override
    public void onLal(PlatformMessage.LalPage p, AclMessage m) {
        String from = m.getSender().name();
        AgentEntry claimed = roles.lalClaimant(p, m);
        boolean fromMine = st.container != null && st.container.name().equals(from) && st.term == p.term();
        if (!fromMine) {
            if (st.container != null && !beats(p.term(), claimed, st.term, st.container) && !st.suspects.contains(st.container.name())) {
                tellBetter(m.getSender());
                return;
            }
        } else if (p.seq() < st.seq && p.page().index() == 0) {
            // Our container's list, of our term, went back: it restarted (under its name, at its
            // port) and lost its list; its pages come in order, so this is no late copy. Taken as
            // it is: if this agent is not in it, it joins again.
            ctx.trace("container-restarted", from + " sends version " + p.seq() + " of its list after " + st.seq);
            st.seq = -1;
        } else if (p.seq() <= st.seq) {
            // Already held: confirm again (our confirmation may have been lost).
            ctx.send(Performative.CONFIRM, Protocol.P_LAL, m.getSender(),
                    new PlatformMessage.Held(false, st.term, st.seq, null, null));
            resetWatch();
            return;
        }
        List<AgentEntry> all = roles.lalAssembler.add(p.term() + "/" + from + "/" + p.seq(), p.page());
        if (all == null) {
            return;
        }
        AgentEntry containerEntry = null;
        for (AgentEntry e : all) {
            if (e.name().equals(from)) {
                containerEntry = e;
            }
        }
        if (containerEntry == null) {
            throw new IllegalArgumentException("the LAL from " + from + " does not list its container");
        }
        roles.join.stop();
        roles.becomeMember(containerEntry, p.term(), p.period(), p.timeout());
        AgentLists lists = st.lists;
        lists.lal.clear();
        for (AgentEntry e : all) {
            lists.lal.put(e.name(), e);
        }
        st.seq = p.seq();
        roles.rebuildRoutes();
        AgentEntry mine = lists.lal.get(ctx.self());
        if (mine == null) {
            // Removed (we were silent too long): join again.
            ctx.trace("rejoin", "not in the list of " + from);
            roles.join.start(containerEntry, p.term());
        } else {
            st.selfEntry = mine;
        }
        ctx.send(Performative.CONFIRM, Protocol.P_LAL, m.getSender(), new PlatformMessage.Held(false, st.term, st.seq, null, null));
        roles.publish();
    }

    /**
     * A page of what changed in the LAL: applied, once every page is in, by a member that holds the
     * version it starts from, of the container it follows in this term, and confirmed; ignored
     * otherwise (the member's next confirmation shows it behind, and the container sends the whole list).
     */
    @Override
    public void onLalDelta(PlatformMessage.LalDelta d, AclMessage m) {
        String from = m.getSender().name();
        if (st.container == null || !st.container.name().equals(from) || st.term != d.term() || st.seq != d.from()) {
            return;
        }
        List<AgentEntry> changed = roles.lalAssembler.add(d.term() + "/" + from + "/" + d.from() + ">" + d.seq(), d.page());
        if (changed == null) {
            return;
        }
        AgentLists lists = st.lists;
        List<String> names = AgentLists.apply(changed, d.removed(), lists.lal, name -> true);
        st.seq = d.seq();
        st.periodMs = d.period();
        st.timeoutMs = d.timeout();
        roles.routesChanged(names);
        resetWatch();
        AgentEntry mine = lists.lal.get(ctx.self());
        if (mine == null) {
            ctx.trace("rejoin", "removed from the list of " + from);
            roles.join.start(st.container, d.term());
        } else {
            st.selfEntry = mine;
        }
        ctx.send(Performative.CONFIRM, Protocol.P_LAL, m.getSender(), new PlatformMessage.Held(false, st.term, st.seq, null, null));
        roles.publish();
    }

    /** The container's alive (fig. 5.9): confirmed with the versions held; a better container is joined. */
    @Override
    public void onAlive(PlatformMessage.Alive a, AclMessage m) {
        long t = a.term();
        AgentEntry by = a.by();
        boolean mine = st.container != null && st.container.name().equals(by.name()) && st.term == t;
        if (!mine) {
            if (st.container == null || beats(t, by, st.term, st.container) || st.suspects.contains(st.container.name())) {
                if (!roles.join.to(by.name())) {
                    roles.join.start(by, t);
                }
            } else {
                tellBetter(m.getSender());
            }
            return;
        }
        st.periodMs = a.period();
        st.timeoutMs = a.timeout();
        resetWatch();
        AgentLists l = st.lists;
        ctx.send(Performative.CONFIRM, Protocol.P_MAINTENANCE, m.getSender(),
                new PlatformMessage.Held(true, st.term, st.seq, l.gseq, l.galFrom));
    }

    /** A new container asks for this agent's information (fig. 5.11): follow it and answer, or name a better one. */
    @Override
    public void onAgentInfoRequest(PlatformMessage.AgentInfoRequest r, AclMessage m) {
        long t = r.term();
        AgentEntry by = r.by();
        if (st.container == null || st.container.name().equals(by.name()) || beats(t, by, st.term, st.container)
                || st.suspects.contains(st.container.name())) {
            roles.join.stop();
            int n = st.lists.lal.size();
            roles.becomeMember(by, t, Math.max(st.periodMs, ctx.config().periodMs(n)), Math.max(st.timeoutMs, ctx.config().timeoutMs(n)));
            ctx.sendQuietly(roles.replyOf(m, Performative.INFORM, new PlatformMessage.AgentInfo(t, List.of(st.selfEntry))));
        } else {
            tellBetter(m.getSender());
        }
    }

    /** True if this agent asked that agent for a copy of its LAL, lately. */
    private boolean asked(AID sender) {
        if (ctx.nowNs() - st.lalCopyUntilNs > 0) {
            return false;
        }
        if (sender.name().equals(st.lalCopyFrom)) {
            return true;
        }
        if (st.lalCopyAt == null) {
            return false;
        }
        for (String uri : sender.addresses()) {
            if (st.lalCopyAt.equals(Address.parse(uri))) {
                return true;
            }
        }
        return false;
    }

    /** A page of the last valid LAL a known agent held, asked for after failed joins. */
    @Override
    public void onLalCopy(PlatformMessage.LalCopy c, AclMessage m) {
        if (!asked(m.getSender())) {
            ctx.drop("unsolicited", "a copy of a LAL from " + m.getSender().name() + ", which this agent did not ask for one");
            return;
        }
        AgentLists lists = st.lists;
        boolean added = false;
        for (AgentEntry e : c.page().entries()) {
            if (!lists.lal.containsKey(e.name()) && !st.suspects.contains(e.name())) {
                lists.lal.put(e.name(), e);
                added = true;
            }
        }
        if (added) {
            roles.rebuildRoutes();
            roles.publish();
        }
        // The copy names the container its holder follows: if that is not the one that failed us,
        // join it rather than wait for an election.
        String named = c.container();
        long t = c.term();
        if (!named.isEmpty() && !st.suspects.contains(named) && !named.equals(ctx.self()) && roles.join.target() == null
                && (st.container == null || t > st.term)) {
            for (AgentEntry e : c.page().entries()) {
                if (e.name().equals(named)) {
                    ctx.trace("join-from-copy", named + " term=" + t);
                    roles.join.start(e, t);
                    return;
                }
            }
        }
    }
}
