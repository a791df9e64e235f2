package io.concord.agents.control;

import io.concord.agents.chair.ChairSupervisor;
import io.concord.agents.chair.ObstacleFilter;
import io.concord.agents.chair.Pose;
import io.concord.agents.proto.WheelchairMessage.Failure;
import io.concord.agents.proto.WheelchairMessage.Granted;
import io.concord.agents.proto.WheelchairMessage.MakeWay;
import io.concord.agents.proto.WheelchairMessage.Plan;
import io.concord.agents.proto.WheelchairMessage.Release;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

import static io.concord.agents.control.Fakes.SMALL;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The runner's own rules, on the small map of docs/hospital-map.md (corridor nodes 1 and 3, the
 * room's node 2 behind door D1), a recorded chair and a planner the test answers for: what it does
 * with answers that come after what they answered is over, and with orders it cannot follow. The
 * phases alone are {@link PhaseTest}'s; the whole, the scenario tests'.
 */
class TaskRunnerTest {
    static final AID MEDICAL = new AID("medical@test");
    static final AID PLANNER = new AID("planner@test");
    static final AID TRAFFIC = new AID("traffic@test");

    final Fakes.Chair chair = new Fakes.Chair();
    final ChairSupervisor supervisor = new ChairSupervisor(chair);
    final TaskQueue queue = new TaskQueue();
    final RouteFollower follower = new RouteFollower(new ObstacleFilter(supervisor), SMALL);
    final List<String> said = new ArrayList<>();
    /** The plans asked for ("from->to"), each answered by the test through its future. */
    final List<String> asked = new ArrayList<>();
    final List<CompletableFuture<AclMessage>> plans = new ArrayList<>();
    final Port port = new Port();
    final DoorClient doors = new DoorClient(port, SMALL, "chair1", (from, why) -> runner().replan(from, why), said::add);
    final TrafficClient traffic = new TrafficClient(port, (node, why) -> runner().refusedByTraffic(node, why));
    final TaskRunner runner = new TaskRunner(supervisor, SMALL, queue, follower, doors, traffic, port);
    long ms;

    private TaskRunner runner() {
        return runner;
    }

    /** The control agent's ports, recorded: no door agents, a traffic agent that has not answered yet. */
    final class Port extends Fakes.Recording implements TaskRunner.Agent, DoorClient.Doors, TrafficClient.Port {
        @Override
        public AID agentOf(String id) {
            return null;
        }

        @Override
        public AID trafficAgent() {
            return TRAFFIC;
        }

        @Override
        public AID planner() {
            return PLANNER;
        }

        @Override
        public CompletableFuture<AclMessage> plan(AID planner, String task, int from, int to, List<Integer> via) {
            asked.add(from + "->" + to);
            CompletableFuture<AclMessage> f = new CompletableFuture<>();
            plans.add(f);
            return f;
        }

        @Override
        public void say(String s) {
            said.add(s);
        }
    }

    /** The chair armed, standing at node 1. */
    @BeforeEach
    void armed() {
        supervisor.resume("the test");
        for (int i = 0; i < 3; i++) {
            ms += 50;
            chair.report(Fakes.clear(ms, at(1)));
        }
        assertTrue(supervisor.armed(), supervisor.state().toString());
    }

    private static Pose at(int node) {
        var p = SMALL.node(node).at();
        return new Pose(p.x(), p.y(), 0);
    }

    /** A reading of the chair standing at {@code node}, handed to the runner. */
    private void reading(int node) {
        ms += 50;
        var r = Fakes.clear(ms, at(node));
        chair.report(r);
        runner.reading(r, follower.locate(r), ms);
    }

    /** A transport from node {@code from} to node 2, given by the Medical agent and queued. */
    private Task given(int from, List<Integer> toPickup) {
        AclMessage cfp = new AclMessage(Performative.CFP);
        cfp.setConversationId("cfp-T1");
        Task t = new Task("T1", from, 2, 0, 30, cfp);
        t.accept = new AclMessage(Performative.ACCEPT_PROPOSAL).setSender(MEDICAL);
        t.accept.setConversationId("cfp-T1");
        t.toPickup = toPickup;
        t.toDropoff = List.of(from, 2);
        t.state = TaskView.State.QUEUED;
        queue.add(t);
        return t;
    }

    private void withdraw(Task t) {
        AclMessage cancel = new AclMessage(Performative.CANCEL).setSender(MEDICAL);
        cancel.setConversationId("cfp-T1");
        runner.cancelled(cancel);
    }

    private static AclMessage plan(Integer... nodes) {
        return new AclMessage(Performative.INFORM_REF).setContent(new Plan("T1", List.of(nodes), List.of(), 3).encode());
    }

    private AclMessage makeWay(int from, int to) {
        AclMessage m = new AclMessage(Performative.INFORM).setSender(TRAFFIC);
        m.setContent(new MakeWay(from, to, List.of(to)).encode());
        return m;
    }

    @Test
    void aPlanAnsweredAfterItsTaskWasWithdrawnIsNotFollowed() {
        // Planned from node 3, the chair stands at node 1: it asks for a plan from where it is.
        Task t = given(3, List.of(3));
        reading(1);
        assertEquals(List.of("1->3"), asked);
        assertInstanceOf(Replanning.class, runner.phase());
        withdraw(t);
        assertNull(runner.phase());
        assertEquals(TaskView.State.CANCELLED, t.state);

        plans.get(0).complete(plan(1, 3));
        assertNull(runner.phase(), "the plan for a withdrawn task brings back no phase");
        assertNull(follower.route(), "nor a route to drive");
        reading(1);
        assertEquals("stop", chair.last());
        assertEquals(TaskView.State.CANCELLED, t.state);
    }

    @Test
    void aWayAsideAnsweredAfterItsTaskWasWithdrawnIsNotDriven() {
        Task t = given(3, List.of(1, 3));
        reading(1);
        assertInstanceOf(ToPickup.class, runner.phase());
        runner.makeWay(makeWay(1, 3));
        assertInstanceOf(StepAside.class, runner.phase(), String.join("\n", said));
        withdraw(t);
        assertNull(runner.phase());

        plans.get(0).complete(plan(1, 3));
        assertNull(runner.phase(), "the way aside of a withdrawn task brings back no phase");
        assertNull(follower.route());
        assertFalse(said.stream().anyMatch(s -> s.contains("has made way")), String.join("\n", said));
    }

    @Test
    void anOrderToMakeWayWhileThePatientGetsOnIsRefused() {
        // The chair is at the pick-up already: its first reading ends the leg, and the patient gets on.
        Task t = given(1, List.of(1));
        reading(1);
        reading(1);
        assertInstanceOf(Loading.class, runner.phase(), String.join("\n", said));

        runner.makeWay(makeWay(1, 3));
        assertInstanceOf(Loading.class, runner.phase(), "the patient getting on is not left for a way aside");
        assertTrue(asked.isEmpty(), "no way aside asked for: " + asked);
        assertTrue(said.stream().anyMatch(s -> s.equals("cannot make way from node 1 to node 3: the patient gets on here")),
                String.join("\n", said));
        assertEquals(TaskView.State.LOADING, t.state);
    }

    /**
     * An order to make way to a node the chair's own route, granted meanwhile, drives into (the
     * traffic agent sent it while the chair was idle): refused, and that node is not given back,
     * for the chair will drive into it (the depot soak's seed 12: given back, it let another chair
     * in head-on).
     */
    @Test
    void anOrderToMakeWayToANodeOfTheRouteUnderWayIsRefusedWithoutGivingThatNodeBack() {
        given(3, List.of(1, 3));
        reading(1);
        assertInstanceOf(ToPickup.class, runner.phase());
        AclMessage grant = new AclMessage(Performative.INFORM).setSender(TRAFFIC);
        grant.setContent(new Granted(List.of(1, 3), 3).encode());
        port.answers.get(0).complete(grant);
        reading(1);
        assertTrue(follower.underWay() && traffic.mayDriveNow(follower.route()), "driving its granted route");

        runner.makeWay(makeWay(1, 3));
        assertTrue(said.contains("cannot make way from node 1 to node 3: it is under way"), String.join("\n", said));
        String release = new Release(3).encode();
        assertFalse(port.sent.stream().anyMatch(m -> release.equals(m.getContent())), "node 3 is not given back");
        assertInstanceOf(ToPickup.class, runner.phase());
    }

    /**
     * On its way to the patient, the chair's route is refused as walled in (idle chairs nobody can
     * move stand between it and the patient): the task is given back, failed with that reason, for
     * the Medical agent to give to another chair, not planned round for ever (the depot soak's seed
     * 59: two ways round the lobby, each refused in turn, for two hours).
     */
    @Test
    void aWayToThePatientWalledInGivesTheTaskBack() {
        Task t = given(3, List.of(1, 3));
        reading(1);
        AclMessage no = new AclMessage(Performative.FAILURE).setSender(TRAFFIC);
        no.setContent(new Failure(null, 3, "walled in: [control-chair5] stand idle in the way and none can be moved").encode());
        port.answers.get(0).complete(no);
        assertEquals(TaskView.State.FAILED, t.state, String.join("\n", said));
        assertTrue(t.reason.startsWith("cannot reach the patient at node 3: FAILURE: walled in: [control-chair5]"), t.reason);
        assertTrue(asked.isEmpty(), "no plan round it: " + asked);
    }

    /**
     * With the patient on board a walled-in refusal is not planned round (that could fail the
     * patient: the 20-chair soak's T17 failed so, "no route ... blocked edges"): the chair keeps its
     * way to the drop-off and asks for it again.
     */
    @Test
    void aWayToTheDropOffWalledInIsAskedAgainNotPlannedRound() {
        Task t = given(1, List.of(1));
        reading(1);
        reading(1);
        assertInstanceOf(Loading.class, runner.phase());
        ms += 31_000;
        reading(1);
        assertInstanceOf(ToDropoff.class, runner.phase(), String.join("\n", said));
        int asks = port.answers.size();
        assertTrue(asks >= 1, "the way to the drop-off asked for");
        AclMessage no = new AclMessage(Performative.FAILURE).setSender(TRAFFIC);
        no.setContent(new Failure(null, 2, "walled in: [control-chair5] stand idle in the way and none can be moved").encode());
        port.answers.get(asks - 1).complete(no);
        assertInstanceOf(ToDropoff.class, runner.phase(), String.join("\n", said));
        assertTrue(asked.isEmpty(), "no plan round it: " + asked);
        reading(1);
        assertEquals(asks + 1, port.answers.size(), "asked again");
        assertEquals(TaskView.State.TO_DROPOFF, t.state);
    }

    /**
     * With the patient on board, an edge blocked and no way round it (the depot soak's seed 190: the
     * chair failed its task with the patient on board and started its next one): the task is kept,
     * the chair keeps its route and asks again after a while, and follows the plan that comes then.
     */
    @Test
    void noWayRoundWithThePatientOnBoardKeepsTheTaskAndAsksAgain() {
        Task t = given(1, List.of(1));
        reading(1);
        reading(1);
        ms += 31_000;
        reading(1);
        assertInstanceOf(ToDropoff.class, runner.phase(), String.join("\n", said));
        runner.replan(1, null); // as the route follower's "edge blocked for 15 s" asks it
        assertInstanceOf(Replanning.class, runner.phase());
        assertEquals(List.of("1->2"), asked);
        plans.get(0).complete(new AclMessage(Performative.FAILURE)
                .setContent(new Failure(null, null, "no route from 1 to 2 and blocked edges [1-2]").encode()));
        assertEquals(TaskView.State.TO_DROPOFF, t.state, "not failed with its patient on board: " + t.reason);
        assertInstanceOf(ToDropoff.class, runner.phase(), String.join("\n", said));
        assertTrue(said.stream().anyMatch(s -> s.startsWith("keeps T1: ") && s.endsWith("asks again in 20 s")), String.join("\n", said));
        reading(1);
        assertEquals(1, asked.size(), "not at once");
        ms += TaskRunner.REPLAN_AGAIN_MS;
        reading(1);
        assertEquals(List.of("1->2", "1->2"), asked, "asked again");
        plans.get(1).complete(plan(1, 2));
        assertInstanceOf(ToDropoff.class, runner.phase(), String.join("\n", said));
        assertEquals(List.of(1, 2), follower.route());
    }
}
