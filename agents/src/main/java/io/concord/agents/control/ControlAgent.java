package io.concord.agents.control;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairEvent;
import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairSupervisor;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Localiser;
import io.concord.agents.chair.Pose;
import io.concord.agents.chair.PoseController;
import io.concord.agents.map.Door;
import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Node;
import io.concord.agents.map.Point;
import io.concord.agents.proto.Asks;
import io.concord.agents.proto.Content;
import io.concord.core.agent.Inbox;
import io.concord.agents.proto.Services;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.proto.ContractNetResponder;
import io.concord.core.proto.FipaProtocols;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.Platform;
import io.concord.layers.platform.ServiceDescription;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;

/**
 * The reactive agent, one per chair, on the chair's {@link ChairDriver} (simulated or real).
 *
 * <ul>
 *   <li>Answers the Medical agent's CFP ({@code transport; task; from; to; priority; unload}) after
 *       asking its planner for two plans (from where its queue ends to the patient, and from the
 *       patient to the destination): PROPOSE {@code proposal; task; cost; path; unload}, or REFUSE
 *       with the reason (no route, a node unknown, no planner).</li>
 *   <li>Queues accepted tasks and executes them in order: drives to the patient, waits the load
 *       time, drives to the destination, waits the unload time, and answers the ACCEPT with
 *       INFORM {@code done}, or FAILURE with why.</li>
 *   <li>Drives on its odometry corrected by floor markers: to each node of the plan, on the
 *       graph's lines; asks each door on the plan to open (REQUEST {@code open}) ahead of
 *       it and waits in front until it is open for the chair, and tells it once past (INFORM
 *       {@code passed}); stops for anything close ahead and slows down for anything nearer than
 *       1.2 m, whatever the plan says; reports an edge blocked for 15 s to its planner and drives
 *       a new plan around it.</li>
 *   <li>Drives through a {@link ChairSupervisor} (made around the driver it is given, unless it is
 *       given one): an e-stop, a watchdog trip, a board's reboot, a refusal or a lost link holds
 *       the chair; the task is paused, not failed, and the Medical agent is told (INFORM
 *       {@code paused; task; chair; reason; resume}, conversation {@code <cfp's>/status}, again
 *       every 20 s while paused) and told again when it resumes (INFORM {@code resumed}). After a
 *       trip or a lost link that came back, the agent decides to resume; after an e-stop, a reboot
 *       or a refusal the board did not explain, only an operator does ({@link #resume}, or
 *       REQUEST {@code resume; by}). While the chair cannot drive it refuses new tasks, saying why,
 *       with {@code unavailable true} (the Medical agent asks again later). A link down for
 *       {@link #LINK_GRACE_MS} fails its tasks.</li>
 * </ul>
 */
public class ControlAgent extends Agent implements ChairListener, ChairSupervisor.Observer {
    /** Metres a second the estimates assume (cruise power, turns and slowing included). */
    static final double EST_SPEED_MPS = 0.7;
    /** Seconds each door adds to an estimate. */
    static final double EST_DOOR_S = 6;
    private static final double STOP_M = 0.45;
    private static final double STOP_IR_M = 0.3;
    private static final double SLOW_M = 1.2;
    private static final double ANNOUNCE_M = 4.0;
    private static final double WAIT_AT_DOOR_M = 2.3;
    private static final long BLOCKED_AFTER_MS = 15_000;
    /** How often it tells the doors ahead that it still means to pass (their sessions lapse after 60 s). */
    static final long KEEPALIVE_MS = 20_000;
    /** How long a chair's link may stay down before its tasks fail (the Medical agent then gives them to another chair). */
    public static final long LINK_GRACE_MS = 30_000;

    private final ChairSupervisor supervisor;
    private final ChairDriver chair;
    /** Counts the link's outages: a grace timer ends only the outage it was set for. */
    private int outages;
    private long linkGraceMs = LINK_GRACE_MS;
    private boolean estopSeen;
    private final HospitalMap map;
    private final Consumer<String> log;
    private final PoseController control = new PoseController(60, 30, 0.12, Math.toRadians(5));
    private final Localiser localiser = new Localiser();
    private final List<Task> tasks = new ArrayList<>();
    private Asks asks;
    private ContractNetResponder responder;

    // driving
    private Task active;
    private List<Integer> route;
    private int index;
    private long pauseUntilMs = -1;
    private String doorAsked;
    private String doorGranted;
    private String doorPassing;
    private long stoppedSinceMs = -1;
    private boolean replanning;
    private int lastNode = -1;
    private String stopReason;
    /** The node the chair drives to on the edge it is on, or -1 at a node. */
    private int edgeTo = -1;

    // traffic: the routes it drives are granted by the traffic agent, if there is one
    private TrafficClient traffic;
    /** The node it steps aside to for another chair (the traffic agent's order), or -1. */
    private int asideTo = -1;

    /**
     * @param chair the chair it drives
     * @param map   the map its plans are on
     * @param log   told of what the chair does (tasks, doors, stops)
     */
    public ControlAgent(ChairDriver chair, HospitalMap map, Consumer<String> log) {
        this.supervisor = chair instanceof ChairSupervisor s ? s : new ChairSupervisor(chair);
        this.chair = supervisor;
        this.map = map;
        this.log = log;
    }

    @Override
    protected void setup() {
        Platform.of(this).register(ServiceDescription.of(Services.TRANSPORT, getLocalName()).withProperty("chair", chair.name()));
        asks = new Asks(this);
        addBehaviour(asks);
        responder = new ContractNetResponder(this, ContractNetResponder.createMessageTemplate(FipaProtocols.CONTRACT_NET)) {
            @Override
            protected AclMessage handleCfp(AclMessage cfp) {
                evaluate(cfp);
                return null;
            }

            @Override
            protected AclMessage handleAcceptProposal(AclMessage cfp, AclMessage propose, AclMessage accept) {
                Task t = find(cfp);
                if (t != null) {
                    t.accept = accept;
                    t.state = TaskView.State.QUEUED;
                    say("task " + t.id + " accepted, queued (" + queued() + " in the queue)");
                }
                return null;
            }

            @Override
            protected void handleRejectProposal(AclMessage cfp, AclMessage propose, AclMessage reject) {
                Task t = find(cfp);
                if (t != null) {
                    tasks.remove(t);
                }
            }
        };
        addBehaviour(responder);
        traffic = new TrafficClient(this, asks, this::refusedByTraffic);
        Inbox.each(this, MessageTemplate.matchPerformative(Performative.INFORM).and(MessageTemplate.matchOntology(Services.ONTOLOGY))
                .and(m -> m.getContent() != null && m.getContent().startsWith("make-way")), this::makeWay);
        Inbox.each(this, MessageTemplate.matchPerformative(Performative.CANCEL), this::cancelled);
        Inbox.each(this, MessageTemplate.matchPerformative(Performative.REQUEST).and(MessageTemplate.matchOntology(Services.ONTOLOGY))
                .and(m -> m.getContent() != null && m.getContent().startsWith("resume")), this::resumeAsked);
        // A chair that waits (loading, queued) is not silent: it keeps its doors' sessions alive.
        addBehaviour(new io.concord.core.agent.TickerBehaviour(this, KEEPALIVE_MS) {
            @Override
            protected void onTick() {
                keepDoorsAlive();
                traffic.alive(standsOn());
                if (active != null && active.paused != null) {
                    notice(active, "paused", active.paused);
                }
            }
        });
        supervisor.setObserver(this);
        chair.setListener(this);
    }

    private void keepDoorsAlive() {
        java.util.Set<String> ahead = new java.util.LinkedHashSet<>();
        if (route != null) {
            doorsOn(route.subList(Math.max(0, index - 1), route.size()), ahead);
        }
        for (Task t : tasks) {
            if (t.state == TaskView.State.QUEUED || t == active) {
                if (t.state.compareTo(TaskView.State.TO_PICKUP) <= 0 && t.toPickup != null) {
                    doorsOn(t.toPickup, ahead);
                }
                if (t.toDropoff != null && t.state.compareTo(TaskView.State.TO_DROPOFF) <= 0) {
                    doorsOn(t.toDropoff, ahead);
                }
            }
        }
        for (String id : ahead) {
            AID agent = doorAgent(id);
            if (agent != null) {
                AclMessage m = new AclMessage(Performative.INFORM);
                m.addReceiver(agent);
                m.setOntology(Services.ONTOLOGY);
                m.setContent(Content.of("here").with("body", chair.name()).toString());
                send(m);
            }
        }
    }

    private void doorsOn(List<Integer> nodes, java.util.Set<String> out) {
        for (int i = 1; i < nodes.size(); i++) {
            map.edge(nodes.get(i - 1), nodes.get(i)).map(Edge::door).ifPresent(out::add);
        }
    }

    @Override
    protected void takeDown() {
        chair.stop();
        chair.setListener(null);
    }

    /** The tasks it holds, in order, with their states. */
    public List<TaskView> tasks() {
        return tasks.stream().map(Task::view).toList();
    }

    /** Where it believes the chair is. */
    public Pose pose() {
        return localiser.pose();
    }

    /** The plan it is driving now (node ids), or an empty list. */
    public List<Integer> route() {
        return route == null ? List.of() : List.copyOf(route);
    }

    private void say(String s) {
        log.accept(getLocalName() + ": " + s);
    }

    private Task find(AclMessage cfp) {
        for (Task t : tasks) {
            if (t.cfp.getConversationId() != null && t.cfp.getConversationId().equals(cfp.getConversationId())) {
                return t;
            }
        }
        return null;
    }

    private int queued() {
        int n = 0;
        for (Task t : tasks) {
            if (t.state == TaskView.State.QUEUED) {
                n++;
            }
        }
        return n;
    }

    // ---- evaluation -----------------------------------------------------------------------------

    private void evaluate(AclMessage cfp) {
        Content c;
        Task t;
        try {
            c = Content.parse(cfp.getContent());
            t = new Task(c.text("task"), c.integer("from"), c.integer("to"), c.number("priority", 0), c.number("unload", 0), cfp);
        } catch (IllegalArgumentException e) {
            responder.respond(cfp, cfp.createReply().setPerformative(Performative.REFUSE)
                    .setContent(Content.of("refuse").with("reason", e.getMessage()).toString()));
            return;
        }
        tasks.add(t);
        String unavailable = supervisor.whyNotAvailable();
        if (unavailable != null) {
            refuse(t, chair.name() + " " + unavailable, true);
            return;
        }
        AID planner = planner();
        if (planner == null) {
            refuse(t, "no planner for " + chair.name() + " in the yellow pages");
            return;
        }
        int start = queueEnd();
        t.start = start;
        plan(planner, t.id + "/pickup", start, t.from).thenAccept(first -> {
            if (first.getPerformative() != Performative.INFORM_REF) {
                refuse(t, reason(first, "no plan from node " + start + " to node " + t.from));
                return;
            }
            plan(planner, t.id + "/dropoff", t.from, t.to).thenAccept(second -> {
                if (second.getPerformative() != Performative.INFORM_REF) {
                    refuse(t, reason(second, "no plan from node " + t.from + " to node " + t.to));
                    return;
                }
                Content p1 = Content.parse(first.getContent());
                Content p2 = Content.parse(second.getContent());
                t.toPickup = nodes(p1);
                t.toDropoff = nodes(p2);
                double approach = p1.number("length") / EST_SPEED_MPS + EST_DOOR_S * p1.list("doors").size();
                t.pathS = p2.number("length") / EST_SPEED_MPS + EST_DOOR_S * p2.list("doors").size();
                t.estimateS = approach + t.unloadS + t.pathS + t.unloadS;
                t.costS = queueSeconds() + t.estimateS;
                // The proposals still open that the cost counts, each with its seconds: the Medical
                // agent takes out those another chair has won.
                StringBuilder pending = new StringBuilder();
                for (Task o : tasks) {
                    if (o != t && o.state == TaskView.State.PROPOSED) {
                        pending.append(pending.length() == 0 ? "" : ",").append(o.id).append(':')
                                .append(String.format(Locale.ROOT, "%.1f", o.estimateS));
                    }
                }
                t.state = TaskView.State.PROPOSED;
                say(String.format(Locale.ROOT, "proposes for %s: cost %.1f s, path %.1f s, unload %.0f s", t.id, t.costS,
                        t.pathS, t.unloadS));
                Content proposal = Content.of("proposal").with("task", t.id).with("cost", t.costS).with("path", t.pathS)
                        .with("unload", t.unloadS);
                responder.respond(t.cfp, t.cfp.createReply().setPerformative(Performative.PROPOSE).setContent(
                        (pending.length() == 0 ? proposal : proposal.with("pending", pending)).toString()));
            });
        });
    }

    private static String reason(AclMessage m, String dflt) {
        if (m == null) {
            return "the planner did not answer";
        }
        try {
            String r = Content.parse(m.getContent()).get("reason");
            return r != null ? r : dflt;
        } catch (IllegalArgumentException e) {
            return dflt;
        }
    }

    private static List<Integer> nodes(Content plan) {
        List<Integer> out = new ArrayList<>();
        for (String s : plan.list("nodes")) {
            out.add(Integer.parseInt(s));
        }
        return out;
    }

    private void refuse(Task t, String why) {
        refuse(t, why, false);
    }

    /** Refuses a task; {@code unavailable}: the chair cannot drive now, and may later. */
    private void refuse(Task t, String why, boolean unavailable) {
        t.state = TaskView.State.REFUSED;
        t.reason = why;
        tasks.remove(t);
        say("refuses " + t.id + ": " + why);
        Content c = Content.of("refuse").with("task", t.id).with("reason", why);
        responder.respond(t.cfp, t.cfp.createReply().setPerformative(Performative.REFUSE)
                .setContent((unavailable ? c.with("unavailable", "true") : c).toString()));
    }

    /** A plan, as the planner's final answer (never null: no answer becomes a FAILURE). */
    private CompletableFuture<AclMessage> plan(AID planner, String task, int from, int to) {
        AclMessage req = new AclMessage(Performative.REQUEST);
        req.addReceiver(planner);
        req.setProtocol(FipaProtocols.REQUEST);
        req.setOntology(Services.ONTOLOGY);
        req.setContent(Content.of("plan").with("task", task).with("from", from).with("to", to).toString());
        return asks.ask(req, 10_000, null).thenApply(a -> a != null ? a
                : new AclMessage(Performative.FAILURE).setContent(Content.of("no-route")
                        .with("reason", "the planner did not answer within 10 s").toString()));
    }

    private AID planner() {
        for (AgentEntry e : Platform.of(this).searchCopy(ServiceDescription.ofType(Services.PLANNER))) {
            for (ServiceDescription s : e.services()) {
                if (s.type().equals(Services.PLANNER) && chair.name().equals(s.properties().get("chair"))) {
                    return e.aid();
                }
            }
        }
        return null;
    }

    /** The node the queue ends at: the last queued task's destination, or the node nearest the chair. */
    private int queueEnd() {
        for (int i = tasks.size() - 1; i >= 0; i--) {
            Task t = tasks.get(i);
            if (t.toDropoff != null && t.state.compareTo(TaskView.State.QUEUED) >= 0 && t.state.compareTo(TaskView.State.UNLOADING) <= 0) {
                return t.to;
            }
        }
        return nearestNode();
    }

    /**
     * Seconds of work ahead: the queued and running tasks, and those it has proposed for and not
     * heard back of (auctions run at once: a chair that counted only accepted work proposed the
     * same short cost for every one of them, and won them all while the other chairs stood).
     */
    private double queueSeconds() {
        double s = 0;
        for (Task t : tasks) {
            if (t.state == TaskView.State.PROPOSED
                    || t.state.compareTo(TaskView.State.QUEUED) >= 0 && t.state.compareTo(TaskView.State.UNLOADING) <= 0) {
                s += t.estimateS;
            }
        }
        return s;
    }

    private int nearestNode() {
        Pose p = localiser.pose();
        if (p == null) {
            ChairReadings r = chair.latest();
            p = r == null ? null : r.fix() != null ? r.fix() : r.odometry();
        }
        int best = -1;
        double bd = Double.MAX_VALUE;
        for (Node n : map.nodes()) {
            double d = p == null ? 0 : p.distanceTo(n.at().x(), n.at().y());
            if (d < bd) {
                bd = d;
                best = n.id();
            }
        }
        return best;
    }

    // ---- execution ------------------------------------------------------------------------------

    @Override
    public void onReadings(ChairReadings r) {
        if (getState() != State.ACTIVE) {
            return;
        }
        Pose pose = localiser.update(r);
        // Loading, unloading and stalls are timed on the chair's clock.
        long now = r.timeNs() / 1_000_000;
        if (estopSeen && !r.emergencyStop() && supervisor.state() == ChairSupervisor.State.HELD
                && !supervisor.hold().cause().agentMayResume() && hasWork()) {
            say("the e-stop of " + chair.name() + " is released: the chair stays held until an operator resumes it");
        }
        estopSeen = r.emergencyStop();
        decideToResume();
        if (active == null && asideTo < 0) {
            startNext(now);
            if (active == null) {
                chair.stop();
                if (!replanning) {
                    traffic.idle(here());
                }
                return;
            }
        }
        if (now < pauseUntilMs) {
            chair.stop();
            return;
        }
        switch (active == null ? TaskView.State.QUEUED : active.state) {
            case LOADING -> {
                active.state = TaskView.State.TO_DROPOFF;
                follow(active.toDropoff);
                say("drives " + active.id + " to node " + active.to + " by " + active.toDropoff);
            }
            case UNLOADING -> {
                finish(active, null);
                return;
            }
            default -> { }
        }
        if (replanning) {
            chair.stop();
            return;
        }
        if (!faultsAllowDriving(r)) {
            return;
        }
        if (!supervisor.armed()) {
            chair.stop();
            return;
        }
        drive(r, pose, now);
    }

    /** The link to the chair went down or came back (a serial chair; a simulated one is always online). */
    @Override
    public void onOnline(boolean up) {
        if (getState() != State.ACTIVE) {
            return;
        }
        say(up ? "the link to " + chair.name() + " is up" : "the link to " + chair.name() + " is down: the chair is stopped by its board");
        if (!up) {
            chair.stop();
            int outage = ++outages;
            if (hasWork()) {
                say("keeps its tasks for " + linkGraceMs / 1000.0 + " s while the link is down");
                long grace = linkGraceMs;
                addBehaviour(new io.concord.core.agent.WakerBehaviour(this, grace) {
                    @Override
                    protected void onWake() {
                        if (outage == outages && !chair.online()) {
                            failAll(chair.name() + " has been offline for " + grace / 1000.0 + " s");
                        }
                    }
                });
            }
        } else {
            decideToResume();
        }
    }

    /** The board said something that is not a reading; the supervisor has acted on it already. */
    @Override
    public void onEvent(ChairEvent event) {
        if (event.kind() == ChairEvent.Kind.INCOMPATIBLE) {
            say("cannot drive " + chair.name() + ": " + event.detail());
        }
    }

    // ---- holds and resumes ----------------------------------------------------------------------

    /** The supervisor holds the chair: the task is paused, and whoever gave it is told why. */
    @Override
    public void onHold(ChairSupervisor.Hold hold) {
        String how = hold.cause().agentMayResume() ? "it resumes when the chair can drive again" : "it waits for an operator's resume";
        if (active != null) {
            active.paused = hold + "; " + how;
            say("pauses " + active.id + ": " + hold + "; " + how);
            notice(active, "paused", active.paused);
        } else {
            say("holds " + chair.name() + ": " + hold);
        }
    }

    /** The chair is armed again after a resume: a paused task goes on. */
    @Override
    public void onArmed(String decidedBy) {
        if (active != null && active.paused != null) {
            active.paused = null;
            say("resumes " + active.id + " (decided by " + decidedBy + ")");
            notice(active, "resumed", "decided by " + decidedBy);
        }
    }

    /**
     * The agent's own decision to resume: after a trip or a link that came back, or with no task
     * accepted at all (no motion follows until a task is); never after an e-stop, a reboot or an
     * unexplained refusal while it holds a task.
     */
    private void decideToResume() {
        if (supervisor.state() != ChairSupervisor.State.HELD || !chair.online() || supervisor.estopPressed()) {
            return;
        }
        ChairSupervisor.Hold h = supervisor.hold();
        if (h.cause().agentMayResume()) {
            supervisor.resume(getLocalName() + " (" + h + ")");
        } else if (!hasWork()) {
            supervisor.resume(getLocalName() + " (" + h + "; no task accepted)");
        }
    }

    /**
     * An operator's decision to resume a held chair (the console, or any code). Thread-safe.
     * Completes with null once resuming, or with why it cannot (offline, the e-stop still pressed).
     *
     * @param who who decided, for the log and the Medical agent
     */
    public CompletableFuture<String> resume(String who) {
        CompletableFuture<String> f = new CompletableFuture<>();
        Runnable r = () -> f.complete(resumeNow(who));
        if (runtime().inLoop()) {
            r.run();
        } else {
            runtime().execute(r);
        }
        return f;
    }

    /** An operator's resume, said in the log: null if resuming, else why not. */
    private String resumeNow(String who) {
        String why = supervisor.resume(who);
        say(why == null ? "resume decided by " + who : "cannot resume (" + who + "): " + why);
        return why;
    }

    private void resumeAsked(AclMessage m) {
        String by = m.getSender().localName();
        try {
            String b = Content.parse(m.getContent()).get("by");
            if (b != null && !b.isBlank()) {
                by = b + " via " + m.getSender().localName();
            }
        } catch (IllegalArgumentException e) {
            // no content beyond the word: the sender decided
        }
        String why = resumeNow(by);
        send(m.createReply().setPerformative(why == null ? Performative.INFORM : Performative.REFUSE)
                .setContent(why == null ? Content.of("resuming").with("chair", chair.name()).toString()
                        : Content.of("refuse").with("reason", why).toString()));
    }

    /** How long the link may stay down before its tasks fail ({@link #LINK_GRACE_MS} unless set). Call on the loop. */
    public void setLinkGraceMs(long ms) {
        this.linkGraceMs = ms;
    }

    /** The safety supervisor the agent drives through. */
    public ChairSupervisor supervisor() {
        return supervisor;
    }

    /** Tells whoever gave the task how it stands (paused, resumed), outside the contract's conversation. */
    private void notice(Task t, String what, String reason) {
        if (t.accept == null) {
            return;
        }
        AclMessage m = new AclMessage(Performative.INFORM);
        m.addReceiver(t.accept.getSender());
        m.setOntology(Services.ONTOLOGY);
        m.setConversationId(t.cfp.getConversationId() + "/status");
        m.setContent(Content.of(what).with("task", t.id).with("chair", chair.name()).with("reason", reason)
                .with("resume", supervisor.hold().cause().agentMayResume() ? "agent" : "operator").toString());
        send(m);
    }

    private boolean hasWork() {
        for (Task t : tasks) {
            if (t.state.compareTo(TaskView.State.QUEUED) >= 0 && t.state.compareTo(TaskView.State.UNLOADING) <= 0) {
                return true;
            }
        }
        return false;
    }

    private void failAll(String why) {
        for (Task t : new ArrayList<>(tasks)) {
            if (t.state.compareTo(TaskView.State.QUEUED) >= 0 && t.state.compareTo(TaskView.State.UNLOADING) <= 0) {
                finish(t, why);
            }
        }
    }

    /** Faults that stop the chair and fail its task; the e-stop, a trip and a lost link are the supervisor's, which pauses it. */
    private boolean faultsAllowDriving(ChairReadings r) {
        java.util.Set<ChairFault> faults = java.util.EnumSet.noneOf(ChairFault.class);
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
                finish(active, stopReason);
            }
            return false;
        }
        stopReason = null;
        return true;
    }

    private void startNext(long now) {
        for (Task t : tasks) {
            if (t.state == TaskView.State.QUEUED) {
                active = t;
                t.state = TaskView.State.TO_PICKUP;
                int here = here();
                if (here != t.toPickup.get(0)) {
                    // It was planned from where the queue was to end; the chair stands elsewhere.
                    say("starts " + t.id + ": to node " + t.from + " from node " + here);
                    route = List.of(here);
                    replanTo(here, t.from, null);
                    return;
                }
                follow(t.toPickup);
                say("starts " + t.id + ": to node " + t.from + " by " + t.toPickup);
                return;
            }
        }
    }

    /** The node the chair stands at or last reached. */
    private int here() {
        return lastNode >= 0 ? lastNode : nearestNode();
    }

    /** The nodes the chair stands on: the last it reached, and the one it drives to if it is on an edge. */
    private List<Integer> standsOn() {
        List<Integer> at = new ArrayList<>();
        at.add(here());
        if (edgeTo >= 0 && edgeTo != at.get(0)) {
            at.add(edgeTo);
        }
        return at;
    }

    private void follow(List<Integer> nodes) {
        route = new ArrayList<>(nodes);
        index = 1;
        doorAsked = null;
        doorGranted = null;
        stoppedSinceMs = -1;
        lastNode = nodes.get(0);
    }

    private void drive(ChairReadings r, Pose pose, long now) {
        if (route == null) {
            chair.stop();
            return;
        }
        if (index >= route.size()) {
            arrived(now);
            return;
        }
        if (!traffic.mayDrive(route, standsOn(), asideTo >= 0)) {
            chair.stop();
            return;
        }
        if (index == 0) {
            Point first = map.node(route.get(0)).at();
            if (control.reached(pose, first.x(), first.y())) {
                index = 1;
                lastNode = route.get(0);
                edgeTo = -1;
                traffic.keepOnly(route);
            } else {
                PoseController.Powers p = control.toPoint(pose, first.x(), first.y());
                chair.drive(p.left() * 0.5, p.right() * 0.5);
            }
            return;
        }
        int fromId = route.get(index - 1);
        int toId = route.get(index);
        Edge edge = map.edge(fromId, toId).orElse(null);
        if (edge == null) {
            replan(fromId, "the plan has no edge " + fromId + "-" + toId);
            return;
        }
        // On the graph's line, to the node itself: the traffic agent never lets two chairs on one
        // edge, and on the line a chair passes over every node's floor marker (a chair kept 0.6 m
        // right of the line missed the markers once its heading had drifted 3 degrees in a spot
        // turn, and met a door's jamb 0.85 m off course: seed 156 of the soak).
        Point target = map.node(toId).at();
        if (control.reached(pose, target.x(), target.y())) {
            if (edge.door() != null && edge.door().equals(doorPassing)) {
                tellPassed(edge.door());
            }
            lastNode = toId;
            edgeTo = -1;
            index++;
            stoppedSinceMs = -1;
            traffic.keepOnly(route.subList(index - 1, route.size()));
            if (index >= route.size()) {
                arrived(now);
            }
            return;
        }
        if (edge.door() != null && !door(edge, fromId, pose)) {
            chair.stop();
            return;
        }
        if (edgeTo != toId) {
            edgeTo = toId;
            traffic.alive(standsOn()); // sets off along the edge: its body now takes both ends
        }
        double front = r.range(chair.layout().sensorIndex("front"));
        double irl = r.range(chair.layout().sensorIndex("ir-front-left"));
        double irr = r.range(chair.layout().sensorIndex("ir-front-right"));
        PoseController.Powers p = control.toPoint(pose, target.x(), target.y());
        // A turn on the spot moves nothing forward: the stop zone lets it turn away from what is ahead.
        boolean spotTurn = Math.abs(p.left() + p.right()) < 1e-9 && p.left() != 0;
        if (!spotTurn && (front < STOP_M || irl < STOP_IR_M || irr < STOP_IR_M)) {
            chair.stop();
            if (stoppedSinceMs < 0) {
                stoppedSinceMs = now;
                say(String.format(Locale.ROOT, "stops: something %.2f m ahead", Math.min(front, Math.min(irl, irr))));
            } else if (now - stoppedSinceMs > BLOCKED_AFTER_MS) {
                stoppedSinceMs = -1;
                blocked(fromId, toId);
            }
            return;
        }
        stoppedSinceMs = -1;
        double scale = front < SLOW_M && !spotTurn ? 0.35 : 1;
        chair.drive(p.left() * scale, p.right() * scale);
    }

    /** Handles the door of the edge being driven; true if the chair may go on. */
    private boolean door(Edge edge, int fromId, Pose pose) {
        String id = edge.door();
        if (id.equals(doorGranted) || id.equals(doorPassing)) {
            doorPassing = id;
            return true;
        }
        Door d = map.door(id);
        double dist = pose.distanceTo(d.centre().x(), d.centre().y());
        if (dist > ANNOUNCE_M) {
            return true;
        }
        if (!id.equals(doorAsked)) {
            AID agent = doorAgent(id);
            if (agent == null) {
                replan(fromId, "door " + id + " has no agent");
                return false;
            }
            doorAsked = id;
            AclMessage req = new AclMessage(Performative.REQUEST);
            req.addReceiver(agent);
            req.setProtocol(FipaProtocols.REQUEST);
            req.setOntology(Services.ONTOLOGY);
            req.setContent(Content.of("open").with("body", chair.name()).toString());
            say("asks door " + id + " to open");
            asks.ask(req, 60_000, agree -> { }).thenAccept(a -> {
                if (!id.equals(doorAsked)) {
                    return;
                }
                if (a != null && a.getPerformative() == Performative.INFORM) {
                    doorGranted = id;
                    say("door " + id + " is open for it");
                } else {
                    doorAsked = null;
                    replan(fromId, "door " + id + (a == null ? " did not open within 60 s" : " answered " + a.getPerformative()
                            + ": " + reason(a, "")));
                }
            });
        }
        // Wait out of the leaf's way: beyond a revolving door's sweep by the chair's half length and
        // its braking distance (at 2.2 m from a 3.2 m door the nose of a chair that braked there was
        // inside the circle, and the leaf hit it).
        double wait = d.kind() == Door.Kind.ROTATING ? Math.max(WAIT_AT_DOOR_M, d.width() / 2 + 1.2) : WAIT_AT_DOOR_M;
        return dist > wait;
    }

    private void tellPassed(String id) {
        AID agent = doorAgent(id);
        if (agent != null) {
            AclMessage m = new AclMessage(Performative.INFORM);
            m.addReceiver(agent);
            m.setOntology(Services.ONTOLOGY);
            m.setContent(Content.of("passed").with("body", chair.name()).toString());
            send(m);
        }
        doorPassing = null;
        doorGranted = null;
        doorAsked = null;
    }

    private AID doorAgent(String id) {
        for (AgentEntry e : Platform.of(this).searchCopy(ServiceDescription.of(Services.DOOR, id))) {
            return e.aid();
        }
        return null;
    }

    private void blocked(int fromId, int toId) {
        say("edge " + fromId + "-" + toId + " blocked for " + BLOCKED_AFTER_MS / 1000 + " s: tells the planner and drives around");
        tellBlocked(fromId, toId);
        replan(fromId, null);
    }

    private void tellBlocked(int fromId, int toId) {
        AID planner = planner();
        if (planner != null) {
            AclMessage m = new AclMessage(Performative.INFORM);
            m.addReceiver(planner);
            m.setOntology(Services.ONTOLOGY);
            m.setContent(Content.of("blocked").with("from", fromId).with("to", toId).toString());
            send(m);
        }
    }

    // ---- traffic --------------------------------------------------------------------------------

    /** The traffic agent cannot grant the route (a silent chair stands on it): plan around that node. */
    private void refusedByTraffic(int node, String why) {
        if (route == null) {
            return;
        }
        if (asideTo >= 0) {
            say("cannot make way to node " + asideTo + ": " + why);
            asideTo = -1;
            route = null;
            return;
        }
        if (active == null) {
            return;
        }
        int at = route.indexOf(node);
        if (at > 0) {
            tellBlocked(route.get(at - 1), node);
        }
        route = new ArrayList<>(route.subList(Math.max(0, index - 1), route.size()));
        replan(here(), "the traffic agent cannot grant the route (" + why + ")");
    }

    /** The traffic agent's order to step aside for another chair: a plan to the node it names, then on from there. */
    private void makeWay(AclMessage m) {
        int from;
        int to;
        try {
            Content c = Content.parse(m.getContent());
            from = c.integer("from");
            to = c.integer("to");
            if (!map.hasNode(to)) {
                throw new IllegalArgumentException("no node " + to);
            }
        } catch (IllegalArgumentException e) {
            say("ignores a malformed order to make way: " + e.getMessage());
            return;
        }
        boolean driving = route != null && index < route.size() && traffic.mayDriveNow(route);
        if (driving || replanning || asideTo >= 0 || here() != from) {
            say("cannot make way from node " + from + " to node " + to + (here() != from ? ": it is at node " + here()
                    : ": it is under way"));
            traffic.release(to);
            if (!driving) {
                traffic.reset(); // its wait was dropped for the order: asks again, or says again where it idles
            }
            return;
        }
        AID planner = planner();
        if (planner == null) {
            traffic.release(to);
            return;
        }
        traffic.reset();
        asideTo = to;
        replanning = true;
        chair.stop();
        plan(planner, "make-way", from, to).thenAccept(a -> {
            replanning = false;
            if (asideTo != to) {
                return;
            }
            if (a.getPerformative() != Performative.INFORM_REF) {
                say("cannot make way to node " + to + ": " + reason(a, "no plan"));
                asideTo = -1;
                traffic.release(to);
                if (active == null) {
                    route = null;
                }
                return;
            }
            List<Integer> nodes = nodes(Content.parse(a.getContent()));
            say("makes way for another chair: to node " + to + " by " + nodes);
            follow(nodes);
        });
    }

    /** The Medical agent withdrew a task (it gave it to another chair): dropped, and the chair stops if it was driving it. */
    private void cancelled(AclMessage m) {
        Task t = null;
        for (Task x : tasks) {
            if (x.accept != null && m.getConversationId() != null && m.getConversationId().equals(x.cfp.getConversationId())) {
                t = x;
            }
        }
        if (t == null || t.state.compareTo(TaskView.State.DONE) >= 0) {
            return;
        }
        if (!m.getSender().equals(t.accept.getSender())) {
            say("ignores a CANCEL of " + t.id + " from " + m.getSender().name() + ": only " + t.accept.getSender().name()
                    + ", who gave it, may withdraw it");
            return;
        }
        say("task " + t.id + " withdrawn by " + m.getSender().localName());
        t.state = TaskView.State.CANCELLED;
        t.reason = "withdrawn by " + m.getSender().localName();
        if (active == t) {
            chair.stop();
            active = null;
            route = null;
            asideTo = -1;
            pauseUntilMs = -1;
            traffic.reset();
        }
    }

    /** Asks for a new plan from a node to the end of the current route; fails the task if none comes. */
    private void replan(int fromId, String why) {
        replanTo(fromId, route.get(route.size() - 1), why);
    }

    /** Asks for a new plan from a node to {@code goal} for the active task; fails the task if none comes. */
    private void replanTo(int fromId, int goal, String why) {
        if (replanning || active == null) {
            return;
        }
        if (why != null) {
            say("replans: " + why);
        }
        AID planner = planner();
        Task t = active;
        if (planner == null) {
            finish(t, "no planner to replan with");
            return;
        }
        replanning = true;
        chair.stop();
        plan(planner, t.id + "/replan", fromId, goal).thenAccept(a -> {
            replanning = false;
            if (active != t) {
                return;
            }
            if (a.getPerformative() != Performative.INFORM_REF) {
                finish(t, reason(a, "no new plan from " + fromId + " to " + goal) + (why == null ? "" : " (" + why + ")"));
                return;
            }
            List<Integer> nodes = nodes(Content.parse(a.getContent()));
            // Back along the edge it was on to the node the new plan starts from (the last one it
            // reached), then along the new plan: never across the floor off the graph.
            follow(nodes);
            index = 0;
            say("new plan " + nodes);
        });
    }

    private void arrived(long now) {
        chair.stop();
        if (asideTo >= 0) {
            int here = asideTo;
            asideTo = -1;
            route = null;
            say("has made way at node " + here);
            if (active == null) {
                return; // idle here: said on the next reading
            }
            int goal = active.state == TaskView.State.TO_PICKUP ? active.from : active.to;
            if (goal != here) {
                route = List.of(here);
                replanTo(here, goal, null);
                return;
            }
        }
        if (active == null) {
            return;
        }
        if (active.state == TaskView.State.TO_PICKUP) {
            active.state = TaskView.State.LOADING;
            pauseUntilMs = now + (long) (active.unloadS * 1000);
            say("at node " + active.from + ": the patient gets on (" + (long) active.unloadS + " s)");
        } else if (active.state == TaskView.State.TO_DROPOFF) {
            active.state = TaskView.State.UNLOADING;
            pauseUntilMs = now + (long) (active.unloadS * 1000);
            say("at node " + active.to + ": the patient gets off (" + (long) active.unloadS + " s)");
        }
    }

    private void finish(Task t, String failure) {
        if (t == null) {
            return;
        }
        chair.stop();
        t.state = failure == null ? TaskView.State.DONE : TaskView.State.FAILED;
        t.reason = failure;
        if (t.accept != null) {
            AclMessage reply = t.accept.createReply();
            if (failure == null) {
                reply.setPerformative(Performative.INFORM).setContent(Content.of("done").with("task", t.id)
                        .with("node", t.to).toString());
                say("done: " + t.id);
            } else {
                reply.setPerformative(Performative.FAILURE).setContent(Content.of("failed").with("task", t.id)
                        .with("reason", failure).toString());
                say("fails " + t.id + ": " + failure);
            }
            send(reply);
        }
        if (active == t) {
            active = null;
            route = null;
            stopReason = null;
            asideTo = -1;
        }
    }

    @Override
    public String toString() {
        return "ControlAgent[" + getLocalName() + " on " + chair.name() + " tasks " + Arrays.toString(tasks().toArray()) + "]";
    }
}
