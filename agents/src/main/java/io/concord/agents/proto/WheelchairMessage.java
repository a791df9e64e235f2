package io.concord.agents.proto;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;

import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;

/**
 * The wheelchair agents' messages as types (docs/wheelchair-protocol.md): one record per meaning,
 * the one codec of their contents. A record's {@link #encode()} is its text on the wire; a message
 * is decoded once, from its performative and its content together (one word under a performative
 * is one record), and checked as it is decoded: a field missing, or not a number where one is
 * wanted, fails the decoding, naming the field. {@link Content} is the low-level text it reads and
 * writes.
 *
 * <p>An optional field is null when absent (and not written); a list is empty when absent, but
 * {@link Here#at()}, which is null when the chair does not say where it stands.
 */
public sealed interface WheelchairMessage {

    /** The content as it goes on the wire. */
    String encode();

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

        default void onClear(Clear w, AclMessage m) { unknown(w.verb(), m); }
        default void onReserveWaits(ReserveWaits w, AclMessage m) { unknown(w.verb(), m); }
        default void onRelease(Release w, AclMessage m) { unknown(w.verb(), m); }
        default void onIdle(Idle w, AclMessage m) { unknown(w.verb(), m); }
        default void onMakeWay(MakeWay w, AclMessage m) { unknown(w.verb(), m); }
    }

    /** A message that says why (a refusal, a failure, a pause). */
    interface Reasoned {
        /** Why; null only where the record's field is optional. */
        String reason();
    }

    // ---- a transport: Medical <-> chairs (Contract Net), the desk -> Medical ------------------------

    /** CFP {@code transport}, Medical -> every control agent; priority and unload are 0 when absent. */
    record TransportCall(String task, int from, int to, double priority, double unload) implements WheelchairMessage {
        public String encode() {
            return Content.of("transport").with("task", task).with("from", from).with("to", to).with("priority", priority)
                    .with("unload", unload).toString();
        }

        static TransportCall read(Content c) {
            return new TransportCall(c.text("task"), c.integer("from"), c.integer("to"), c.number("priority", 0), c.number("unload", 0));
        }

        public void to(Handler h, AclMessage m) {
            h.onTransportCall(this, m);
        }
    }

    /**
     * REQUEST {@code transport} to the Medical agent, which answers AGREE with this very text;
     * priority is 0 and unload 60 when absent.
     */
    record TransportRequest(int from, int to, double priority, double unload) implements WheelchairMessage {
        public String encode() {
            return Content.of("transport").with("from", from).with("to", to).with("priority", priority).with("unload", unload).toString();
        }

        static TransportRequest read(Content c) {
            return new TransportRequest(c.integer("from"), c.integer("to"), c.number("priority", 0), c.number("unload", 60));
        }

        public void to(Handler h, AclMessage m) {
            h.onTransportRequest(this, m);
        }
    }

    /**
     * PROPOSE {@code proposal}, control -> Medical: seconds until delivered, from pick-up to drop-off,
     * to load; {@code pending}: the chair's other open proposals that the cost counts, with their seconds.
     */
    record Proposal(String task, double cost, double path, double unload, List<Pending> pending) implements WheelchairMessage {
        /** An open proposal of the chair's (written to a tenth of a second). */
        public record Pending(String task, double seconds) {
        }

        public Proposal {
            pending = List.copyOf(pending);
        }

        public String encode() {
            return Content.of("proposal").with("task", task).with("cost", cost).with("path", path).with("unload", unload)
                    .maybe("pending", pending.isEmpty() ? null : Codec.pending(pending)).toString();
        }

        static Proposal read(Content c) {
            return new Proposal(c.text("task"), c.number("cost"), c.number("path"), c.number("unload"), Codec.pending(c));
        }

        public void to(Handler h, AclMessage m) {
            h.onProposal(this, m);
        }
    }

    /**
     * REFUSE {@code refuse}: a CFP (with the task, and {@code unavailable} from a chair that cannot
     * drive now), a plan (with the task), a door's passage or opening (with the door), a
     * reservation, a transport or a resume.
     */
    record Refused(String task, String door, String reason, boolean unavailable) implements WheelchairMessage, Reasoned {
        /** A refusal saying only why. */
        public static Refused because(String reason) {
            return new Refused(null, null, reason, false);
        }

        public String encode() {
            return Content.of("refuse").maybe("task", task).maybe("door", door).with("reason", reason)
                    .maybe("unavailable", unavailable ? "true" : null).toString();
        }

        static Refused read(Content c) {
            return new Refused(c.get("task"), c.get("door"), c.text("reason"), "true".equals(c.get("unavailable")));
        }

        public void to(Handler h, AclMessage m) {
            h.onRefused(this, m);
        }
    }

    /** ACCEPT-PROPOSAL {@code transport}, Medical -> the best proposal's chair. */
    record Award(String task) implements WheelchairMessage {
        public String encode() {
            return Content.of("transport").with("task", task).toString();
        }

        static Award read(Content c) {
            return new Award(c.text("task"));
        }

        public void to(Handler h, AclMessage m) {
            h.onAward(this, m);
        }
    }

    /** REJECT-PROPOSAL {@code transport}, Medical -> the other proposals' chairs. */
    record Rejection(String task) implements WheelchairMessage {
        public String encode() {
            return Content.of("transport").with("task", task).toString();
        }

        static Rejection read(Content c) {
            return new Rejection(c.text("task"));
        }

        public void to(Handler h, AclMessage m) {
            h.onRejection(this, m);
        }
    }

    /** CANCEL {@code transport}, Medical -> the chair it had given the task to. */
    record Withdrawal(String task) implements WheelchairMessage {
        public String encode() {
            return Content.of("transport").with("task", task).toString();
        }

        static Withdrawal read(Content c) {
            return new Withdrawal(c.text("task"));
        }

        public void to(Handler h, AclMessage m) {
            h.onWithdrawal(this, m);
        }
    }

    /**
     * INFORM {@code done}: from the chair to the Medical agent, with the node it delivered to; from
     * the Medical agent to whoever asked by REQUEST, with the chair and a reason (empty).
     */
    record Done(String task, Integer node, String chair, String reason) implements WheelchairMessage, Reasoned {
        public String encode() {
            return Content.of("done").with("task", task).maybe("node", node).maybe("chair", chair).maybe("reason", reason).toString();
        }

        static Done read(Content c) {
            return new Done(c.text("task"), Codec.optionalInt(c, "node"), c.get("chair"), c.get("reason"));
        }

        public void to(Handler h, AclMessage m) {
            h.onDone(this, m);
        }
    }

    /** FAILURE {@code failed}: from the chair to the Medical agent; from the Medical agent (with the chair) to whoever asked. */
    record Failed(String task, String chair, String reason) implements WheelchairMessage, Reasoned {
        public String encode() {
            return Content.of("failed").with("task", task).maybe("chair", chair).with("reason", reason).toString();
        }

        static Failed read(Content c) {
            return new Failed(c.text("task"), c.get("chair"), c.text("reason"));
        }

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
    record Progress(String task, String chair, String phase, int node, String waits) implements WheelchairMessage {
        /** The phases in which the patient is on board: from the moment the chair is at the pick-up. */
        public static final Set<String> ON_BOARD = Set.of("loading", "to-dropoff", "unloading");

        public Progress {
            if (!ON_BOARD.contains(phase) && !phase.equals("to-pickup")) {
                throw new IllegalArgumentException("field 'phase' must be to-pickup, loading, to-dropoff or unloading, got '" + phase + "'");
            }
        }

        /** True once the chair is at the patient: nobody else may be sent for the patient. */
        public boolean patientOnBoard() {
            return ON_BOARD.contains(phase);
        }

        public String encode() {
            return Content.of("progress").with("task", task).with("chair", chair).with("phase", phase).with("node", node)
                    .maybe("waits", waits).toString();
        }

        static Progress read(Content c) {
            return new Progress(c.text("task"), c.text("chair"), c.text("phase"), c.integer("node"), c.get("waits"));
        }

        public void to(Handler h, AclMessage m) {
            h.onProgress(this, m);
        }
    }

    /** INFORM {@code paused}, chair -> Medical: its task is paused; {@code resume=agent} if the agent resumes by itself, else {@code operator}. */
    record Paused(String task, String chair, String reason, boolean agentResumes) implements WheelchairMessage, Reasoned {
        public String encode() {
            return Content.of("paused").with("task", task).with("chair", chair).with("reason", reason)
                    .with("resume", Codec.resumer(agentResumes)).toString();
        }

        static Paused read(Content c) {
            return new Paused(c.text("task"), c.text("chair"), c.text("reason"), Codec.resumer(c));
        }

        public void to(Handler h, AclMessage m) {
            h.onPaused(this, m);
        }
    }

    /** INFORM {@code resumed}, chair -> Medical: its task goes on; the fields are {@link Paused}'s. */
    record Resumed(String task, String chair, String reason, boolean agentResumes) implements WheelchairMessage, Reasoned {
        public String encode() {
            return Content.of("resumed").with("task", task).with("chair", chair).with("reason", reason)
                    .with("resume", Codec.resumer(agentResumes)).toString();
        }

        static Resumed read(Content c) {
            return new Resumed(c.text("task"), c.text("chair"), c.text("reason"), Codec.resumer(c));
        }

        public void to(Handler h, AclMessage m) {
            h.onResumed(this, m);
        }
    }

    /** REQUEST {@code resume}, an operator -> a control agent: resume the held chair; {@code by}: who decided, or null. */
    record ResumeRequest(String by) implements WheelchairMessage {
        public String encode() {
            return Content.of("resume").maybe("by", by).toString();
        }

        static ResumeRequest read(Content c) {
            return new ResumeRequest(c.get("by"));
        }

        public void to(Handler h, AclMessage m) {
            h.onResumeRequest(this, m);
        }
    }

    /** INFORM {@code resuming}, control -> the operator: the chair resumes. */
    record Resuming(String chair) implements WheelchairMessage {
        public String encode() {
            return Content.of("resuming").with("chair", chair).toString();
        }

        static Resuming read(Content c) {
            return new Resuming(c.text("chair"));
        }

        public void to(Handler h, AclMessage m) {
            h.onResuming(this, m);
        }
    }

    // ---- a plan: control <-> planner ----------------------------------------------------------------

    /** REQUEST {@code plan}, control -> planner; {@code chair}: whom the doors are asked for (null: the sender). */
    record PlanRequest(String task, int from, int to, String chair, List<Integer> via) implements WheelchairMessage {
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

        public String encode() {
            return Content.of("plan").with("task", task).with("from", from).with("to", to).maybe("chair", chair)
                    .maybe("via", via == null ? null : Codec.join(via)).toString();
        }

        static PlanRequest read(Content c) {
            int from = c.integer("from");
            int to = c.integer("to");
            return new PlanRequest(c.text("task"), from, to, c.get("chair"), c.get("via") == null ? null : Codec.nodes(c, "via"));
        }

        public void to(Handler h, AclMessage m) {
            h.onPlanRequest(this, m);
        }
    }

    /** AGREE {@code plan}, planner -> control. */
    record PlanAgreed(String task) implements WheelchairMessage {
        public String encode() {
            return Content.of("plan").with("task", task).toString();
        }

        static PlanAgreed read(Content c) {
            return new PlanAgreed(c.text("task"));
        }

        public void to(Handler h, AclMessage m) {
            h.onPlanAgreed(this, m);
        }
    }

    /** INFORM-REF {@code plan}, planner -> control: the nodes, the doors on them, the length in metres. */
    record Plan(String task, List<Integer> nodes, List<String> doors, double length) implements WheelchairMessage {
        public Plan {
            nodes = List.copyOf(nodes);
            doors = List.copyOf(doors);
        }

        public String encode() {
            return Content.of("plan").with("task", task).with("nodes", Codec.join(nodes)).with("doors", Codec.join(doors))
                    .with("length", length).toString();
        }

        static Plan read(Content c) {
            return new Plan(c.text("task"), Codec.nodes(c, "nodes"), c.list("doors"), c.number("length"));
        }

        public void to(Handler h, AclMessage m) {
            h.onPlan(this, m);
        }
    }

    /** FAILURE {@code no-route}, planner -> control (task null: the control agent's own, when its planner did not answer). */
    record NoRoute(String task, String reason) implements WheelchairMessage, Reasoned {
        public String encode() {
            return Content.of("no-route").maybe("task", task).with("reason", reason).toString();
        }

        static NoRoute read(Content c) {
            return new NoRoute(c.get("task"), c.text("reason"));
        }

        public void to(Handler h, AclMessage m) {
            h.onNoRoute(this, m);
        }
    }

    /** INFORM {@code blocked}, control -> planner: the edge from-to is blocked. */
    record Blocked(int from, int to) implements WheelchairMessage {
        public String encode() {
            return Content.of("blocked").with("from", from).with("to", to).toString();
        }

        static Blocked read(Content c) {
            return new Blocked(c.integer("from"), c.integer("to"));
        }

        public void to(Handler h, AclMessage m) {
            h.onBlocked(this, m);
        }
    }

    // ---- doors: planner <-> door, control <-> door ----------------------------------------------------

    /** SUBSCRIBE or REQUEST {@code state}, planner -> door. */
    record StateQuery() implements WheelchairMessage {
        public String encode() {
            return Content.of("state").toString();
        }

        static StateQuery read(Content c) {
            return new StateQuery();
        }

        public void to(Handler h, AclMessage m) {
            h.onStateQuery(this, m);
        }
    }

    /** AGREE (to a subscription) or INFORM {@code state}, door -> planner: its state (lower case), how open, where. */
    record DoorState(String door, String state, double open, double x, double y) implements WheelchairMessage {
        public String encode() {
            return Content.of("state").with("door", door).with("state", state).with("open", open).with("x", x).with("y", y).toString();
        }

        static DoorState read(Content c) {
            return new DoorState(c.text("door"), c.text("state"), c.number("open"), c.number("x"), c.number("y"));
        }

        public void to(Handler h, AclMessage m) {
            h.onDoorState(this, m);
        }
    }

    /** REQUEST {@code pass}, planner -> door: let this chair (its control agent; null: the sender) pass. */
    record PassRequest(String chair, String task) implements WheelchairMessage {
        public String encode() {
            return Content.of("pass").maybe("chair", chair).maybe("task", task).toString();
        }

        static PassRequest read(Content c) {
            return new PassRequest(c.get("chair"), c.get("task"));
        }

        public void to(Handler h, AclMessage m) {
            h.onPassRequest(this, m);
        }
    }

    /** CONFIRM {@code pass}, door -> planner. */
    record PassConfirmed(String door, String chair) implements WheelchairMessage {
        public String encode() {
            return Content.of("pass").with("door", door).with("chair", chair).toString();
        }

        static PassConfirmed read(Content c) {
            return new PassConfirmed(c.text("door"), c.text("chair"));
        }

        public void to(Handler h, AclMessage m) {
            h.onPassConfirmed(this, m);
        }
    }

    /** REQUEST {@code open}, control -> door: the chair's body as the doorway sees it (or null). */
    record OpenRequest(String body) implements WheelchairMessage {
        public String encode() {
            return Content.of("open").maybe("body", body).toString();
        }

        static OpenRequest read(Content c) {
            return new OpenRequest(c.get("body"));
        }

        public void to(Handler h, AclMessage m) {
            h.onOpenRequest(this, m);
        }
    }

    /** AGREE {@code open}, door -> control: the chair waits in the door's queue, this long with it. */
    record OpenQueued(String door, int queue) implements WheelchairMessage {
        public String encode() {
            return Content.of("open").with("door", door).with("queue", queue).toString();
        }

        static OpenQueued read(Content c) {
            return new OpenQueued(c.text("door"), c.integer("queue"));
        }

        public void to(Handler h, AclMessage m) {
            h.onOpenQueued(this, m);
        }
    }

    /** INFORM {@code open}, door -> control: open, and the doorway is the chair's. */
    record DoorOpen(String door) implements WheelchairMessage {
        public String encode() {
            return Content.of("open").with("door", door).toString();
        }

        static DoorOpen read(Content c) {
            return new DoorOpen(c.text("door"));
        }

        public void to(Handler h, AclMessage m) {
            h.onDoorOpen(this, m);
        }
    }

    /**
     * FAILURE {@code failure}: a door that went offline, to a chair waiting for it (with the door);
     * the traffic agent, to a wait that cannot end (with the node in the way, if one is).
     */
    record Failure(String door, Integer node, String reason) implements WheelchairMessage, Reasoned {
        public String encode() {
            return Content.of("failure").maybe("door", door).maybe("node", node).with("reason", reason).toString();
        }

        static Failure read(Content c) {
            return new Failure(c.get("door"), Codec.optionalInt(c, "node"), c.text("reason"));
        }

        public void to(Handler h, AclMessage m) {
            h.onFailure(this, m);
        }
    }

    /** INFORM {@code passed}, control -> door: the chair is through. */
    record Passed(String body) implements WheelchairMessage {
        public String encode() {
            return Content.of("passed").maybe("body", body).toString();
        }

        static Passed read(Content c) {
            return new Passed(c.get("body"));
        }

        public void to(Handler h, AclMessage m) {
            h.onPassed(this, m);
        }
    }

    /**
     * INFORM {@code here}, control -> a door ahead (with the chair's body) or the traffic agent
     * (with the nodes it stands on, {@code at}; null if not said): the chair is alive.
     */
    record Here(String body, List<Integer> at) implements WheelchairMessage {
        public Here {
            at = at == null ? null : List.copyOf(at);
        }

        public String encode() {
            return Content.of("here").maybe("body", body).maybe("at", at == null ? null : Codec.join(at)).toString();
        }

        static Here read(Content c) {
            return new Here(c.get("body"), c.get("at") == null ? null : Codec.nodes(c, "at"));
        }

        public void to(Handler h, AclMessage m) {
            h.onHere(this, m);
        }
    }

    // ---- traffic: control <-> traffic -----------------------------------------------------------------

    /** REQUEST {@code reserve}, control -> traffic: the nodes it stands on, the route, whether it steps aside. */
    record Reserve(List<Integer> at, List<Integer> path, boolean aside) implements WheelchairMessage {
        public Reserve {
            at = List.copyOf(at);
            path = List.copyOf(path);
        }

        public String encode() {
            return Content.of("reserve").with("at", Codec.join(at)).with("path", Codec.join(path))
                    .maybe("aside", aside ? "true" : null).toString();
        }

        static Reserve read(Content c) {
            return new Reserve(Codec.nodes(c, "at"), Codec.nodes(c, "path"), "true".equals(c.get("aside")));
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
    record Granted(List<Integer> path, Integer upto) implements WheelchairMessage {
        public Granted {
            path = List.copyOf(path);
            if (upto != null && !path.contains(upto)) {
                throw new IllegalArgumentException("upto: node " + upto + " is not on the path " + path);
            }
        }

        /** The whole route, at once. */
        public Granted(List<Integer> path) {
            this(path, null);
        }

        public String encode() {
            return Content.of("granted").with("path", Codec.join(path)).maybe("upto", upto).toString();
        }

        static Granted read(Content c) {
            return new Granted(Codec.nodes(c, "path"), Codec.optionalInt(c, "upto"));
        }

        public void to(Handler h, AclMessage m) {
            h.onGranted(this, m);
        }
    }

    /**
     * INFORM {@code clear}, traffic -> control, in the conversation of a granted reservation: the
     * chair may drive on up to node {@code upto} of that route (the chairs ahead have left).
     */
    record Clear(int upto) implements WheelchairMessage {
        public String encode() {
            return Content.of("clear").with("upto", upto).toString();
        }

        static Clear read(Content c) {
            return new Clear(c.integer("upto"));
        }

        public void to(Handler h, AclMessage m) {
            h.onClear(this, m);
        }
    }

    /** AGREE {@code reserve}, traffic -> control: the route waits for the chairs that hold it ({@code held-by}). */
    record ReserveWaits(List<String> heldBy) implements WheelchairMessage {
        public ReserveWaits {
            heldBy = List.copyOf(heldBy);
        }

        public String encode() {
            return Content.of("reserve").with("held-by", Codec.join(heldBy)).toString();
        }

        static ReserveWaits read(Content c) {
            return new ReserveWaits(c.list("held-by"));
        }

        public void to(Handler h, AclMessage m) {
            h.onReserveWaits(this, m);
        }
    }

    /** INFORM {@code release}, control -> traffic: it has left the node. */
    record Release(int node) implements WheelchairMessage {
        public String encode() {
            return Content.of("release").with("node", node).toString();
        }

        static Release read(Content c) {
            return new Release(c.integer("node"));
        }

        public void to(Handler h, AclMessage m) {
            h.onRelease(this, m);
        }
    }

    /** INFORM {@code idle}, control -> traffic: nothing to do, standing at {@code at}. */
    record Idle(List<Integer> at) implements WheelchairMessage {
        public Idle {
            at = List.copyOf(at);
        }

        public String encode() {
            return Content.of("idle").with("at", Codec.join(at)).toString();
        }

        static Idle read(Content c) {
            return new Idle(Codec.nodes(c, "at"));
        }

        public void to(Handler h, AclMessage m) {
            h.onIdle(this, m);
        }
    }

    /** INFORM {@code make-way}, traffic -> control: drive from {@code from} to {@code to} (held for it) by {@code path}. */
    record MakeWay(int from, int to, List<Integer> path) implements WheelchairMessage {
        public MakeWay {
            path = List.copyOf(path);
        }

        public String encode() {
            return Content.of("make-way").with("from", from).with("to", to).with("path", Codec.join(path)).toString();
        }

        static MakeWay read(Content c) {
            return new MakeWay(c.integer("from"), c.integer("to"), Codec.nodes(c, "path"));
        }

        public void to(Handler h, AclMessage m) {
            h.onMakeWay(this, m);
        }
    }

    // ---- decoding ---------------------------------------------------------------------------------------

    /** A content that does not read as a verb and {@code key=value} fields. */
    final class Unreadable extends IllegalArgumentException {
        Unreadable(String message) {
            super(message);
        }
    }

    /** A verb that is no word under the message's performative. */
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

    /** A field missing, or not a number where one is wanted. */
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
     * a content that starts with its word (whether or not the rest decodes).
     */
    static MessageTemplate matching(Class<? extends WheelchairMessage> kind) {
        String verb = Codec.verb(kind);
        return m -> Codec.under(kind).contains(m.getPerformative()) && m.getContent() != null && m.getContent().startsWith(verb);
    }

    /**
     * Decodes a message and hands it to {@code h}. One that does not decode is answered, if it is a
     * REQUEST, as docs/wheelchair-protocol.md says: NOT-UNDERSTOOD with what is wrong when its
     * content does not read, REFUSE {@code refuse; reason} naming the field when a field is missing
     * or not a number; a word unknown under its performative goes to {@link Handler#unknown}.
     */
    static void dispatch(AclMessage m, Handler h, Consumer<AclMessage> send) {
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
