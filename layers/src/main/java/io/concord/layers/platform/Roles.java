package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.net.Address;
import io.concord.core.net.internal.Neighbourhood;
import io.concord.layers.frame.Frames;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Holds an agent's current role and swaps it: each transition of the dissertation's figures is one
 * method here (begin discovery, become container, become member, yield, a join that failed). The
 * role left has its timers cancelled; what the next one needs is in {@link PlatformState}.
 */
final class Roles implements Federation.Host {
    final PlatformContext ctx;
    final PlatformState st;
    final Joining join;
    final Federation federation;
    final GatewayRelay relay;
    /** The pages of the LAL and of the GAL being received from a container. */
    final PageAssembler lalAssembler = new PageAssembler();
    final PageAssembler galAssembler = new PageAssembler();
    private final Runnable publish;
    private RoleBase current;

    /**
     * @param network the discovery of other hosts' containers, or {@code null} for none
     * @param around  the node's neighbourhood (its listener for the network discovery), or {@code null}
     */
    private final Runnable listsChanged;
    /** When this agent last asked each claimed container itself whether it is (bounded). */
    private final Map<String, Long> verified = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Long> eldest) {
            return size() > 64;
        }
    };

    Roles(PlatformContext ctx, PlatformState st, NetworkConfig network, Neighbourhood around,
          GatewayRelay relay, Runnable publish, Runnable listsChanged) {
        this.ctx = ctx;
        this.st = st;
        this.federation = network == null ? null : new Federation(ctx, network, around, this);
        this.relay = relay;
        this.publish = publish;
        this.listsChanged = listsChanged;
        this.join = new Joining(ctx, st, this::joinFailed);
        this.current = new SeekingRole(this);
    }

    RoleBase current() {
        return current;
    }

    Role kind() {
        return current.kind();
    }

    private <R extends RoleBase> R become(R next) {
        current.leave();
        current = next;
        return next;
    }

    /** The agent starts: with nobody else in its port range it is container at once, else it seeks. */
    void start(List<Address> neighbours) {
        if (neighbours.isEmpty()) {
            becomeContainer(1, "no other agent holds a port of the range");
            return;
        }
        for (Address a : neighbours) {
            st.asked.put(a, Boolean.FALSE);
        }
        beginDiscovery();
    }

    void beginDiscovery() {
        become(new SeekingRole(this)).begin();
    }

    void becomeContainer(long newTerm, String why) {
        ContainerRole c = become(new ContainerRole(this));
        join.stop();
        st.successor = null;
        st.lists.galFrom = ctx.self();
        st.term = newTerm;
        st.maxTermSeen = Math.max(st.maxTermSeen, newTerm);
        st.seq = 1;
        st.container = st.selfEntry;
        for (String s : st.suspects) {
            st.lists.lal.remove(s);
        }
        st.suspects.clear();
        st.failoverRounds = 0;
        st.lists.lal.put(ctx.self(), st.selfEntry);
        c.begin(why);
        if (federation != null) {
            federation.start();
        }
        if (relay != null) {
            relay.startGateway();
        }
        publish();
    }

    /** A container that heard a better one: it tells its members, and joins the winner. */
    void yieldTo(AgentEntry better, long t) {
        ctx.trace("yield", "to " + better.name() + " term=" + t);
        if (federation != null) {
            federation.stop();
        }
        if (relay != null) {
            relay.stopGateway();
        }
        become(new MemberRole(this));
        PlatformMessage claim = new PlatformMessage.ContainerIs(t, better, st.selfEntry);
        for (AgentEntry e : st.lists.lal.values()) {
            if (!e.name().equals(ctx.self()) && !e.name().equals(better.name())) {
                ctx.send(Performative.INFORM, Protocol.P_DISCOVERY, e.aid(), claim);
            }
        }
        join.start(better, t);
    }

    void becomeMember(AgentEntry by, long t, long period, long timeout) {
        boolean sameContainer = st.container != null && st.container.name().equals(by.name()) && st.term == t;
        boolean changed = current.kind() != Role.MEMBER || !sameContainer;
        if (federation != null) {
            federation.stop();
        }
        if (relay != null) {
            relay.stopGateway();
        }
        MemberRole m = become(new MemberRole(this));
        st.successor = null;
        if (!sameContainer) {
            st.seq = 0; // a new container's list replaces ours whatever its sequence
        }
        st.container = by;
        st.term = t;
        st.maxTermSeen = Math.max(st.maxTermSeen, t);
        st.periodMs = period;
        st.timeoutMs = timeout;
        st.suspects.clear();
        st.failoverRounds = 0;
        st.seekers.clear();
        if (!st.lists.lal.containsKey(by.name())) {
            st.lists.lal.put(by.name(), by);
            rebuildRoutes();
        }
        m.resetWatch();
        if (changed) {
            ctx.trace("member", "of " + by.name() + " term=" + t);
        }
        publish();
    }

    /**
     * The container does not answer joins: a random known agent is asked for the last valid LAL,
     * and the agent waits a timeout for it (it may name a container to join), then elects from it.
     */
    private void joinFailed(AgentEntry failed) {
        st.suspects.add(failed.name());
        List<AID> known = new ArrayList<>();
        for (AgentEntry e : st.seekers.values()) {
            known.add(e.aid());
        }
        for (AgentEntry e : st.lists.lal.values()) {
            if (!e.name().equals(ctx.self()) && !e.name().equals(failed.name())) {
                known.add(e.aid());
            }
        }
        if (known.isEmpty()) {
            for (Address a : st.asked.keySet()) {
                if (!a.equals(failed.transportAddress())) {
                    known.add(ctx.anyAt(a));
                }
            }
        }
        if (!known.isEmpty()) {
            AID pick = known.get(ctx.random().nextInt(known.size()));
            boolean anyone = pick.name().startsWith(Frames.ANY_LOCAL_NAME + "@");
            st.lalCopyFrom = anyone ? null : pick.name();
            st.lalCopyAt = anyone ? Address.parse(pick.addresses().get(0)) : null;
            st.lalCopyUntilNs = ctx.nowNs() + 2_000_000_000L;
            ctx.send(Performative.REQUEST, Protocol.P_LAL, pick, new PlatformMessage.LalRequest(st.term, st.selfEntry));
        }
        MemberRole m = become(new MemberRole(this));
        st.container = null;
        st.successor = failed;
        st.term = Math.max(st.term, join.claimTerm);
        st.lists.lal.put(ctx.self(), st.selfEntry);
        rebuildRoutes();
        st.timeoutMs = Math.max(st.timeoutMs, ctx.config().timeoutMs(st.lists.lal.size()));
        publish();
        m.resetWatch();
    }

    /** The agent stops: it says so (a container to every member, a member to its container). */
    void stop() {
        Role was = current.kind();
        current.leave();
        join.stop();
        if (federation != null) {
            federation.stop();
        }
        if (relay != null) {
            relay.stopGateway();
        }
        PlatformMessage leave = new PlatformMessage.Leave(st.term);
        if (was == Role.CONTAINER) {
            for (AgentEntry e : st.lists.lal.values()) {
                if (!e.name().equals(ctx.self())) {
                    ctx.send(Performative.INFORM, Protocol.P_MAINTENANCE, e.aid(), leave);
                }
            }
        } else if (was == Role.MEMBER && st.container != null && !st.container.name().equals(ctx.self())) {
            ctx.send(Performative.INFORM, Protocol.P_MAINTENANCE, st.container.aid(), leave);
        }
        current = new Stopped(this);
    }

    @Override
    public long term() {
        return st.term;
    }

    @Override
    public long lalSequence() {
        return st.seq;
    }

    /** The federation's lists changed: the container recomputes the GAL. */
    @Override
    public void globalChanged() {
        if (current instanceof ContainerRole c) {
            c.globalChanged();
        }
    }

    /** A container of this host announced itself on the network: the better one stays. */
    @Override
    public void contest(AgentEntry other, long term) {
        if (current instanceof ContainerRole c) {
            c.contest(other, term);
        }
    }

    /** The container's gateway did not start (its port was held): try again. */
    void gatewayRetry() {
        if (relay != null) {
            relay.startGateway();
        }
    }

    /** The LAL's entry lines in pages. */
    @Override
    public List<String> lalPages() {
        return AgentLists.pages(st.lists.lal.values(), ctx.config().maxContentBytes());
    }

    /**
     * Who sent a LAL page: its entry in the page, else in our list, else only its name.
     *
     * @throws IllegalArgumentException if a list of one page does not list its container
     */
    AgentEntry lalClaimant(PlatformMessage.LalPage p, AclMessage m) {
        String from = m.getSender().name();
        AgentEntry by = null;
        for (AgentEntry e : p.page().entries()) {
            if (e.name().equals(from)) {
                by = e;
            }
        }
        if (by == null && p.page().count() == 1) {
            throw new IllegalArgumentException("a LAL must list its container");
        }
        AgentEntry claimed = by != null ? by : st.lists.lal.get(from);
        if (claimed == null) {
            claimed = new AgentEntry(from, m.getSender().addresses().isEmpty() ? "" : m.getSender().addresses().get(0),
                    Long.MAX_VALUE, List.of());
        }
        return claimed;
    }

    /**
     * Asks an agent said to be container, in a frame sealed to it, whether it is: its own answer
     * decides. At most once per maintenance period per name, so that claims cost little.
     */
    void verifyClaim(AgentEntry claimed) {
        long now = ctx.nowNs();
        Long last = verified.get(claimed.name());
        long gapNs = Math.max(1, st.periodMs > 0 ? st.periodMs : ctx.config().basePeriodMs()) * 1_000_000L;
        if (last != null && now - last < gapNs) {
            return;
        }
        verified.put(claimed.name(), now);
        ctx.trace("verify-claim", claimed.name());
        ctx.send(Performative.QUERY_REF, Protocol.P_DISCOVERY, claimed.aid(),
                new PlatformMessage.WhoIsContainer(st.round, st.selfEntry));
    }

    AclMessage replyOf(AclMessage to, Performative act, PlatformMessage content) {
        return ctx.reply(to, act, content);
    }

    void rebuildRoutes() {
        st.lists.rebuildRoutes(ctx.nowNs());
        listsChanged.run();
    }

    /** Only these names' entries changed: only their routes follow (see {@link AgentLists#updateRoutes}). */
    void routesChanged(Collection<String> names) {
        st.lists.updateRoutes(names, ctx.nowNs());
        listsChanged.run();
    }

    void routesChanged(String name) {
        routesChanged(List.of(name));
    }

    void publish() {
        publish.run();
    }

    /** After the agent stopped: the layer dispatches nothing to it any more. */
    private static final class Stopped extends RoleBase {
        Stopped(Roles roles) {
            super(roles);
        }

        @Override
        Role kind() {
            return Role.STOPPED;
        }

        @Override
        void claimed(AgentEntry container, long term, AclMessage m) {
        }
    }
}
