package io.concord.agents.control;

import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.Plan;
import io.concord.agents.proto.WheelchairMessage.Proposal;
import io.concord.agents.proto.WheelchairMessage.Refused;
import io.concord.agents.proto.WheelchairMessage.TransportCall;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import java.util.function.IntSupplier;
import java.util.function.Supplier;

/**
 * A control agent's answers to the Medical agent's calls for proposals ({@code transport-call}). It asks the chair's planner for two plans, from where the queue
 * ends to the patient and from the patient to the destination, and proposes {@code proposal}
 * (with its {@code pending} items: the proposals still open that the cost counts);
 * or it refuses, saying why: a malformed call, a chair that cannot drive now ({@code :unavailable
 * true}), no planner, no route.
 *
 * <p>The cost is the seconds until the patient is delivered: the work ahead in the queue, the
 * approach, loading, the path and unloading, at {@link #EST_SPEED_MPS} and {@link #EST_DOOR_S}
 * a door, and the waits for other chairs the traffic agent expects on the way (its reservations
 * now): the quote the Medical agent's deadline is set by.
 */
final class Bidder {
    /** Metres a second the estimates assume (cruise power, turns and slowing included). */
    static final double EST_SPEED_MPS = 0.7;
    /** Seconds each door adds to an estimate. */
    static final double EST_DOOR_S = 6;

    /** How a bidder gets plans. */
    interface Planning {
        /** The chair's planner, from the yellow pages, or null. */
        AID planner();

        /** A plan as the planner's final answer (INFORM-REF {@code plan}), never null. */
        default CompletableFuture<AclMessage> plan(AID planner, String task, int from, int to) {
            return plan(planner, task, from, to, null);
        }

        /** The same along {@code via} (its first node {@code from}, its last {@code to}) if not null: that way, its doors asked. */
        CompletableFuture<AclMessage> plan(AID planner, String task, int from, int to, List<Integer> via);

        /**
         * The seconds the chair should expect to wait for other chairs along {@code path}, as the
         * traffic agent estimates them from its reservations; 0 without a traffic agent or an answer.
         */
        default CompletableFuture<Double> waits(List<Integer> path) {
            return CompletableFuture.completedFuture(0.0);
        }
    }

    private final TaskQueue queue;
    private final String chair;
    private final Planning planning;
    /** Why the chair cannot take a task now, or null. */
    private final Supplier<String> unavailable;
    /** The node the chair stands at or nearest to. */
    private final IntSupplier chairAt;
    /** Sends an answer to a CFP: the CFP and the answer. */
    private final BiConsumer<AclMessage, AclMessage> respond;
    private final Consumer<String> say;

    Bidder(TaskQueue queue, String chair, Planning planning, Supplier<String> unavailable, IntSupplier chairAt,
           BiConsumer<AclMessage, AclMessage> respond, Consumer<String> say) {
        this.queue = queue;
        this.chair = chair;
        this.planning = planning;
        this.unavailable = unavailable;
        this.chairAt = chairAt;
        this.respond = respond;
        this.say = say;
    }

    /** Evaluates a CFP: the answer goes out once the plans are in (at once if there is nothing to ask). */
    void evaluate(AclMessage cfp) {
        Task t;
        try {
            TransportCall c = WheelchairMessage.decode(cfp, TransportCall.class);
            t = new Task(c.task(), c.from(), c.to(), c.priority(), c.unload(), cfp);
        } catch (IllegalArgumentException e) {
            respond.accept(cfp, cfp.createReply().setPerformative(Performative.REFUSE).setContent(Refused.because(e.getMessage()).encode()));
            return;
        }
        queue.add(t);
        String why = unavailable.get();
        if (why != null) {
            refuse(t, chair + " " + why, true);
            return;
        }
        AID planner = planning.planner();
        if (planner == null) {
            refuse(t, "no planner for " + chair + " in the yellow pages", false);
            return;
        }
        int start = queue.end(chairAt);
        t.start = start;
        planning.plan(planner, t.id + "/pickup", start, t.from).thenAccept(first -> {
            if (first.getPerformative() != Performative.INFORM_REF) {
                refuse(t, ControlAgent.reason(first, "no plan from node " + start + " to node " + t.from), false);
                return;
            }
            planning.plan(planner, t.id + "/dropoff", t.from, t.to).thenAccept(second -> {
                if (second.getPerformative() != Performative.INFORM_REF) {
                    refuse(t, ControlAgent.reason(second, "no plan from node " + t.from + " to node " + t.to), false);
                    return;
                }
                Plan toPickup = WheelchairMessage.decode(first, Plan.class);
                Plan toDropoff = WheelchairMessage.decode(second, Plan.class);
                List<Integer> way = new java.util.ArrayList<>(toPickup.nodes());
                way.addAll(toDropoff.nodes().isEmpty() ? List.of() : toDropoff.nodes().subList(1, toDropoff.nodes().size()));
                planning.waits(way).thenAccept(waits -> propose(t, toPickup, toDropoff, waits));
            });
        });
    }

    private void propose(Task t, Plan toPickup, Plan toDropoff, double waitsS) {
        t.toPickup = toPickup.nodes();
        t.toDropoff = toDropoff.nodes();
        double approach = toPickup.length() / EST_SPEED_MPS + EST_DOOR_S * toPickup.doors().size();
        t.pathS = toDropoff.length() / EST_SPEED_MPS + EST_DOOR_S * toDropoff.doors().size();
        t.estimateS = approach + t.unloadS + t.pathS + t.unloadS + waitsS;
        t.costS = queue.seconds() + t.estimateS;
        // The proposals still open that the cost counts, each with its seconds: the Medical agent
        // takes out those another chair has won.
        List<Proposal.Pending> pending = queue.pendingBesides(t);
        t.state = TaskView.State.PROPOSED;
        say.accept(String.format(Locale.ROOT, "proposes for %s: cost %.1f s, path %.1f s, unload %.0f s", t.id, t.costS,
                t.pathS, t.unloadS) + (waitsS > 0 ? String.format(Locale.ROOT, ", waits %.1f s", waitsS) : ""));
        respond.accept(t.cfp, t.cfp.createReply().setPerformative(Performative.PROPOSE).setContent(
                new Proposal(t.id, t.costS, t.pathS, t.unloadS, pending).encode()));
    }

    /** Refuses a task; {@code unavailable}: the chair cannot drive now, and may later. */
    private void refuse(Task t, String why, boolean unavailable) {
        t.state = TaskView.State.REFUSED;
        t.reason = why;
        queue.remove(t);
        say.accept("refuses " + t.id + ": " + why);
        respond.accept(t.cfp, t.cfp.createReply().setPerformative(Performative.REFUSE)
                .setContent(new Refused(t.id, null, why, unavailable).encode()));
    }
}
