package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.net.Address;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * An agent's part in the platform, as an object (as JGroups' GMS swaps its implementation on a
 * view change): it handles the platform messages by their type, owns its fields and its timers,
 * and its timers are cancelled together when the role is left. What every role answers alike is
 * here; what differs is in {@link SeekingRole}, {@link MemberRole} and {@link ContainerRole}.
 */
abstract class RoleBase implements PlatformMessage.Handler {
    final Roles roles;
    final PlatformContext ctx;
    final PlatformState st;
    private final Set<Long> timers = new LinkedHashSet<>();

    RoleBase(Roles roles) {
        this.roles = roles;
        this.ctx = roles.ctx;
        this.st = roles.st;
    }

    abstract Role kind();

    /** A timer of this role: cancelled when the role is left. */
    final long after(long ms, Runnable task) {
        long[] id = new long[1];
        id[0] = ctx.after(ms, () -> {
            timers.remove(id[0]);
            task.run();
        });
        timers.add(id[0]);
        return id[0];
    }

    final long cancel(long id) {
        if (id >= 0) {
            timers.remove(id);
            ctx.cancel(id);
        }
        return -1;
    }

    /** The role is left: every timer of it is cancelled. */
    void leave() {
        for (long id : timers) {
            ctx.cancel(id);
        }
        timers.clear();
    }

    /** Holds a candidate of the election, unless {@link PlatformState#MAX_SEEKERS} are held (counted). */
    void addSeeker(AgentEntry e) {
        if (!st.addSeeker(e)) {
            ctx.drop("seekers-limit", PlatformState.MAX_SEEKERS + " agents are seeking a container already; "
                    + e.name() + " is not taken as a candidate");
        }
    }

    // ---- answered alike in every role --------------------------------------------------------

    /** Who is container: the one this agent follows, or "seeking" (and the asker is a candidate). */
    @Override
    public void onWhoIsContainer(PlatformMessage.WhoIsContainer w, AclMessage m) {
        AgentEntry asker = w.asker();
        PlatformMessage answer;
        if (st.container != null && kind() != Role.SEEKING) {
            answer = new PlatformMessage.ContainerIs(st.term, st.container, st.selfEntry);
        } else {
            addSeeker(asker);
            answer = new PlatformMessage.Seeking(st.round, st.maxTermSeen, st.selfEntry);
        }
        // Answered to whoever holds the asker's port, as it asked: sealed with the platform key, so
        // that discovery costs no signed handshake per pair of agents.
        AclMessage reply = roles.replyOf(m, Performative.INFORM, answer);
        if (st.fromAny) {
            reply.clearAllReceiver();
            Address back = asker.transportAddress();
            reply.addReceiver(back != null ? ctx.anyAt(back) : asker.aid());
        }
        // Asked in a frame sealed to this agent (a claim being checked): answered the same way,
        // so that the answer is authenticated too.
        ctx.sendQuietly(reply);
    }

    @Override
    public void onSeeking(PlatformMessage.Seeking s, AclMessage m) {
        markAnswered(m);
        st.maxTermSeen = Math.max(st.maxTermSeen, s.term());
    }

    @Override
    public void onContainerIs(PlatformMessage.ContainerIs c, AclMessage m) {
        markAnswered(m);
        if (c.container().name().equals(ctx.self())) {
            return;
        }
        boolean ownClaim = (!st.fromAny || !st.claimCheck) && c.container().name().equals(m.getSender().name());
        if (!ownClaim && kind() != Role.SEEKING) {
            // A member or a container changes sides only on the claimed container's own word,
            // sealed to it; anything else is a hint, and the claimed container is asked itself.
            roles.verifyClaim(c.container());
            return;
        }
        if (!st.fromAny || !st.claimCheck) {
            st.maxTermSeen = Math.max(st.maxTermSeen, c.term());
        }
        claimed(c.container(), c.term(), m);
    }

    /** Another agent is container, says a container message. */
    abstract void claimed(AgentEntry container, long term, AclMessage m);

    /** A join's confirmation: the agent becomes a member of the container it joined. */
    @Override
    public void onJoined(PlatformMessage.Joined j, AclMessage m) {
        if (!roles.join.to(j.by().name())) {
            return; // an old confirmation
        }
        roles.join.stop();
        roles.becomeMember(j.by(), j.term(), j.period(), j.timeout());
    }

    /** The last valid LAL this agent holds, sent as its container sent it. */
    @Override
    public void onLalRequest(PlatformMessage.LalRequest r, AclMessage m) {
        if (st.lists.lal.isEmpty()) {
            return;
        }
        List<String> p = roles.lalPages();
        String container = st.container == null ? "" : st.container.name();
        for (int i = 0; i < p.size(); i++) {
            ctx.sendQuietly(roles.replyOf(m, Performative.INFORM_REF, new PlatformMessage.LalCopy(st.term, st.seq, container,
                    PlatformMessage.Page.of(i, p.size(), p.get(i)))));
        }
    }

    /** Says which container this agent follows, to an agent that follows a worse one. */
    final void tellBetter(AID to) {
        if (st.container != null) {
            ctx.send(Performative.INFORM, Protocol.P_DISCOVERY, to,
                    new PlatformMessage.ContainerIs(st.term, st.container, st.selfEntry));
        }
    }

    private void markAnswered(AclMessage m) {
        Address a = addressOf(m.getSender());
        if (a != null && st.asked.containsKey(a)) {
            st.asked.put(a, Boolean.TRUE);
        }
    }

    private static Address addressOf(AID aid) {
        for (String uri : aid.addresses()) {
            Address a = Address.parse(uri);
            if (a != null) {
                return a;
            }
        }
        return null;
    }

    /** True if (t1, c1) is a better container claim than (t2, c2): a later term, else the elder. */
    static boolean beats(long t1, AgentEntry c1, long t2, AgentEntry c2) {
        if (c2 == null) {
            return true;
        }
        if (t1 != t2) {
            return t1 > t2;
        }
        return AgentEntry.SENIORITY.compare(c1, c2) < 0;
    }
}
