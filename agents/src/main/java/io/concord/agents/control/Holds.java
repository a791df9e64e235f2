package io.concord.agents.control;

import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.ChairSupervisor;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.Paused;
import io.concord.agents.proto.WheelchairMessage.Refused;
import io.concord.agents.proto.WheelchairMessage.ResumeRequest;
import io.concord.agents.proto.WheelchairMessage.Resumed;
import io.concord.agents.proto.WheelchairMessage.Resuming;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import java.util.function.Supplier;

/**
 * The place of the chair's {@link ChairSupervisor} in the control agent: what a hold means for the
 * tasks, and who decides to resume. A hold pauses the task under way (it does not fail it) and
 * whoever gave the task is told (INFORM {@code paused}, conversation
 * {@code <cfp's>/status}), again each keep-alive while paused, and told again when it resumes
 * (INFORM {@code resumed}). After a trip or a lost link that came back the agent decides to resume
 * by itself, and with no task accepted it resumes whatever the hold but a recurring fault (no motion follows until a
 * task does); after an e-stop, a reboot or a refusal the board did not explain, only an operator
 * does. A link down for the grace time fails the tasks (the Medical agent gives them to another
 * chair).
 */
final class Holds implements ChairSupervisor.Observer {
    /** What the holds act on: the agent's tasks and its ways out. */
    interface Agent {
        /** The task under way, or null. */
        Task active();

        /** Whether any task is accepted and not finished. */
        boolean hasWork();

        /** Fails every task accepted and not finished. */
        void failAll(String why);

        /** Sends a message. */
        void send(AclMessage m);

        /** Runs {@code r} on the agent's loop after {@code ms} of the agent's clock. */
        void after(long ms, Runnable r);

        /** Says something in the agent's log. */
        void say(String s);
    }

    private final ChairSupervisor supervisor;
    /** The agent's name: who decided, when the agent resumes. */
    private final Supplier<String> name;
    private final Supplier<String> platform;
    private final ResumeAuthority authority;
    private final Agent agent;
    /** Counts the link's outages: a grace timer ends only the outage it was set for. */
    private int outages;
    private long linkGraceMs = ControlAgent.LINK_GRACE_MS;
    private boolean estopSeen;

    Holds(ChairSupervisor supervisor, Supplier<String> name, Agent agent) {
        this(supervisor, name, () -> "", agent, new ResumeAuthority(System::currentTimeMillis));
    }

    /**
     * @param platform  this agent's platform name, to tell its members from agents of other platforms
     * @param authority who may resume (operators and the policy)
     */
    Holds(ChairSupervisor supervisor, Supplier<String> name, Supplier<String> platform, Agent agent, ResumeAuthority authority) {
        this.platform = platform;
        this.authority = authority;
        this.supervisor = supervisor;
        this.name = name;
        this.agent = agent;
    }

    void setLinkGraceMs(long ms) {
        this.linkGraceMs = ms;
    }

    /** A reading came: an e-stop released says what follows; the agent resumes if it may. */
    void reading(ChairReadings r) {
        if (estopSeen && !r.emergencyStop() && supervisor.state() == ChairSupervisor.State.HELD
                && !supervisor.hold().agentMayResume() && agent.hasWork()) {
            agent.say("the e-stop of " + supervisor.name() + " is released: the chair stays held until an operator resumes it");
        }
        estopSeen = r.emergencyStop();
        decideToResume();
    }

    /** The link went down (the tasks are kept for the grace time) or came back (the agent resumes if it may). */
    void online(boolean up) {
        String chair = supervisor.name();
        agent.say(up ? "the link to " + chair + " is up" : "the link to " + chair + " is down: the chair is stopped by its board");
        if (!up) {
            supervisor.stop();
            int outage = ++outages;
            if (agent.hasWork()) {
                agent.say("keeps its tasks for " + linkGraceMs / 1000.0 + " s while the link is down");
                long grace = linkGraceMs;
                agent.after(grace, () -> {
                    if (outage == outages && !supervisor.online()) {
                        agent.failAll(chair + " has been offline for " + grace / 1000.0 + " s");
                    }
                });
            }
        } else {
            decideToResume();
        }
    }

    /** The supervisor holds the chair: the task is paused, and whoever gave it is told why. */
    @Override
    public void onHold(ChairSupervisor.Hold hold) {
        String how = hold.agentMayResume() ? "it resumes when the chair can drive again" : "it waits for an operator's resume";
        Task active = agent.active();
        if (active != null) {
            active.paused = hold + "; " + how;
            agent.say("pauses " + active.id + ": " + hold + "; " + how);
            notice(active, new Paused(active.id, supervisor.name(), active.paused, agentResumes()));
        } else {
            agent.say("holds " + supervisor.name() + ": " + hold);
        }
    }

    /** The chair is armed again after a resume: a paused task goes on. */
    @Override
    public void onArmed(String decidedBy) {
        Task active = agent.active();
        if (active != null && active.paused != null) {
            active.paused = null;
            agent.say("resumes " + active.id + " (decided by " + decidedBy + ")");
            notice(active, new Resumed(active.id, supervisor.name(), "decided by " + decidedBy, agentResumes()));
        }
    }

    /** While the task under way is paused, whoever gave it is told again. */
    void keepAlive() {
        Task active = agent.active();
        if (active != null && active.paused != null) {
            notice(active, new Paused(active.id, supervisor.name(), active.paused, agentResumes()));
        }
    }

    /**
     * The agent's own decision to resume: after a trip or a link that came back, or with no task
     * accepted at all (no motion follows until a task is); never after an e-stop, a reboot or an
     * unexplained refusal while it holds a task, nor after a fault that recurred too often
     * ({@link ChairSupervisor.Hold#repeated()}), task or not.
     */
    private void decideToResume() {
        if (supervisor.state() != ChairSupervisor.State.HELD || !supervisor.online() || supervisor.estopPressed()) {
            return;
        }
        ChairSupervisor.Hold h = supervisor.hold();
        if (h.agentMayResume()) {
            supervisor.resume(name.get() + " (" + h + ")");
        } else if (!agent.hasWork() && h.repeated() == null && h.cause() != ChairSupervisor.Cause.OPERATOR
                && supervisor.operatorStop() == null) {
            // A fault that recurs waits for an operator even with no task: the next task would meet it.
            supervisor.resume(name.get() + " (" + h + "; no task accepted)");
        }
    }

    /** An operator's resume, said in the log: null if resuming, else why not. */
    String resume(String who) {
        String why = supervisor.resume(who);
        agent.say(why == null ? "resume decided by " + who : "cannot resume (" + who + "): " + why);
        return why;
    }

    /**
     * REQUEST {@code resume-request}: an operator's resume through a message, carried by a member
     * with the operator's signed order ({@link ResumeAuthority}); the answer says whether it resumes.
     * A member that holds only the platform key, an agent of another platform, a forged, replayed or
     * stale order: refused with the reason, said in the log and counted.
     */
    void resumeAsked(AclMessage m) {
        String why;
        try {
            ResumeRequest r = WheelchairMessage.decode(m, ResumeRequest.class);
            // Who asks comes first: whoever may not resume learns nothing of the chair's state.
            ResumeAuthority.Verdict v = authority.ofMessage(m, r.order(), supervisor.name(), platform.get());
            if (!v.allowed()) {
                why = v.refusal();
                agent.say("refuses the resume of " + supervisor.name() + " asked by " + m.getSender().name() + ": " + why);
            } else if (supervisor.armed()) {
                // As the console's form answers: a chair that is not held has nothing to resume.
                why = supervisor.name() + " is not held: it is armed and drives as its tasks ask; nothing to resume";
            } else {
                String by = r.by() != null && !r.by().isBlank() && !r.by().equals(v.operator()) ? v.operator() + " (" + r.by() + ")" : v.operator();
                why = resume(by + " via " + m.getSender().localName());
            }
        } catch (IllegalArgumentException e) {
            why = e.getMessage();   // a request that does not read resumes nothing
        }
        agent.send(m.createReply().setPerformative(why == null ? Performative.INFORM : Performative.REFUSE)
                .setContent(why == null ? new Resuming(supervisor.name()).encode() : Refused.because(why).encode()));
    }

    /** An operator's signed order given in this process (the console): null if resuming, else why not (said and counted). */
    String resumeOrdered(String order) {
        ResumeAuthority.Verdict v = authority.ofOrder(order, supervisor.name());
        if (!v.allowed()) {
            agent.say("refuses a resume of " + supervisor.name() + ": " + v.refusal());
            return v.refusal();
        }
        return resume(v.operator());
    }

    ResumeAuthority authority() {
        return authority;
    }

    /** Whether the agent resumes by itself after the hold (else an operator does). */
    private boolean agentResumes() {
        return supervisor.hold().agentMayResume();
    }

    /** Tells whoever gave the task how it stands (paused, resumed), outside the contract's conversation. */
    private void notice(Task t, WheelchairMessage notice) {
        AclMessage m = t.notice(notice);
        if (m != null) {
            agent.send(m);
        }
    }
}
