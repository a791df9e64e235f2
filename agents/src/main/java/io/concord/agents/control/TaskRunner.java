package io.concord.agents.control;

import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.ChairSupervisor;
import io.concord.agents.chair.Pose;
import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.Blocked;
import io.concord.agents.proto.WheelchairMessage.Done;
import io.concord.agents.proto.WheelchairMessage.Failed;
import io.concord.agents.proto.WheelchairMessage.MakeWay;
import io.concord.agents.proto.WheelchairMessage.Plan;
import io.concord.agents.proto.WheelchairMessage.Progress;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import java.util.EnumSet;
import java.util.HashMap;
import java.util.Map;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;

/**
 * The control agent's task manager: runs the accepted tasks one after another, each through its
 * phases ({@link ToPickup}, {@link Loading}, {@link ToDropoff}, {@link Unloading}: one class each,
 * which knows what the chair does in it and what follows), reading by reading. It only sequences
 * them: starts the next task, hands each reading and each arrival to the phase under way, has the
 * {@link RouteFollower} drive each leg, and interrupts a phase to step aside or to replan (the
 * phase goes on afterwards toward its goal). It asks for a new plan when a route
 * breaks (a door that does not open, an edge blocked, the traffic agent unable to grant it), steps
 * aside when the traffic agent orders it, drops a task its giver withdraws, and answers each
 * accepted task with INFORM {@code done} or FAILURE and why. Faults the chair reports stop it and
 * fail the task (the e-stop, a trip and a lost link are the {@link ChairSupervisor}'s: they hold
 * the chair and pause the task, see {@link Holds}).
 */
final class TaskRunner {
    /** How the runner gets plans and speaks. */
    interface Agent extends Bidder.Planning {
        /** Sends a message. */
        void send(AclMessage m);

        /** Says something in the agent's log. */
        void say(String s);
    }

    private final ChairSupervisor chair;
    private final HospitalMap map;
    private final TaskQueue tasks;
    private final RouteFollower follower;
    private final DoorClient doors;
    private final TrafficClient traffic;
    private final Agent agent;

    /**
     * The phase under way, or null (idle): the task's, or an {@link Interruption} of it (a step
     * aside, a plan awaited), or an idle chair's way home.
     */
    private Phase phase;
    /** Why the chair reports it cannot drive (said once), or null. */
    private String stopReason;
    /** What the chair waits for, said in its progress reports, or null while it drives. */
    private String waitsFor;

    private static final String WAITS_FOR_ROUTE = "its route (the traffic agent)";

    /**
     * With its patient on board, how long a chair whose way to the drop-off nobody could plan (an
     * edge blocked, no way round) keeps its route before it asks the planner again (ms, the chair's clock).
     */
    static final long REPLAN_AGAIN_MS = 20_000;
    /** The phase that asks for its plan again at {@link #replanAgainAt}, its goal and where it stood; null if none. */
    private Phase replanAgainFor;
    private long replanAgainAt;
    private int replanAgainGoal;
    private int replanAgainFrom;
    /** The chair's clock at its last reading. */
    private long lastReadingMs;
    /** What it says it waits for, made once a door or node (asked at every reading while it waits). */
    private final Map<String, String> doorWaits = new HashMap<>();
    private final Map<Integer, String> turnWaits = new HashMap<>();

    private final RouteFollower.Way way = new RouteFollower.Way() {
        @Override
        public boolean mayDrive(List<Integer> route, List<Integer> standsOn) {
            boolean may = traffic.mayDrive(route, standsOn, makingWay() != null);
            waitsFor = may ? null : WAITS_FOR_ROUTE;
            return may;
        }

        @Override
        public boolean mayGoOn(List<Integer> route, int index) {
            boolean may = traffic.mayGoOn(route, index);
            waitsFor = may ? null : turnWaits.computeIfAbsent(route.get(index), n -> "its turn at node " + n
                    + " (the traffic agent: a chair ahead)");
            return may;
        }

        @Override
        public boolean mayEnter(Edge edge, int fromId, Pose pose) {
            boolean may = doors.mayEnter(edge, fromId, pose);
            waitsFor = may ? null : doorWaits.computeIfAbsent(edge.door(), d -> "door " + d);
            return may;
        }

        @Override
        public void setOff(List<Integer> standsOn) {
            traffic.alive(standsOn);
        }

        @Override
        public void reached(Edge edge, List<Integer> rest) {
            if (edge != null) {
                doors.reached(edge);
            }
            traffic.keepOnly(rest);
            progress(active());
        }
    };

    /** What a phase may do, through this runner. */
    private final Phase.Context context = new Phase.Context() {
        @Override
        public void follow(List<Integer> nodes) {
            TaskRunner.this.follow(nodes);
        }

        @Override
        public void say(String s) {
            TaskRunner.this.say(s);
        }

        @Override
        public void progress(Task t) {
            TaskRunner.this.progress(t);
        }

        @Override
        public void finish(Task t, String failure) {
            TaskRunner.this.finish(t, failure);
        }

        @Override
        public void followBack(List<Integer> nodes) {
            follower.followBack(nodes);
            doors.newRoute();
        }

        @Override
        public void standAt(int node) {
            follower.hold(List.of(node));
        }

        @Override
        public void clearRoute() {
            follower.clear();
        }

        @Override
        public Phase replan(Phase resume, int from, int goal, String why) {
            replanTo(resume, from, goal, why);
            return phase;
        }
    };

    private final RouteFollower.Events events = new RouteFollower.Events() {
        @Override
        public void arrived(long nowMs) {
            TaskRunner.this.arrived(nowMs);
        }

        @Override
        public void broken(int fromId, String why) {
            replan(fromId, why);
        }

        @Override
        public void blocked(int fromId, int toId) {
            say("edge " + fromId + "-" + toId + " blocked for " + RouteFollower.BLOCKED_AFTER_MS / 1000
                    + " s: tells the planner and drives around");
            tellBlocked(fromId, toId);
            replan(fromId, null);
        }

        @Override
        public void say(String s) {
            TaskRunner.this.say(s);
        }
    };


    TaskRunner(ChairSupervisor chair, HospitalMap map, TaskQueue tasks, RouteFollower follower, DoorClient doors,
               TrafficClient traffic, Agent agent) {
        this.chair = chair;
        this.map = map;
        this.tasks = tasks;
        this.follower = follower;
        this.doors = doors;
        this.traffic = traffic;
        this.agent = agent;
    }

    /** What the chair waits for while its task is under way (its route, its turn at a node, a door, a plan), or null. */
    String waitsFor() {
        return waitsFor;
    }

    /** The task under way, or null. */
    Task active() {
        return phase == null ? null : phase.task;
    }

    /** The phase under way, or null. */
    Phase phase() {
        return phase;
    }

    /** The step aside or the way home under way (under a plan awaited, perhaps), or null. */
    private MakingWay makingWay() {
        for (Phase p = phase; p instanceof Interruption i; p = i.resume) {
            if (i instanceof MakingWay m) {
                return m;
            }
        }
        return null;
    }

    /** True while the chair stands until a plan comes (a new route, or its way aside). */
    private boolean awaitsPlan() {
        return phase instanceof Interruption i && i.awaitsPlan();
    }

    private void say(String s) {
        agent.say(s);
    }

    private void send(AclMessage m) {
        agent.send(m);
    }

    private AID planner() {
        return agent.planner();
    }

    private CompletableFuture<AclMessage> plan(AID planner, String task, int from, int to) {
        return agent.plan(planner, task, from, to);
    }

    private CompletableFuture<AclMessage> plan(AID planner, String task, List<Integer> via) {
        return agent.plan(planner, task, via.get(0), via.get(via.size() - 1), via);
    }

    /**
     * Tells whoever gave the task where it stands (its phase, the node last reached, what the chair
     * waits for): at each phase, at each node, and every keep-alive while it is the chair's, so that a
     * chair held up longer than it quoted is not taken for a silent one.
     */
    private void progress(Task t) {
        if (t == null || t.phase() == null) {
            return;
        }
        AclMessage m = t.notice(new Progress(t.id, chair.name(), t.phase(), follower.here(), waitsFor));
        if (m != null) {
            send(m);
        }
    }

    /** The keep-alive: the task under way is reported, however long the chair has waited. */
    void keepAlive() {
        progress(active());
    }

    /** One reading ({@code pose}: where the chair is believed to be; {@code now}: the chair's clock, in ms). */
    void reading(ChairReadings r, Pose pose, long now) {
        lastReadingMs = now;
        if (replanAgainFor != null && now >= replanAgainAt) {
            Phase again = replanAgainFor;
            replanAgainFor = null;
            if (phase == again && follower.here() == replanAgainFrom) {
                // Nothing else happened meanwhile, and it has not driven on along the route it kept.
                if (again instanceof Replanning standing) {
                    phase = standing.resume; // it stood: asks for the phase it interrupted
                }
                replanTo(phase, replanAgainFrom, replanAgainGoal, "it asks again for a way to node " + replanAgainGoal
                        + " for the patient on board");
            }
        }
        if (phase == null) {
            startNext();
            if (phase == null) {
                chair.stop();
                traffic.idle(follower.here());
                return;
            }
        }
        // The phase reads the time first: a patient getting on or off keeps the chair standing,
        // then the next phase begins (to the drop-off), or the task ends (unloaded); a chair
        // waiting for a plan stands.
        Phase next = phase.reading(now, context);
        if (next == null) {
            return;
        }
        if (next == phase && !next.drives()) {
            chair.stop();
            return;
        }
        phase = next;
        if (!faultsAllowDriving(r)) {
            return;
        }
        if (!chair.armed()) {
            chair.stop();
            return;
        }
        follower.step(r, pose, now, way, events);
    }

    /** The doors on the route it drives and on the routes of the tasks it holds, in order. */
    Set<String> doorsAhead() {
        Set<String> ahead = new LinkedHashSet<>();
        if (follower.route() != null) {
            doorsOn(follower.ahead(), ahead);
        }
        for (Task t : tasks.all()) {
            if (t.state == TaskView.State.QUEUED || t == active()) {
                if (t.state.compareTo(TaskView.State.TO_PICKUP) <= 0 && t.toPickup != null) {
                    doorsOn(t.toPickup, ahead);
                }
                if (t.toDropoff != null && t.state.compareTo(TaskView.State.TO_DROPOFF) <= 0) {
                    doorsOn(t.toDropoff, ahead);
                }
            }
        }
        return ahead;
    }

    private void doorsOn(List<Integer> nodes, Set<String> out) {
        for (int i = 1; i < nodes.size(); i++) {
            map.edge(nodes.get(i - 1), nodes.get(i)).map(Edge::door).ifPresent(out::add);
        }
    }

    /** Fails every task accepted and not finished. */
    void failAll(String why) {
        for (Task t : tasks.held()) {
            finish(t, why);
        }
    }

    /** Faults that stop the chair and fail its task; the e-stop, a trip and a lost link are the supervisor's, which pauses it. */
    private boolean faultsAllowDriving(ChairReadings r) {
        Set<ChairFault> faults = EnumSet.noneOf(ChairFault.class);
        faults.addAll(r.faults());
        faults.remove(ChairFault.WATCHDOG);
        faults.remove(ChairFault.LINK);
        if (r.emergencyStop() || !faults.isEmpty()) {
            chair.stop();
            if (stopReason == null) {
                stopReason = r.emergencyStop() ? "the e-stop is pressed" : "the chair reports " + faults;
                say("stops: " + stopReason);
            }
            if (faults.stream().anyMatch(f -> f != ChairFault.BATTERY_LOW)) {
                finish(active(), stopReason);
            }
            return false;
        }
        stopReason = null;
        return true;
    }

    private void startNext() {
        Task t = tasks.nextQueued();
        if (t == null) {
            return;
        }
        phase = new ToPickup(t);
        waitsFor = null;
        progress(t);
        int here = follower.here();
        if (here != t.toPickup.get(0)) {
            // It was planned from where the queue was to end; the chair stands elsewhere.
            say("starts " + t.id + ": to node " + t.from + " from node " + here);
            follower.hold(List.of(here));
            replanTo(phase, here, t.from, null);
            return;
        }
        follow(t.toPickup);
        say("starts " + t.id + ": to node " + t.from + " by " + t.toPickup);
    }

    private void follow(List<Integer> nodes) {
        follower.follow(nodes);
        doors.newRoute();
    }

    private void tellBlocked(int fromId, int toId) {
        AID planner = planner();
        if (planner != null) {
            AclMessage m = new AclMessage(Performative.INFORM);
            m.addReceiver(planner);
            m.setOntology(Services.ONTOLOGY);
            m.setLanguage(Services.LANGUAGE);
            m.setContent(new Blocked(fromId, toId).encode());
            send(m);
        }
    }

    // ---- traffic --------------------------------------------------------------------------------

    /** The traffic agent cannot grant the route (a silent chair stands on it): plan around that node. */
    void refusedByTraffic(int node, String why) {
        List<Integer> route = follower.route();
        if (route == null) {
            return;
        }
        MakingWay aside = makingWay();
        if (aside != null) {
            say("cannot make way to node " + aside.to + ": " + why);
            phase = aside.resume; // a plan awaited for the way aside is dropped with it
            if (phase == null) {
                follower.clear();
                return;
            }
            // The task goes on from where the chair stands: a chair with a task never stands for
            // good because its step aside was taken back (issue 47: it held its node, and the chairs
            // waiting for it waited for ever, in silence).
            resumeTask(follower.here(), why);
            return;
        }
        if (active() == null || phase instanceof Standing) {
            return; // idle, or the leg is driven and the patient gets on or off: nothing to plan
        }
        if (WheelchairMessage.Failure.isWalledIn(why)) {
            if (phase instanceof ToPickup) {
                // Idle chairs nobody can move stand between it and the patient (one of them, beside the
                // patient, can do the task): given back for another chair, not planned round for ever.
                finish(active(), "cannot reach the patient at node " + active().from + ": " + why);
            }
            // With the patient on board (or making way) it keeps its way and asks for it again on the
            // next reading: planned round, it could fail the patient; the monitor's alarms go on.
            return;
        }
        int at = route.indexOf(node);
        if (at > 0) {
            tellBlocked(route.get(at - 1), node);
        }
        follower.trim();
        replan(follower.here(), "the traffic agent cannot grant the route (" + why + ")");
    }

    /** Plans the active task on from {@code here} (after a step aside that ended anywhere but where it was to). */
    private void resumeTask(int here, String why) {
        follower.hold(List.of(here));
        replanTo(phase, here, phase.goal(), "the step aside did not happen (" + why + ")");
    }

    /** The traffic agent's order to step aside for another chair: a plan to the node it names, then on from there. */
    void makeWay(AclMessage m) {
        int from;
        int to;
        List<Integer> way = new java.util.ArrayList<>();
        try {
            MakeWay order = WheelchairMessage.decode(m, MakeWay.class);
            from = order.from();
            to = order.to();
            way.add(from);
            way.addAll(order.path());
            if (way.get(way.size() - 1) != to) {
                throw new IllegalArgumentException("its path " + order.path() + " does not end at node " + to);
            }
            if (!map.hasNode(to)) {
                throw new IllegalArgumentException("no node " + to);
            }
        } catch (IllegalArgumentException e) {
            say("ignores a malformed order to make way: " + e.getMessage());
            return;
        }
        int here = follower.here();
        boolean driving = follower.underWay() && traffic.mayDriveNow(follower.route());
        MakingWay aside = makingWay();
        boolean planning = awaitsPlan();
        // Already on its way aside but not yet granted that way: the new order replaces the old one
        // (refusing it, the chair asked again for the old way, and was ordered again: for ever).
        boolean another = aside != null && !driving && !planning && here == from;
        if (!another && (driving || planning || aside != null || here != from || phase instanceof Standing)) {
            say("cannot make way from node " + from + " to node " + to + (here != from ? ": it is at node " + here
                    : driving ? ": it is under way" : planning ? ": it is waiting for a plan"
                    : aside != null ? ": it is making way to node " + aside.to
                    : ": the patient " + (phase instanceof Loading ? "gets on" : "gets off") + " here"));
            if (!traffic.onRoute(to)) {
                // Not a node its own route takes: the traffic agent held it for the step aside.
                traffic.release(to);
            }
            if (!driving) {
                traffic.reset(); // its wait was dropped for the order: asks again, or says again where it idles
            }
            return;
        }
        if (another && aside.to != to) {
            say("makes way to node " + to + " instead of node " + aside.to);
            traffic.release(aside.to);
        }
        AID planner = planner();
        if (planner == null) {
            traffic.release(to);
            return;
        }
        traffic.reset();
        Phase resume = another ? aside.resume : phase;
        MakingWay mw = resume == null ? new GoingHome(to, map.parking().contains(to)) : new StepAside(resume, to);
        phase = mw;
        waitsFor = "a new plan";
        chair.stop();
        // The way the traffic agent chose, over nodes nobody held: another (the planner's shortest)
        // may cross a node another chair holds, and each then waits for the other.
        plan(planner, "make-way", way).thenAccept(a -> {
            if (phase != mw) {
                return; // taken back meanwhile (another order, the task withdrawn or failed)
            }
            if (a.getPerformative() != Performative.INFORM_REF) {
                say("cannot make way to node " + to + ": " + ControlAgent.reason(a, "no plan"));
                phase = mw.resume;
                traffic.release(to);
                if (phase == null) {
                    follower.clear();
                }
                return;
            }
            mw.planned(WheelchairMessage.decode(a, Plan.class).nodes(), context);
        });
    }

    /** The Medical agent withdrew a task (it gave it to another chair): dropped, and the chair stops if it was driving it. */
    void cancelled(AclMessage m) {
        Task t = tasks.accepted(m.getConversationId());
        if (t == null || t.state.compareTo(TaskView.State.DONE) >= 0) {
            return;
        }
        if (!m.getSender().equals(t.accept.getSender())) {
            say("ignores a CANCEL of " + t.id + " from " + m.getSender().name() + ": only " + t.accept.getSender().name()
                    + ", who gave it, may withdraw it");
            return;
        }
        if (t.patientOnBoard()) {
            // Nobody else can take the patient: the chair that has them drives on to the drop-off.
            say("keeps " + t.id + " although " + m.getSender().localName() + " withdrew it: the patient is on board");
            progress(t);
            return;
        }
        say("task " + t.id + " withdrawn by " + m.getSender().localName());
        t.state = TaskView.State.CANCELLED;
        t.reason = "withdrawn by " + m.getSender().localName();
        if (active() == t) {
            chair.stop();
            phase = null; // and whatever interrupted it: a plan answered later is not followed
            follower.clear();
            traffic.reset();
        }
    }

    /** Asks for a new plan from a node to the end of the current route ({@link #replanTo}). */
    void replan(int fromId, String why) {
        if (follower.route() != null) {
            replanTo(phase, fromId, follower.goal(), why);
        }
    }

    /**
     * Asks for a new plan from a node to {@code goal} for the task of {@code resume}, which goes on
     * along it ({@link Replanning} until the answer comes); fails the task if none comes, unless the
     * patient is on board: then the chair keeps the route it had and asks again after
     * {@link #REPLAN_AGAIN_MS} if it has not driven on meanwhile. Nothing to ask for an idle chair,
     * a chair already waiting for a plan, or one whose patient gets on or off.
     */
    private void replanTo(Phase resume, int fromId, int goal, String why) {
        if (resume == null || resume.task == null || resume instanceof Standing
                || resume instanceof Interruption i && i.awaitsPlan()) {
            return;
        }
        if (why != null) {
            say("replans: " + why);
        }
        AID planner = planner();
        Task t = resume.task;
        replanAgainFor = null; // this plan is the one asked
        if (planner == null) {
            if (t.patientOnBoard()) {
                keepForThePatient(new Replanning(resume, why), fromId, goal, "no planner to replan with", why);
            } else {
                finish(t, "no planner to replan with");
            }
            return;
        }
        Replanning r = new Replanning(resume, why);
        phase = r;
        waitsFor = "a new plan";
        chair.stop();
        plan(planner, t.id + "/replan", fromId, goal).thenAccept(a -> {
            waitsFor = null;
            if (phase != r) {
                return; // the task was withdrawn or failed meanwhile, or its step aside taken back
            }
            if (a.getPerformative() != Performative.INFORM_REF && t.patientOnBoard()) {
                // Nobody else can take the patient (depot seed 190: an edge blocked 15 s on a one-lane
                // map, no way round, and the chair failed the task with its patient on board and took
                // its next one).
                keepForThePatient(r, fromId, goal, ControlAgent.reason(a, "no new plan from " + fromId + " to " + goal), why);
                return;
            }
            phase = a.getPerformative() == Performative.INFORM_REF
                    ? r.answered(WheelchairMessage.decode(a, Plan.class).nodes(), null, context)
                    : r.answered(null, ControlAgent.reason(a, "no new plan from " + fromId + " to " + goal), context);
        });
    }

    /**
     * With its patient on board and no plan to be had ({@code r}, the replanning that got none): the
     * chair keeps its task. If the route it had still leads to the goal, it goes back to the phase
     * it was in along it (it drives on if the way clears); if not (a route held to wait on), it
     * stands. Either way it asks again after {@link #REPLAN_AGAIN_MS} if it has not driven on by
     * then; the fleet monitor's alarm tells the ward if it lasts.
     */
    private void keepForThePatient(Replanning r, int fromId, int goal, String refusal, String why) {
        Task t = r.task;
        boolean drive = follower.leadsTo(goal);
        say("keeps " + t.id + ": " + refusal + (why == null ? "" : " (" + why + ")") + "; the patient is on board, so it "
                + (drive ? "keeps its route" : "stands") + " and asks again in " + REPLAN_AGAIN_MS / 1000 + " s");
        phase = drive ? r.resume : r;
        replanAgainFor = phase;
        replanAgainAt = lastReadingMs + REPLAN_AGAIN_MS;
        replanAgainGoal = goal;
        replanAgainFrom = fromId;
        waitsFor = "a way to node " + goal + " (" + refusal + ")";
        progress(t);
    }

    private void arrived(long now) {
        chair.stop();
        if (phase != null) {
            phase = phase.arrived(now, context);
        }
    }

    private void finish(Task t, String failure) {
        if (t == null) {
            return;
        }
        chair.stop();
        if (replanAgainFor != null && replanAgainFor.task == t) {
            replanAgainFor = null;
        }
        t.state = failure == null ? TaskView.State.DONE : TaskView.State.FAILED;
        t.reason = failure;
        if (t.accept != null) {
            AclMessage reply = t.accept.createReply();
            if (failure == null) {
                reply.setPerformative(Performative.INFORM).setContent(new Done(t.id, t.to, null, null).encode());
                say("done: " + t.id);
            } else {
                reply.setPerformative(Performative.FAILURE).setContent(new Failed(t.id, null, failure).encode());
                say("fails " + t.id + ": " + failure);
            }
            send(reply);
        }
        if (active() == t) {
            phase = null;
            follower.clear();
            stopReason = null;
        }
    }
}
