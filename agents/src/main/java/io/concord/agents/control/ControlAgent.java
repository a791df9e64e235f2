package io.concord.agents.control;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairEvent;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.ChairSupervisor;
import io.concord.agents.chair.Pose;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.proto.Asks;
import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.Clear;
import io.concord.agents.proto.WheelchairMessage.MakeWay;
import io.concord.agents.proto.WheelchairMessage.NoRoute;
import io.concord.agents.proto.WheelchairMessage.PlanRequest;
import io.concord.agents.proto.WheelchairMessage.ResumeRequest;
import io.concord.layers.authority.Operators;
import io.concord.layers.authority.Policy;
import io.concord.layers.authority.SignedOrder;
import io.concord.layers.defence.Defence;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Inbox;
import io.concord.core.agent.TickerBehaviour;
import io.concord.core.agent.WakerBehaviour;
import io.concord.core.proto.ContractNetResponder;
import io.concord.core.proto.FipaProtocols;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.Platform;
import io.concord.layers.platform.ServiceDescription;

import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;

/**
 * The reactive agent, one per chair, on the chair's {@link ChairDriver} (simulated or real).
 *
 * <ul>
 *   <li>Answers the Medical agent's CFP ({@code transport-call}) after
 *       asking its planner for two plans (from where its queue ends to the patient, and from the
 *       patient to the destination): PROPOSE {@code proposal}, or REFUSE
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
 *       {@code paused}, conversation {@code <cfp's>/status}, again
 *       every 20 s while paused) and told again when it resumes (INFORM {@code resumed}). After a
 *       trip or a lost link that came back, the agent decides to resume; after an e-stop, a reboot
 *       or a refusal the board did not explain, only an operator does ({@link #resume}, or
 *       REQUEST {@code resume-request}). While the chair cannot drive it refuses new tasks, saying why,
 *       with {@code unavailable true} (the Medical agent asks again later). A link down for
 *       {@link #LINK_GRACE_MS} fails its tasks.</li>
 * </ul>
 *
 * <p>The work is done by parts, which this class wires and speaks for: the {@link Bidder} (the
 * CFP's evaluation and the proposal's cost, over a {@link TaskQueue}), the {@link RouteFollower}
 * (the chair along a route, its stop and slow zones), the {@link DoorClient} and the
 * {@link TrafficClient} (the doors and the traffic agent, asked before the chair moves), and the
 * {@link ChairSupervisor} (the chair's safety: nothing drives the chair but through it). This
 * class keeps what ties them together: which task is under way and what it waits for, when to
 * replan, to make way, to resume.
 */
public class ControlAgent extends Agent implements ChairListener {
    /** How often it tells the doors ahead that it still means to pass (their sessions lapse after 60 s). */
    static final long KEEPALIVE_MS = 20_000;
    /** How long a chair's link may stay down before its tasks fail (the Medical agent then gives them to another chair). */
    public static final long LINK_GRACE_MS = 30_000;

    private final ChairSupervisor supervisor;
    private final ChairDriver chair;
    /** The stop and slow zones between the route follower and the supervisor: every drive command passes them. */
    private final io.concord.agents.chair.ObstacleFilter obstacles;
    private final HospitalMap map;
    private final Consumer<String> log;
    private final TaskQueue tasks = new TaskQueue();
    private final RouteFollower follower;
    private final Holds holds;
    private final ResumeAuthority authority;
    private Asks asks;
    private ContractNetResponder responder;
    private Bidder bidder;
    private DoorClient doors;
    /** The routes it drives are granted by the traffic agent, if there is one. */
    private TrafficClient traffic;
    private TaskRunner runner;
    private final Ports ports = new Ports();

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
        this.obstacles = new io.concord.agents.chair.ObstacleFilter(supervisor);
        this.follower = new RouteFollower(obstacles, map);
        this.authority = new ResumeAuthority(() -> runtime() == null ? System.currentTimeMillis() : runtime().clock().epochMillis());
        this.holds = new Holds(supervisor, this::getLocalName, () -> getAID() == null ? "" : getAID().platform(), ports, authority);
    }

    @Override
    protected void setup() {
        // An agent that drives a chair is not killed by a message: any holder of the platform key
        // is a member, and a member may ask any other agent to leave (the observation service).
        io.concord.layers.observe.ObserverLayer observer = runtime().layer(getAID(), io.concord.layers.observe.ObserverLayer.class);
        if (observer != null && authority.checks()) {
            observer.guard(Policy.Service.OBSERVE_KILL, getLocalName() + " drives " + chair.name()
                    + ": it is not killed by a message; stop it where it runs (its ward's JVM, or the console there)");
        }
        Platform.of(this).register(ServiceDescription.of(Services.TRANSPORT, getLocalName()).withProperty("chair", chair.name()));
        asks = new Asks(this);
        addBehaviour(asks);
        responder = new ContractNetResponder(this, ContractNetResponder.createMessageTemplate(FipaProtocols.CONTRACT_NET)) {
            @Override
            protected AclMessage handleCfp(AclMessage cfp) {
                bidder.evaluate(cfp);
                return null;
            }

            @Override
            protected AclMessage handleAcceptProposal(AclMessage cfp, AclMessage propose, AclMessage accept) {
                Task t = tasks.ofCfp(cfp);
                if (t != null) {
                    t.accept = accept;
                    t.state = TaskView.State.QUEUED;
                    say("task " + t.id + " accepted, queued (" + tasks.queued() + " in the queue)");
                }
                return null;
            }

            @Override
            protected void handleRejectProposal(AclMessage cfp, AclMessage propose, AclMessage reject) {
                Task t = tasks.ofCfp(cfp);
                if (t != null) {
                    tasks.remove(t);
                }
            }
        };
        addBehaviour(responder);
        bidder = new Bidder(tasks, chair.name(), ports, supervisor::whyNotAvailable, follower::nearestNode,
                (cfp, reply) -> responder.respond(cfp, reply), this::say);
        doors = new DoorClient(ports, map, chair.name(), (from, why) -> runner.replan(from, why), this::say);
        traffic = new TrafficClient(ports, (node, why) -> runner.refusedByTraffic(node, why));
        runner = new TaskRunner(supervisor, map, tasks, follower, doors, traffic, ports);
        MessageTemplate ours = MessageTemplate.matchOntology(Services.ONTOLOGY);
        Inbox.each(this, ours.and(WheelchairMessage.matching(MakeWay.class)), m -> runner.makeWay(m));
        // Every clear (one read before its grant is kept for it, a stale one ignored: none stays in the mailbox) and a FAILURE of the granted route.
        Inbox.each(this, ours.and(WheelchairMessage.matching(Clear.class).or(traffic::isAboutGrant)), traffic::aboutGrant);
        Inbox.each(this, MessageTemplate.matchPerformative(Performative.CANCEL), m -> runner.cancelled(m));
        MessageTemplate resume = WheelchairMessage.matching(ResumeRequest.class);
        Inbox.each(this, resume, holds::resumeAsked);
        // Any other REQUEST is answered, saying what is wrong or what this agent takes.
        Inbox.each(this, MessageTemplate.matchPerformative(Performative.REQUEST).and(MessageTemplate.not(resume)),
                m -> WheelchairMessage.notTaken(m, "a control agent takes resume-request (and the Medical agent's CFPs)", this::send));
        // A chair that waits (loading, queued) is not silent: it keeps its doors' sessions alive.
        addBehaviour(new TickerBehaviour(this, KEEPALIVE_MS) {
            @Override
            protected void onTick() {
                doors.keepAlive(runner.doorsAhead());
                traffic.alive(follower.standsOn());
                holds.keepAlive();
                runner.keepAlive();
            }
        });
        supervisor.setObserver(holds);
        chair.setListener(this);
    }

    @Override
    protected void takeDown() {
        chair.stop();
        chair.setListener(null);
    }

    /** The tasks it holds, in order, with their states. */
    public List<TaskView> tasks() {
        return tasks.views();
    }

    /**
     * What the chair waits for while a task is under way, as its progress reports say it: {@code
     * its route (the traffic agent)}, {@code its turn at node N ...}, {@code door D}, {@code a new
     * plan}; null while it drives or has nothing to do. Loop thread (tests, console, benchmark).
     */
    public String waitingFor() {
        return runner == null ? null : runner.waitsFor();
    }

    /** Where it believes the chair is. */
    public Pose pose() {
        return follower.pose();
    }

    /** The plan it is driving now (node ids), or an empty list. */
    public List<Integer> route() {
        return follower.route() == null ? List.of() : List.copyOf(follower.route());
    }

    private void say(String s) {
        log.accept(getLocalName() + ": " + s);
    }

    /** The reason an answer gives ({@code reason} in its content), or {@code dflt}. */
    static String reason(AclMessage m, String dflt) {
        if (m == null) {
            return "the planner did not answer";
        }
        String r = WheelchairMessage.reasonOf(m);
        return r != null ? r : dflt;
    }

    // ---- execution ------------------------------------------------------------------------------

    @Override
    public void onReadings(ChairReadings r) {
        if (getState() != State.ACTIVE) {
            return;
        }
        Pose pose = follower.locate(r);
        // Loading, unloading and stalls are timed on the chair's clock.
        long now = r.timeNs() / 1_000_000;
        holds.reading(r);
        runner.reading(r, pose, now);
    }

    /** The link to the chair went down or came back (a serial chair; a simulated one is always online). */
    @Override
    public void onOnline(boolean up) {
        if (getState() == State.ACTIVE) {
            holds.online(up);
        }
    }

    /** The board said something that is not a reading; the supervisor has acted on it already. */
    @Override
    public void onEvent(ChairEvent event) {
        if (event.kind() == ChairEvent.Kind.INCOMPATIBLE) {
            say("cannot drive " + chair.name() + ": " + event.detail());
        }
    }

    // ---- holds and resumes: see Holds --------------------------------------------------------

    /**
     * An operator's decision to resume a held chair (the console, or any code): the operator's order,
     * signed with an operator key the ward configured ({@link #operators}), for this chair
     * ({@code OperatorKey.sign("resume", chair, epochMs)}). Thread-safe. Completes with null once
     * resuming, or with why it cannot (not an operator's order, a replay, offline, the e-stop still pressed).
     */
    public CompletableFuture<String> resume(SignedOrder order) {
        CompletableFuture<String> f = new CompletableFuture<>();
        String text = order.encode();
        Runnable r = () -> f.complete(holds.resumeOrdered(text));
        if (runtime().inLoop()) {
            r.run();
        } else {
            runtime().execute(r);
        }
        return f;
    }

    /**
     * The operators whose signed orders this agent takes (the ward's); none until set, so that no
     * one can resume a chair held for an operator. Thread-safe.
     */
    public void operators(Operators ops) {
        authority.operators(java.util.Objects.requireNonNull(ops, "operators"));
    }

    /**
     * Builds this agent without a defence: only for the tests that show what the defence stands
     * against ({@link Defence#AUTHORITY}: anyone's resume-request resumes the chair, any member's
     * kill ends the agent). Before it starts, or on its loop.
     */
    public ControlAgent withoutDefences(Defence... off) {
        if (java.util.List.of(off).contains(Defence.AUTHORITY)) {
            authority.policy(Policy.allowingEverything());
            io.concord.layers.observe.ObserverLayer observer = getAID() == null ? null
                    : runtime().layer(getAID(), io.concord.layers.observe.ObserverLayer.class);
            if (observer != null) {
                observer.guard(Policy.Service.OBSERVE_KILL, null);   // started already: its guard goes too
            }
        }
        return this;
    }

    /** Resumes refused so far, by kind ({@code foreign}, {@code unsigned}, {@code bad-order}). On the loop or after. */
    public java.util.Map<String, Long> resumeRefusals() {
        return authority.refusals();
    }

    /** How long the link may stay down before its tasks fail ({@link #LINK_GRACE_MS} unless set). Call on the loop. */
    public void setLinkGraceMs(long ms) {
        holds.setLinkGraceMs(ms);
    }

    /** The safety supervisor the agent drives through. */
    public ChairSupervisor supervisor() {
        return supervisor;
    }

    /**
     * The chair's obstacle filter (the stop and slow zones every drive command passes). A test may
     * switch it off ({@code enabled(false)}) to show what it prevents; nothing else does.
     */
    public io.concord.agents.chair.ObstacleFilter obstacleFilter() {
        return obstacles;
    }

    /** The agent as its parts see it: its loop, its yellow pages, its pending asks, its log. */
    private final class Ports implements Holds.Agent, TaskRunner.Agent, DoorClient.Doors, TrafficClient.Port {
        @Override
        public Task active() {
            return runner == null ? null : runner.active();
        }

        @Override
        public boolean hasWork() {
            return tasks.hasWork();
        }

        @Override
        public void failAll(String why) {
            runner.failAll(why);
        }

        @Override
        public void send(AclMessage m) {
            ControlAgent.this.send(m);
        }

        @Override
        public void after(long ms, Runnable r) {
            addBehaviour(new WakerBehaviour(ControlAgent.this, ms) {
                @Override
                protected void onWake() {
                    r.run();
                }
            });
        }

        @Override
        public void say(String s) {
            ControlAgent.this.say(s);
        }

        @Override
        public AID planner() {
            for (AgentEntry e : Platform.of(ControlAgent.this).searchCopy(ServiceDescription.ofType(Services.PLANNER))) {
                for (ServiceDescription s : e.services()) {
                    if (s.type().equals(Services.PLANNER) && chair.name().equals(s.properties().get("chair"))) {
                        return e.aid();
                    }
                }
            }
            return null;
        }

        /** A plan, as the planner's final answer (never null: no answer becomes a FAILURE). */
        @Override
        public CompletableFuture<AclMessage> plan(AID planner, String task, int from, int to, List<Integer> via) {
            AclMessage req = new AclMessage(Performative.REQUEST);
            req.addReceiver(planner);
            req.setProtocol(FipaProtocols.REQUEST);
            req.setOntology(Services.ONTOLOGY);
            req.setLanguage(Services.LANGUAGE);
            req.setContent(new PlanRequest(task, from, to, null, via).encode());
            return asks.ask(req, 10_000, null).thenApply(a -> a != null ? a
                    : new AclMessage(Performative.FAILURE).setContent(new NoRoute(null, "the planner did not answer within 10 s").encode()));
        }

        /** The traffic agent's estimate of the waits along {@code path} (QUERY-REF wait-estimate); 0 without one or an answer in 2 s. */
        @Override
        public CompletableFuture<Double> waits(List<Integer> path) {
            AID traffic = trafficAgent();
            if (traffic == null || path.size() < 2) {
                return CompletableFuture.completedFuture(0.0);
            }
            AclMessage q = new AclMessage(Performative.QUERY_REF);
            q.addReceiver(traffic);
            q.setProtocol(FipaProtocols.QUERY);
            q.setOntology(Services.ONTOLOGY);
            q.setLanguage(Services.LANGUAGE);
            q.setContent(new io.concord.agents.proto.WheelchairMessage.WaitEstimate(path, null).encode());
            return asks.ask(q, 2_000, null).thenApply(a -> {
                if (a == null || a.getPerformative() != Performative.INFORM_REF) {
                    return 0.0;
                }
                try {
                    Double s = io.concord.agents.proto.WheelchairMessage.decode(a, io.concord.agents.proto.WheelchairMessage.WaitEstimate.class).seconds();
                    return s == null ? 0.0 : s;
                } catch (IllegalArgumentException e) {
                    return 0.0;
                }
            });
        }

        @Override
        public AID trafficAgent() {
            for (AgentEntry e : Platform.of(ControlAgent.this).searchCopy(ServiceDescription.ofType(Services.TRAFFIC))) {
                return e.aid();
            }
            return null;
        }

        @Override
        public AID agentOf(String door) {
            for (AgentEntry e : Platform.of(ControlAgent.this).searchCopy(ServiceDescription.of(Services.DOOR, door))) {
                return e.aid();
            }
            return null;
        }

        @Override
        public CompletableFuture<AclMessage> ask(AclMessage request, long timeoutMs) {
            return asks.ask(request, timeoutMs, null);
        }
    }

    @Override
    public String toString() {
        return "ControlAgent[" + getLocalName() + " on " + chair.name() + " tasks " + Arrays.toString(tasks().toArray()) + "]";
    }
}
