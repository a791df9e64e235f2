package io.concord.agents.proto;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.content.AgentAction;
import io.concord.core.content.Concept;
import io.concord.core.content.Element;
import io.concord.core.content.Slot;

import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;

/**
 * The wheelchair agents' messages as types (docs/wheelchair-protocol.md): one record per meaning,
 * and the ontology {@value Services#ONTOLOGY} built from them. A record is an element of that
 * ontology (an agent action for what is asked, a concept for what is said), named by its
 * {@link Element}, its components its slots; its {@link #encode()} is its content in FIPA-SL,
 * readable on the wire: {@code ((transport-call :from 3 :priority 3.0 :task T1 :to 9 :unload 60.0))}.
 * A message is decoded once, from its performative and its content together (each record is sent
 * under its own performatives), and checked against the ontology as it is decoded: a slot
 * missing, of the wrong type or refused by the record fails the decoding, naming the slot.
 *
 * <p>An optional field is null when absent (and not written); a list is empty when absent, but
 * {@link Here#at()} and {@link PlanRequest#via()}, which are null when not said.
 */
public sealed interface WheelchairMessage {

    /** The content as it goes on the wire: FIPA-SL under the ontology {@value Services#ONTOLOGY}. */
    default String encode() {
        return Codec.encode(this);
    }

    /**
     * The ontology {@value Services#ONTOLOGY}: the records' schemas, for a reader of its own (its
     * {@code fromAbs} turns core's abstract content, such as {@code ContentManager.extractAbs}
     * gives, into these records).
     */
    static io.concord.core.content.Ontology ontology() {
        return Codec.ONTOLOGY;
    }

    /** Hands this message to the handler's method for its type. */
    void to(Handler h, AclMessage m);

    /** The word the content starts with. */
    default String verb() {
        return Codec.verb(getClass());
    }

    /** One method per record; by default each goes to {@link #unknown}, which ignores it. */
    interface Handler {
        /** A word this handler does not take, the codec's or one it does not know under the message's performative. */
        default void unknown(String verb, AclMessage m) { }

        default void onTransportCall(TransportCall w, AclMessage m) { unknown(w.verb(), m); }
        default void onTransportRequest(TransportRequest w, AclMessage m) { unknown(w.verb(), m); }
        default void onProposal(Proposal w, AclMessage m) { unknown(w.verb(), m); }
        default void onRefused(Refused w, AclMessage m) { unknown(w.verb(), m); }
        default void onAward(Award w, AclMessage m) { unknown(w.verb(), m); }
        default void onRejection(Rejection w, AclMessage m) { unknown(w.verb(), m); }
        default void onWithdrawal(Withdrawal w, AclMessage m) { unknown(w.verb(), m); }
        default void onCancelRequest(CancelRequest w, AclMessage m) { unknown(w.verb(), m); }
        default void onDone(Done w, AclMessage m) { unknown(w.verb(), m); }
        default void onFailed(Failed w, AclMessage m) { unknown(w.verb(), m); }
        default void onPaused(Paused w, AclMessage m) { unknown(w.verb(), m); }
        default void onResumed(Resumed w, AclMessage m) { unknown(w.verb(), m); }
        default void onProgress(Progress w, AclMessage m) { unknown(w.verb(), m); }
        default void onResumeRequest(ResumeRequest w, AclMessage m) { unknown(w.verb(), m); }
        default void onResuming(Resuming w, AclMessage m) { unknown(w.verb(), m); }
        default void onPlanRequest(PlanRequest w, AclMessage m) { unknown(w.verb(), m); }
        default void onPlanAgreed(PlanAgreed w, AclMessage m) { unknown(w.verb(), m); }
        default void onPlan(Plan w, AclMessage m) { unknown(w.verb(), m); }
        default void onNoRoute(NoRoute w, AclMessage m) { unknown(w.verb(), m); }
        default void onBlocked(Blocked w, AclMessage m) { unknown(w.verb(), m); }
        default void onStateQuery(StateQuery w, AclMessage m) { unknown(w.verb(), m); }
        default void onDoorState(DoorState w, AclMessage m) { unknown(w.verb(), m); }
        default void onPassRequest(PassRequest w, AclMessage m) { unknown(w.verb(), m); }
        default void onPassConfirmed(PassConfirmed w, AclMessage m) { unknown(w.verb(), m); }
        default void onOpenRequest(OpenRequest w, AclMessage m) { unknown(w.verb(), m); }
        default void onOpenQueued(OpenQueued w, AclMessage m) { unknown(w.verb(), m); }
        default void onDoorOpen(DoorOpen w, AclMessage m) { unknown(w.verb(), m); }
        default void onFailure(Failure w, AclMessage m) { unknown(w.verb(), m); }
        default void onPassed(Passed w, AclMessage m) { unknown(w.verb(), m); }
        default void onHere(Here w, AclMessage m) { unknown(w.verb(), m); }
        default void onReserve(Reserve w, AclMessage m) { unknown(w.verb(), m); }
        default void onGranted(Granted w, AclMessage m) { unknown(w.verb(), m); }
        default void onWaitEstimate(WaitEstimate w, AclMessage m) { unknown(w.verb(), m); }

        default void onClear(Clear w, AclMessage m) { unknown(w.verb(), m); }
        default void onReserveWaits(ReserveWaits w, AclMessage m) { unknown(w.verb(), m); }
        default void onRelease(Release w, AclMessage m) { unknown(w.verb(), m); }
        default void onIdle(Idle w, AclMessage m) { unknown(w.verb(), m); }
        default void onMakeWay(MakeWay w, AclMessage m) { unknown(w.verb(), m); }
        default void onStalled(Stalled w, AclMessage m) { unknown(w.verb(), m); }
    }

    /** A message that says why (a refusal, a failure, a pause). */
    interface Reasoned {
        /** Why; null only where the record's field is optional. */
        String reason();
    }

    // ---- a transport: Medical <-> chairs (Contract Net), the desk -> Medical ------------------------

    /** CFP {@code transport-call}, Medical -> every control agent; every slot given. */
    @Element(name = "transport-call")
    record TransportCall(@Slot(mandatory = true) String task, int from, int to, double priority, double unload)
            implements WheelchairMessage, AgentAction {
        public void to(Handler h, AclMessage m) {
            h.onTransportCall(this, m);
        }
    }

    /**
     * REQUEST {@code transport-request} to the Medical agent, which answers AGREE with this very text;
     * priority (TP, 0 to 3) is 0 and unload (0 to 3600 s) 60 when absent.
     */
    @Element(name = "transport-request")
    record TransportRequest(int from, int to, Double priority, Double unload) implements WheelchairMessage, AgentAction {
        public TransportRequest {
            priority = priority == null ? 0.0 : priority;
            unload = unload == null ? 60.0 : unload;
            if (!(priority >= 0 && priority <= 3)) {
                throw new IllegalArgumentException("priority is 0 to 3 (the dissertation's TP: 0, 1.5 or 3), got " + priority);
            }
            if (!(unload >= 0 && unload <= 3600)) {
                throw new IllegalArgumentException("unload is 0 to 3600 s, got " + unload);
            }
        }

        /** A request with every field given. */
        public TransportRequest(int from, int to, double priority, double unload) {
            this(from, to, Double.valueOf(priority), Double.valueOf(unload));
        }

        public void to(Handler h, AclMessage m) {
            h.onTransportRequest(this, m);
        }
    }

    /**
     * PROPOSE {@code proposal}, control -> Medical: seconds until delivered, from pick-up to drop-off,
     * to load; {@code pending}: the chair's other open proposals that the cost counts, with their seconds.
     */
    @Element(name = "proposal")
    record Proposal(@Slot(mandatory = true) String task, double cost, double path, double unload, List<Pending> pending)
            implements WheelchairMessage, Concept {
        /** An open proposal of the chair's: its task and its seconds. */
        @Element(name = "pending")
        public record Pending(@Slot(mandatory = true) String task, double seconds) implements Concept {
        }

        public Proposal {
            pending = Codec.list(pending);
        }

        public void to(Handler h, AclMessage m) {
            h.onProposal(this, m);
        }
    }

    /**
     * REFUSE {@code refused}: a CFP (with the task, and {@code unavailable} from a chair that cannot
     * drive now), a plan (with the task), a door's passage or opening (with the door), a
     * reservation, a transport or a resume.
     */
    @Element(name = "refused")
    record Refused(String task, String door, @Slot(mandatory = true) String reason, boolean unavailable)
            implements WheelchairMessage, Concept, Reasoned {
        /** A refusal saying only why. */
        public static Refused because(String reason) {
            return new Refused(null, null, reason, false);
        }

        public void to(Handler h, AclMessage m) {
            h.onRefused(this, m);
        }
    }

    /** ACCEPT-PROPOSAL {@code award}, Medical -> the best proposal's chair. */
    @Element(name = "award")
    record Award(@Slot(mandatory = true) String task) implements WheelchairMessage, AgentAction {
        public void to(Handler h, AclMessage m) {
            h.onAward(this, m);
        }
    }

    /** REJECT-PROPOSAL {@code rejection}, Medical -> the other proposals' chairs. */
    @Element(name = "rejection")
    record Rejection(@Slot(mandatory = true) String task) implements WheelchairMessage, AgentAction {
        public void to(Handler h, AclMessage m) {
            h.onRejection(this, m);
        }
    }

    /** CANCEL {@code withdrawal}, Medical -> the chair it had given the task to. */
    @Element(name = "withdrawal")
    record Withdrawal(@Slot(mandatory = true) String task) implements WheelchairMessage, AgentAction {
        public void to(Handler h, AclMessage m) {
            h.onWithdrawal(this, m);
        }
    }

    /**
     * REQUEST {@code cancel-request}, to the Medical agent: withdraw a transport ({@code task}, its
     * id, T and a number) for {@code reason}; answered AGREE with this very text once withdrawn, or
     * REFUSE ({@link Refused}) saying why not: the transport has ended, its patient is on board,
     * or the sender did not ask for it (a member cancels only the transports it asked for).
     * {@code order}: an operator's signed order ({@code io.concord.layers.authority.SignedOrder},
     * action {@code cancel}, target the task), with which any transport may be withdrawn (the
     * staff's own, a console's), or null for a member's cancel of its own.
     */
    @Element(name = "cancel-request")
    record CancelRequest(@Slot(mandatory = true) String task, String reason, String order) implements WheelchairMessage, AgentAction {
        /** A member's cancel of a transport it asked for itself (no operator's order). */
        public CancelRequest(String task, String reason) {
            this(task, reason, null);
        }

        public void to(Handler h, AclMessage m) {
            h.onCancelRequest(this, m);
        }
    }

    /**
     * INFORM {@code transport-done}: from the chair to the Medical agent, with the node it delivered to; from
     * the Medical agent to whoever asked by REQUEST, with the chair and a reason (empty).
     */
    @Element(name = "transport-done")
    record Done(@Slot(mandatory = true) String task, Integer node, String chair, String reason)
            implements WheelchairMessage, Concept, Reasoned {
        public void to(Handler h, AclMessage m) {
            h.onDone(this, m);
        }
    }

    /** FAILURE {@code transport-failed}: from the chair to the Medical agent; from the Medical agent (with the chair) to whoever asked. */
    @Element(name = "transport-failed")
    record Failed(@Slot(mandatory = true) String task, String chair, @Slot(mandatory = true) String reason)
            implements WheelchairMessage, Concept, Reasoned {
        public void to(Handler h, AclMessage m) {
            h.onFailed(this, m);
        }
    }

    /**
     * INFORM {@code progress}, chair -> Medical, in the task's status conversation: where the task
     * stands ({@code phase}: {@code to-pickup}, {@code loading}, {@code to-dropoff}, {@code unloading}),
     * the node the chair last reached, and what it waits for if it waits. Sent as the phase changes, at
     * each node, and every 20 s while the task is the chair's: each one tells the Medical agent the
     * chair is at work, however long it is held up.
     */
    @Element(name = "progress")
    record Progress(@Slot(mandatory = true) String task, @Slot(mandatory = true) String chair, @Slot(mandatory = true) String phase,
                    int node, String waits)
            implements WheelchairMessage, Concept {
        /** The phases in which the patient is on board: from the moment the chair is at the pick-up. */
        public static final Set<String> ON_BOARD = Set.of("loading", "to-dropoff", "unloading");
        /** The phases in which the chair stands while its patient gets on or off, for the time the task asked. */
        public static final Set<String> DWELLS = Set.of("loading", "unloading");

        public Progress {
            if (!ON_BOARD.contains(phase) && !phase.equals("to-pickup")) {
                throw new IllegalArgumentException("field 'phase' must be to-pickup, loading, to-dropoff or unloading, got '" + phase + "'");
            }
        }

        /** True once the chair is at the patient: nobody else may be sent for the patient. */
        public boolean patientOnBoard() {
            return ON_BOARD.contains(phase);
        }

        public void to(Handler h, AclMessage m) {
            h.onProgress(this, m);
        }
    }

    /**
     * INFORM {@code paused}, chair -> Medical: its task is paused; {@code :agent-resumes true} if the agent resumes by itself,
     * {@code false} if an operator must.
     */
    @Element(name = "paused")
    record Paused(@Slot(mandatory = true) String task, @Slot(mandatory = true) String chair, @Slot(mandatory = true) String reason,
                  @Slot(name = "agent-resumes") boolean agentResumes)
            implements WheelchairMessage, Concept, Reasoned {
        public void to(Handler h, AclMessage m) {
            h.onPaused(this, m);
        }
    }

    /** INFORM {@code resumed}, chair -> Medical: its task goes on; the fields are {@link Paused}'s. */
    @Element(name = "resumed")
    record Resumed(@Slot(mandatory = true) String task, @Slot(mandatory = true) String chair, @Slot(mandatory = true) String reason,
                  @Slot(name = "agent-resumes") boolean agentResumes)
            implements WheelchairMessage, Concept, Reasoned {
        public void to(Handler h, AclMessage m) {
            h.onResumed(this, m);
        }
    }

    /**
     * REQUEST {@code resume-request}, an operator -> a control agent: resume the held chair;
     * {@code order}: the operator's signed order ({@code io.concord.layers.authority.SignedOrder}, resume of that chair),
     * without which it is refused; {@code by}: who decided, for the log, or null.
     */
    @Element(name = "resume-request")
    record ResumeRequest(String by, String order) implements WheelchairMessage, AgentAction {
        /** A request with no order (refused: only an operator's signed order resumes a chair). */
        public ResumeRequest(String by) {
            this(by, null);
        }

        public void to(Handler h, AclMessage m) {
            h.onResumeRequest(this, m);
        }
    }

    /** INFORM {@code resuming}, control -> the operator: the chair resumes. */
    @Element(name = "resuming")
    record Resuming(@Slot(mandatory = true) String chair) implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onResuming(this, m);
        }
    }

    // ---- a plan: control <-> planner ----------------------------------------------------------------

    /** REQUEST {@code plan-request}, control -> planner; {@code chair}: whom the doors are asked for (null: the sender). */
    @Element(name = "plan-request")
    record PlanRequest(@Slot(mandatory = true) String task, int from, int to, String chair, List<Integer> via)
            implements WheelchairMessage, AgentAction {
        public PlanRequest {
            if (via != null) {
                via = List.copyOf(via);
                if (via.isEmpty() || via.get(0) != from || via.get(via.size() - 1) != to) {
                    throw new IllegalArgumentException("via: the way " + via + " must go from node " + from + " to node " + to);
                }
            }
        }

        /** A plan the planner chooses. */
        public PlanRequest(String task, int from, int to, String chair) {
            this(task, from, to, chair, null);
        }

        public void to(Handler h, AclMessage m) {
            h.onPlanRequest(this, m);
        }
    }

    /** AGREE {@code plan-agreed}, planner -> control. */
    @Element(name = "plan-agreed")
    record PlanAgreed(@Slot(mandatory = true) String task) implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onPlanAgreed(this, m);
        }
    }

    /** INFORM-REF {@code plan}, planner -> control: the nodes, the doors on them, the length in metres. */
    @Element(name = "plan")
    record Plan(@Slot(mandatory = true) String task, List<Integer> nodes, List<String> doors, double length)
            implements WheelchairMessage, Concept {
        public Plan {
            nodes = Codec.list(nodes);
            doors = Codec.list(doors);
        }

        public void to(Handler h, AclMessage m) {
            h.onPlan(this, m);
        }
    }

    /** FAILURE {@code no-route}, planner -> control (task null: the control agent's own, when its planner did not answer). */
    @Element(name = "no-route")
    record NoRoute(String task, @Slot(mandatory = true) String reason) implements WheelchairMessage, Concept, Reasoned {
        public void to(Handler h, AclMessage m) {
            h.onNoRoute(this, m);
        }
    }

    /** INFORM {@code blocked}, control -> planner: the edge from-to is blocked. */
    @Element(name = "blocked")
    record Blocked(int from, int to) implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onBlocked(this, m);
        }
    }

    // ---- doors: planner <-> door, control <-> door ----------------------------------------------------

    /** SUBSCRIBE or REQUEST {@code state-query}, planner -> door. */
    @Element(name = "state-query")
    record StateQuery() implements WheelchairMessage, AgentAction {
        public void to(Handler h, AclMessage m) {
            h.onStateQuery(this, m);
        }
    }

    /** AGREE (to a subscription) or INFORM {@code door-state}, door -> planner: its state (lower case), how open, where. */
    @Element(name = "door-state")
    record DoorState(@Slot(mandatory = true) String door, @Slot(mandatory = true) String state, double open, double x, double y)
            implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onDoorState(this, m);
        }
    }

    /** REQUEST {@code pass-request}, planner -> door: let this chair (its control agent; null: the sender) pass. */
    @Element(name = "pass-request")
    record PassRequest(String chair, String task) implements WheelchairMessage, AgentAction {
        public void to(Handler h, AclMessage m) {
            h.onPassRequest(this, m);
        }
    }

    /** CONFIRM {@code pass-confirmed}, door -> planner. */
    @Element(name = "pass-confirmed")
    record PassConfirmed(@Slot(mandatory = true) String door, @Slot(mandatory = true) String chair) implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onPassConfirmed(this, m);
        }
    }

    /** REQUEST {@code open-request}, control -> door: the chair's body as the doorway sees it (or null). */
    @Element(name = "open-request")
    record OpenRequest(String body) implements WheelchairMessage, AgentAction {
        public void to(Handler h, AclMessage m) {
            h.onOpenRequest(this, m);
        }
    }

    /** AGREE {@code open-queued}, door -> control: the chair waits in the door's queue, this long with it. */
    @Element(name = "open-queued")
    record OpenQueued(@Slot(mandatory = true) String door, int queue) implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onOpenQueued(this, m);
        }
    }

    /** INFORM {@code door-open}, door -> control: open, and the doorway is the chair's. */
    @Element(name = "door-open")
    record DoorOpen(@Slot(mandatory = true) String door) implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onDoorOpen(this, m);
        }
    }

    /**
     * FAILURE {@code failure}: a door that went offline, to a chair waiting for it (with the door);
     * the traffic agent, to a wait that cannot end (with the node in the way, if one is).
     */
    @Element(name = "failure")
    record Failure(String door, Integer node, @Slot(mandatory = true) String reason) implements WheelchairMessage, Concept, Reasoned {
        /**
         * How the traffic agent's reason begins when idle chairs nobody can move stand in the way
         * (its walled-in rule): the chair on its way to a patient gives the task back, not plan round.
         */
        public static final String WALLED_IN = "walled in: ";

        /** The traffic agent's refusal of a way walled in by {@code idle} chairs (their local names). */
        public static String walledIn(List<String> idle) {
            return WALLED_IN + idle + " stand idle in the way and none can be moved";
        }

        /** True if {@code reason} is a walled-in refusal ({@link #walledIn}), as it reaches a chair (maybe quoted within another). */
        public static boolean isWalledIn(String reason) {
            return reason != null && reason.contains(WALLED_IN);
        }

        public void to(Handler h, AclMessage m) {
            h.onFailure(this, m);
        }
    }

    /** INFORM {@code passed}, control -> door: the chair is through. */
    @Element(name = "passed")
    record Passed(String body) implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onPassed(this, m);
        }
    }

    /**
     * INFORM {@code here}, control -> a door ahead (with the chair's body) or the traffic agent
     * (with the nodes it stands on, {@code at}; null if not said): the chair is alive.
     */
    @Element(name = "here")
    record Here(String body, List<Integer> at) implements WheelchairMessage, Concept {
        public Here {
            at = at == null ? null : List.copyOf(at);
        }

        public void to(Handler h, AclMessage m) {
            h.onHere(this, m);
        }
    }

    // ---- traffic: control <-> traffic -----------------------------------------------------------------

    /** REQUEST {@code reserve}, control -> traffic: the nodes it stands on, the route, whether it steps aside. */
    @Element(name = "reserve")
    record Reserve(List<Integer> at, List<Integer> path, boolean aside) implements WheelchairMessage, AgentAction {
        public Reserve {
            at = Codec.list(at);
            path = Codec.list(path);
        }

        public void to(Handler h, AclMessage m) {
            h.onReserve(this, m);
        }
    }

    /**
     * INFORM {@code granted}, traffic -> control: the route is the chair's, to drive up to node
     * {@code upto} now (null: all of it; the traffic agent's in-order rules name it, and say
     * {@link Clear} as the chairs ahead leave).
     */
    @Element(name = "granted")
    record Granted(List<Integer> path, Integer upto) implements WheelchairMessage, Concept {
        public Granted {
            path = Codec.list(path);
            if (upto != null && !path.contains(upto)) {
                throw new IllegalArgumentException("upto: node " + upto + " is not on the path " + path);
            }
        }

        /** The whole route, at once. */
        public Granted(List<Integer> path) {
            this(path, null);
        }

        public void to(Handler h, AclMessage m) {
            h.onGranted(this, m);
        }
    }

    /**
     * INFORM {@code clear}, traffic -> control, in the conversation of a granted reservation: the
     * chair may drive on up to node {@code upto} of that route (the chairs ahead have left).
     */
    @Element(name = "clear")
    record Clear(int upto) implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onClear(this, m);
        }
    }

    /** AGREE {@code reserve-waits}, traffic -> control: the route waits for the chairs that hold it ({@code held-by}). */
    @Element(name = "reserve-waits")
    record ReserveWaits(@Slot(name = "held-by") List<String> heldBy) implements WheelchairMessage, Concept {
        public ReserveWaits {
            heldBy = Codec.list(heldBy);
        }

        public void to(Handler h, AclMessage m) {
            h.onReserveWaits(this, m);
        }
    }

    /**
     * QUERY-REF {@code wait-estimate}, control -> traffic: how long a chair should expect to wait
     * for the chairs ahead of it on {@code path}, from the reservations now; answered INFORM-REF
     * with the same path and {@code seconds} (the traffic agent's estimate: each chair queued or
     * standing on a node of the path, counted once, for as long as chairs have held that node).
     */
    @Element(name = "wait-estimate")
    record WaitEstimate(List<Integer> path, Double seconds) implements WheelchairMessage, Concept {
        public WaitEstimate {
            path = Codec.list(path);
            if (seconds != null && !(seconds >= 0)) {
                throw new IllegalArgumentException("seconds: a wait is 0 or more, got " + seconds);
            }
        }

        public void to(Handler h, AclMessage m) {
            h.onWaitEstimate(this, m);
        }
    }

    /** INFORM {@code release}, control -> traffic: it has left the node. */
    @Element(name = "release")
    record Release(int node) implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onRelease(this, m);
        }
    }

    /** INFORM {@code idle}, control -> traffic: nothing to do, standing at {@code at}. */
    @Element(name = "idle")
    record Idle(List<Integer> at) implements WheelchairMessage, Concept {
        public Idle {
            at = Codec.list(at);
        }

        public void to(Handler h, AclMessage m) {
            h.onIdle(this, m);
        }
    }

    /** INFORM {@code make-way}, traffic -> control: drive from {@code from} to {@code to} (held for it) by {@code path}. */
    @Element(name = "make-way")
    record MakeWay(int from, int to, List<Integer> path) implements WheelchairMessage, Concept {
        public MakeWay {
            path = Codec.list(path);
        }

        public void to(Handler h, AclMessage m) {
            h.onMakeWay(this, m);
        }
    }

    /**
     * INFORM {@code stalled}, traffic -> Medical: the alarm of the fleet monitor. {@code chair} (its
     * agent's name) has work to do and has made no progress (left no node) for {@code seconds} s; {@code waits} says what it waits for (its route and who is in
     * the way, its turn at a node and who is ahead, or nothing the traffic agent holds back).
     */
    @Element(name = "stalled")
    record Stalled(@Slot(mandatory = true) String chair, long seconds, @Slot(mandatory = true) String waits)
            implements WheelchairMessage, Concept {
        public void to(Handler h, AclMessage m) {
            h.onStalled(this, m);
        }
    }

    // ---- decoding ---------------------------------------------------------------------------------------

    /** A content that does not read as one FIPA-SL element. */
    final class Unreadable extends IllegalArgumentException {
        Unreadable(String message) {
            super(message);
        }
    }

    /** An element the ontology has not, or not under the message's performative. */
    final class UnknownWord extends IllegalArgumentException {
        private final String verb;

        UnknownWord(String verb, Performative performative) {
            super("no word '" + verb + "' under " + performative);
            this.verb = verb;
        }

        /** The verb that is not known. */
        public String verb() {
            return verb;
        }
    }

    /** A slot missing, of the wrong type, or refused by the record. */
    final class BadField extends IllegalArgumentException {
        BadField(String message) {
            super(message);
        }
    }

    /**
     * Decodes a content under a performative.
     *
     * @throws IllegalArgumentException naming what is wrong: {@link Unreadable}, {@link UnknownWord}
     *     or {@link BadField}
     */
    static WheelchairMessage decode(String content, Performative performative) {
        return Codec.decode(content, performative);
    }

    /** Decodes a message's content under its performative; see {@link #decode(String, Performative)}. */
    static WheelchairMessage decode(AclMessage m) {
        return decode(m.getContent(), m.getPerformative());
    }

    /**
     * Decodes a message that must be of one kind (a reply whose kind is known).
     *
     * @throws IllegalArgumentException if it does not decode, or decodes as another kind
     */
    static <T extends WheelchairMessage> T decode(AclMessage m, Class<T> kind) {
        WheelchairMessage w = decode(m);
        if (!kind.isInstance(w)) {
            throw new IllegalArgumentException("expected " + kind.getSimpleName() + ", got '" + w.verb() + "' under "
                    + m.getPerformative());
        }
        return kind.cast(w);
    }

    /** The message decoded, or empty if it does not decode. */
    static Optional<WheelchairMessage> tryDecode(AclMessage m) {
        try {
            return Optional.of(decode(m));
        } catch (IllegalArgumentException e) {
            return Optional.empty();
        }
    }

    /** The reason an answer gives ({@link Reasoned}), or null if it gives none or does not decode. */
    static String reasonOf(AclMessage m) {
        return tryDecode(m).map(w -> w instanceof Reasoned r ? r.reason() : null).orElse(null);
    }

    /**
     * Matches the messages that are, or try to be, of one kind: under one of its performatives, with
     * a content that starts with its element (whether or not the rest decodes).
     */
    static MessageTemplate matching(Class<? extends WheelchairMessage> kind) {
        String open = "((" + Codec.verb(kind);
        return m -> Codec.under(kind).contains(m.getPerformative()) && Codec.startsWith(m.getContent(), open);
    }

    /**
     * Decodes a message and hands it to {@code h}. One that does not decode is answered, if it is a
     * REQUEST, as docs/wheelchair-protocol.md says: NOT-UNDERSTOOD with what is wrong when its
     * content does not read, REFUSE {@code refused} naming the slot when a slot is missing or of the
     * wrong type; an element unknown under its performative goes to {@link Handler#unknown}.
     */
    static void dispatch(AclMessage m, Handler h, Consumer<AclMessage> send) {
        dispatchChecked(m, h, send);
    }

    /**
     * Answers a REQUEST an agent does not take, as {@link #dispatch} does: NOT-UNDERSTOOD naming
     * what is wrong when the content does not read, REFUSE naming the slot when it breaks the
     * ontology, and NOT-UNDERSTOOD saying what the agent takes ({@code takes}) otherwise.
     */
    static void notTaken(AclMessage m, String takes, Consumer<AclMessage> send) {
        dispatchChecked(m, new Handler() {
            @Override
            public void unknown(String verb, AclMessage r) {
                send.accept(r.createReply().setPerformative(Performative.NOT_UNDERSTOOD)
                        .setContent("unknown request '" + verb + "'; " + takes + " (docs/wheelchair-protocol.md)"));
            }
        }, send);
    }

    private static void dispatchChecked(AclMessage m, Handler h, Consumer<AclMessage> send) {
        WheelchairMessage w;
        try {
            w = decode(m);
        } catch (Unreadable e) {
            if (m.getPerformative() == Performative.REQUEST) {
                send.accept(m.createReply().setPerformative(Performative.NOT_UNDERSTOOD).setContent(e.getMessage()));
            }
            return;
        } catch (UnknownWord e) {
            h.unknown(e.verb(), m);
            return;
        } catch (BadField e) {
            if (m.getPerformative() == Performative.REQUEST) {
                send.accept(m.createReply().setPerformative(Performative.REFUSE).setContent(Refused.because(e.getMessage()).encode()));
            }
            return;
        }
        w.to(h, m);
    }
}
