package io.concord.agents.control;

import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.*;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The bidder alone: CFPs in, the planner answered by the test, the answers to the CFPs out. */
class BidderTest {
    static final AID PLANNER = new AID("planner-chair1@test");

    final TaskQueue queue = new TaskQueue();
    final List<String> asked = new ArrayList<>();
    final List<CompletableFuture<AclMessage>> plans = new ArrayList<>();
    final List<AclMessage> answers = new ArrayList<>();
    AID planner = PLANNER;
    String unavailable;
    int chairAt = 19;

    final Bidder bidder = new Bidder(queue, "chair1", new Bidder.Planning() {
        @Override
        public AID planner() {
            return planner;
        }

        @Override
        public CompletableFuture<AclMessage> plan(AID p, String task, int from, int to, java.util.List<Integer> via) {
            asked.add(task + " " + from + "->" + to);
            CompletableFuture<AclMessage> f = new CompletableFuture<>();
            plans.add(f);
            return f;
        }
    }, () -> unavailable, () -> chairAt, (cfp, reply) -> answers.add(reply), s -> { });

    static AclMessage cfp(String task, int from, int to, double unload) {
        AclMessage m = new AclMessage(Performative.CFP);
        m.setConversationId("cfp-" + task);
        m.setContent(new TransportCall(task, from, to, 1.5, unload).encode());
        return m;
    }

    static AclMessage plan(double lengthM, int doors, int... nodes) {
        List<Integer> n = new ArrayList<>();
        for (int x : nodes) {
            n.add(x);
        }
        List<String> d = new ArrayList<>();
        for (int i = 0; i < doors; i++) {
            d.add("D" + i);
        }
        return new AclMessage(Performative.INFORM_REF).setContent(new Plan("T", n, d, lengthM).encode());
    }

    private Proposal proposal(int i) {
        return WheelchairMessage.decode(answers.get(i), Proposal.class);
    }

    private Refused refusal(int i) {
        return WheelchairMessage.decode(answers.get(i), Refused.class);
    }

    @Test
    void proposesTheSecondsUntilDeliveryFromTwoPlans() {
        bidder.evaluate(cfp("t1", 3, 9, 60));
        assertEquals(List.of("t1/pickup 19->3"), asked, "first the way to the patient, from where the chair is");
        plans.get(0).complete(plan(14, 1, 19, 5, 3));
        assertEquals("t1/dropoff 3->9", asked.get(1), "then the way to the destination");
        plans.get(1).complete(plan(21, 2, 3, 7, 9));
        assertEquals(Performative.PROPOSE, answers.get(0).getPerformative());
        Proposal p = proposal(0);
        double approach = 14 / Bidder.EST_SPEED_MPS + Bidder.EST_DOOR_S;
        double path = 21 / Bidder.EST_SPEED_MPS + 2 * Bidder.EST_DOOR_S;
        assertEquals(path, p.path(), 0.05);
        assertEquals(approach + 60 + path + 60, p.cost(), 0.05);
        assertEquals(60, p.unload(), 1e-9);
        assertTrue(p.pending().isEmpty());
        assertEquals(TaskView.State.PROPOSED, queue.views().get(0).state());
        assertEquals(List.of(19, 5, 3), queue.all().get(0).toPickup);
    }

    @Test
    void theWorkAheadAndTheOpenProposalsCountInTheCost() {
        bidder.evaluate(cfp("t1", 3, 9, 0));
        plans.get(0).complete(plan(7, 0, 19, 3));
        plans.get(1).complete(plan(7, 0, 3, 9));
        double first = proposal(0).cost();
        bidder.evaluate(cfp("t2", 4, 8, 0));
        plans.get(2).complete(plan(7, 0, 19, 4));
        plans.get(3).complete(plan(7, 0, 4, 8));
        assertEquals(first * 2, proposal(1).cost(), 0.1, "its own work and t1's, still open");
        assertEquals(1, proposal(1).pending().size());
        assertEquals("t1", proposal(1).pending().get(0).task());
        assertEquals(20.0, proposal(1).pending().get(0).seconds(), 0.05);

        Task t1 = queue.all().get(0);
        t1.state = TaskView.State.QUEUED;
        bidder.evaluate(cfp("t3", 5, 6, 0));
        assertEquals("t3/pickup 9->5", asked.get(4), "planned from where the accepted task ends, not from the chair");
    }

    @Test
    void aMalformedCallIsRefusedWithWhatIsWrongAndNotQueued() {
        AclMessage m = cfp("t1", 3, 9, 0);
        m.setContent("((transport-call :task t1 :from three :to 9 :priority 0 :unload 0))");
        bidder.evaluate(m);
        assertEquals(Performative.REFUSE, answers.get(0).getPerformative());
        assertTrue(refusal(0).reason().contains("from"), answers.get(0).getContent());
        assertTrue(queue.all().isEmpty());
        assertTrue(asked.isEmpty());
    }

    @Test
    void aChairThatCannotDriveNowRefusesSayingItMayLater() {
        unavailable = "is held: the e-stop was pressed";
        bidder.evaluate(cfp("t1", 3, 9, 0));
        assertEquals("chair1 is held: the e-stop was pressed", refusal(0).reason());
        assertTrue(refusal(0).unavailable());
        assertTrue(asked.isEmpty());
        assertTrue(queue.all().isEmpty());
    }

    @Test
    void withNoPlannerOrNoRouteItRefuses() {
        planner = null;
        bidder.evaluate(cfp("t1", 3, 9, 0));
        assertEquals("no planner for chair1 in the yellow pages", refusal(0).reason());
        assertFalse(refusal(0).unavailable());

        planner = PLANNER;
        bidder.evaluate(cfp("t2", 3, 99, 0));
        plans.get(0).complete(plan(7, 0, 19, 3));
        plans.get(1).complete(new AclMessage(Performative.FAILURE).setContent(new NoRoute(null, "no node 99").encode()));
        assertEquals(Performative.REFUSE, answers.get(1).getPerformative());
        assertEquals("no node 99", refusal(1).reason());
        assertTrue(queue.all().isEmpty());
    }
}
