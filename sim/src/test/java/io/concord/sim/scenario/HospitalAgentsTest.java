package io.concord.sim.scenario;

import io.concord.agents.control.TaskView;
import io.concord.agents.door.DoorAgent;
import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.proto.Asks;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.*;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.testkit.FaultPlan;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.WorldDoor;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The agents' rules one by one, in the default hospital on the virtual clock. */
class HospitalAgentsTest {

    /** Sends what a test asks it to and keeps the answers. */
    static final class Probe extends Agent {
        Asks asks;

        @Override
        protected void setup() {
            asks = new Asks(this);
            addBehaviour(asks);
        }

        CompletableFuture<AclMessage> ask(String to, String content) {
            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(AID.local(to, "hospital"));
            m.setContent(content);
            return asks.ask(m, 30_000, null);
        }

        CompletableFuture<AclMessage> ask(String to, WheelchairMessage content) {
            return ask(to, content.encode());
        }

        void tell(String to, WheelchairMessage content) {
            AclMessage m = new AclMessage(Performative.INFORM);
            m.addReceiver(AID.local(to, "hospital"));
            m.setContent(content.encode());
            send(m);
        }
    }

    /** A probe started on the hospital's platform, after {@code ms} of the hospital's time (the yellow pages settle). */
    private static Probe probe(ScenarioTest.Run r, String name, long ms) {
        Probe p = new Probe();
        r.platform.startAgent(name, p);
        r.sim.runFor(ms);
        return p;
    }

    private static AclMessage await(ScenarioTest.Run r, CompletableFuture<AclMessage> f) {
        assertTrue(r.sim.runUntil(f::isDone, 60_000), "an answer");
        return f.join();
    }

    @Test
    void theMedicalAgentPicksTheChairOfBestUtility() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 0)) {
            r.world.addChair("far", ChairConfig.standard().withWatchdog(0.3), r.world.poseAt(31, 90));
            r.world.addChair("near", ChairConfig.standard().withWatchdog(0.3), r.world.poseAt(19, 90));
            r.hospital.addChair(r.platform, r.world, r.world.chair("far"), r.log::add);
            r.hospital.addChair(r.platform, r.world, r.world.chair("near"), r.log::add);
            assertTrue(r.sim.runUntil(r.hospital::ready, 60_000));
            var f = r.medical.transport(3, 9, 3, 30);
            assertTrue(r.sim.runUntil(f::isDone, 900_000), String.join("\n", ScenarioTest.tail(r.log, 30)));
            assertTrue(f.join().done(), f.join().toString());
            assertEquals("control-near", f.join().chair(), "the chair in the lobby is nearer node 3");
            assertTrue(r.log.stream().anyMatch(l -> l.startsWith("medical: control-far proposes")), "both proposed");
        }
    }

    @Test
    void transportsAskedForAtOnceAreSpreadOverTheChairs() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(5, FaultPlan.NONE, 3)) {
            var fs = java.util.List.of(r.medical.transport(3, 9, 3, 20), r.medical.transport(14, 31, 0, 20),
                    r.medical.transport(26, 17, 1.5, 20));
            assertTrue(r.sim.runUntil(() -> fs.stream().allMatch(CompletableFuture::isDone), 1_800_000));
            java.util.Set<String> chairs = new java.util.TreeSet<>();
            for (var f : fs) {
                assertTrue(f.join().done(), f.join().toString());
                chairs.add(f.join().chair());
            }
            // Each chair counts its open proposals in its cost; the Medical agent takes out those
            // another chair has won. Without that, the nearest chair won all three at once.
            assertTrue(chairs.size() >= 2, "more than one chair at work: " + chairs);
        }
    }

    /**
     * A plan asked for along a way (a chair told to make way) is that way, not the planner's
     * shortest (19-22-7 is shorter than 19-23-22-7), with its doors asked; a way over an edge the
     * map has not is a FAILURE that names it.
     */
    @Test
    void aPlanAlongAWayIsThatWayWithItsDoorsAsked() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 1)) {
            Probe p = probe(r, "probe", 200);
            AclMessage plan = await(r, p.ask("planner-chair1", "((plan-request :task make-way :from 19 :to 5 :via (sequence 19 23 22 7 6 5)))"));
            assertEquals(Performative.INFORM_REF, plan.getPerformative(), plan.getContent());
            assertEquals(List.of(19, 23, 22, 7, 6, 5), WheelchairMessage.decode(plan, Plan.class).nodes());
            assertEquals(List.of("WA"), WheelchairMessage.decode(plan, Plan.class).doors());
            assertTrue(r.log.contains("planner-chair1: make-way plan [19, 23, 22, 7, 6, 5] through [WA] confirmed"), String.join("\n", r.log));
            AclMessage off = await(r, p.ask("planner-chair1", "((plan-request :task make-way :from 19 :to 5 :via (sequence 19 5)))"));
            assertEquals(Performative.FAILURE, off.getPerformative());
            assertEquals("via: no edge 19-5 on " + r.world.map().name(), WheelchairMessage.reasonOf(off));
        }
    }

    @Test
    void aTaskToAnUnknownNodeIsRefusedWithTheReason() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 1)) {
            var f = r.medical.transport(3, 99, 0, 30);
            assertTrue(r.sim.runUntil(f::isDone, 60_000));
            assertFalse(f.join().done());
            // The real reason, the chair's own (issue 47: it once said only "no chair proposed").
            assertEquals("no chair proposed (control-chair1: unknown node 99)", f.join().reason());
            assertTrue(r.log.contains("medical: control-chair1 refuses T1: unknown node 99"), String.join("\n", r.log));
        }
    }

    /**
     * A proposal that comes after the auction's deadline (the network lost everything for longer
     * than the chairs had to answer) is no answer: the task is auctioned again and done, not given up.
     */
    @Test
    void anAuctionNobodyAnsweredInTimeIsHeldAgain() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 1)) {
            r.sim.network().setFaultPlan(new FaultPlan(1, 0, 0, 0, 50_000, 0, 0));
            var f = r.medical.transport(3, 9, 0, 30);
            r.sim.runFor(2_500);
            r.sim.network().setFaultPlan(FaultPlan.NONE);
            assertTrue(r.sim.runUntil(f::isDone, 900_000), String.join("\n", ScenarioTest.tail(r.log, 30)));
            assertTrue(r.log.contains("medical: no chair answered T1 in time; it is auctioned again"), String.join("\n", r.log));
            assertTrue(f.join().done(), f.join() + "\n" + String.join("\n", ScenarioTest.tail(r.log, 30)));
            assertEquals(2, f.join().auctions());
        }
    }

    @Test
    void aWardBehindAnOfflineDoorIsUnreachableAndTheChairSaysSo() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 1)) {
            r.world.door("WB").setMechanismFailed(true);
            assertTrue(r.sim.runUntil(() -> r.hospital.planner("chair1").knownDoors().stream()
                    .anyMatch(d -> d.id().equals("WB") && d.state().equals("offline")), 5_000), "the planner heard WB go offline");
            var f = r.medical.transport(3, 9, 0, 30);
            assertTrue(r.sim.runUntil(f::isDone, 60_000));
            assertFalse(f.join().done());
            assertTrue(r.log.stream().anyMatch(l -> l.startsWith("medical: control-chair1 refuses T1: no route from 3 to 9")),
                    String.join("\n", r.log));
        }
    }

    @Test
    void aDoorOpensOnlyForAChairItConfirmedAndClosesAfterItsTimeout() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 0)) {
            Probe p = probe(r, "stranger", 2_000);
            AclMessage refused = await(r, p.ask("door-A1", new OpenRequest("nobody")));
            assertEquals(Performative.REFUSE, refused.getPerformative());
            assertTrue(refused.getContent().contains("not confirmed"), refused.getContent());
            DoorAgent door = r.hospital.door("A1");
            assertEquals(DoorAgent.State.CLOSED, door.state());
            // A planner confirms the stranger; now it may ask.
            assertEquals(Performative.CONFIRM, await(r, p.ask("door-A1", new PassRequest("stranger@hospital", null))).getPerformative());
            AclMessage open = await(r, p.ask("door-A1", new OpenRequest("nobody")));
            assertEquals(Performative.INFORM, open.getPerformative());
            assertEquals(DoorAgent.State.OPEN, door.state());
            assertTrue(r.world.door("A1").isOpen());
            p.tell("door-A1", new Passed(null));
            // Five seconds with nobody in the doorway, then it closes.
            r.sim.runFor(4_000);
            assertEquals(DoorAgent.State.OPEN, door.state());
            r.sim.runFor(5_000);
            assertEquals(DoorAgent.State.CLOSED, door.state(), r.log.toString());
            assertTrue(r.world.door("A1").isClosed());
        }
    }

    @Test
    void aClosingDoorThatMeetsAChairStopsAndOpensAgain() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 0)) {
            Probe p = probe(r, "stranger", 2_000);
            await(r, p.ask("door-A1", new PassRequest("stranger@hospital", null)));
            await(r, p.ask("door-A1", new OpenRequest("nobody")));
            p.tell("door-A1", new Passed(null));
            DoorAgent door = r.hospital.door("A1");
            assertTrue(r.sim.runUntil(() -> door.state() == DoorAgent.State.CLOSING, 10_000));
            // A chair rolls into the leaf's way in the room as it closes.
            r.world.addChair("chair1", ChairConfig.standard().noiseless(), new io.concord.agents.chair.Pose(2.9, 13.9, 0));
            assertTrue(r.sim.runUntil(() -> r.log.contains("A1: stopped closing on chair1, opens again"), 10_000), r.log.toString());
            assertTrue(r.sim.runUntil(() -> door.state() == DoorAgent.State.OPEN, 10_000));
            assertEquals(0, r.world.chair("chair1").truePose().distanceTo(2.9, 13.9), 0.03, "not pushed");
            // While the chair stays in the sweep, the door does not close on it.
            r.sim.runFor(20_000);
            assertEquals(DoorAgent.State.OPEN, door.state());
        }
    }

    @Test
    void aDoorWhoseMechanismFailsIsOfflineAndRefusesPassage() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 0)) {
            Probe p = probe(r, "stranger", 2_000);
            WorldDoor d = r.world.door("B2");
            d.setMechanismFailed(true);
            assertTrue(r.sim.runUntil(() -> r.hospital.door("B2").state() == DoorAgent.State.OFFLINE, 1_000));
            AclMessage refused = await(r, p.ask("door-B2", new PassRequest("stranger@hospital", null)));
            assertEquals(Performative.REFUSE, refused.getPerformative());
            assertEquals("offline", WheelchairMessage.reasonOf(refused));
            d.setMechanismFailed(false);
            assertTrue(r.sim.runUntil(() -> r.hospital.door("B2").state() == DoorAgent.State.CLOSED, 1_000));
            assertEquals(Performative.CONFIRM, await(r, p.ask("door-B2", new PassRequest("stranger@hospital", null))).getPerformative());
        }
    }

    @Test
    void aDoorLetsOneChairThroughAtATime() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 0)) {
            Probe a = new Probe();
            Probe b = new Probe();
            r.platform.startAgent("a", a);
            r.platform.startAgent("b", b);
            r.sim.runFor(2_000);
            await(r, a.ask("door-WA", new PassRequest("a@hospital", null)));
            await(r, b.ask("door-WA", new PassRequest("b@hospital", null)));
            var first = a.ask("door-WA", new OpenRequest("ca"));
            assertEquals(Performative.INFORM, await(r, first).getPerformative());
            // Chair a stands in the doorway, now open.
            r.world.addChair("ca", ChairConfig.standard().noiseless(), new io.concord.agents.chair.Pose(19.5, 10.8, 0));
            var second = b.ask("door-WA", new OpenRequest("cb"));
            r.sim.runFor(10_000);
            assertFalse(second.isDone(), "b waits while a is in the doorway");
            assertEquals(java.util.List.of("b@hospital"), r.hospital.door("WA").waiting());
            a.tell("door-WA", new Passed(null));
            r.sim.runFor(2_000);
            assertFalse(second.isDone(), "a said it passed, but its chair is still in the doorway");
            r.world.removeChair("ca");
            assertEquals(Performative.INFORM, await(r, second).getPerformative());
        }
    }

    @Test
    void aSessionLapsesWhenTheChairGoesSilent() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 0)) {
            Probe p = probe(r, "stranger", 2_000);
            await(r, p.ask("door-A3", new PassRequest("stranger@hospital", null)));
            assertEquals(java.util.List.of("stranger@hospital"), r.hospital.door("A3").sessions());
            r.sim.runFor(50_000);
            p.tell("door-A3", new Here(null, null));
            r.sim.runFor(50_000);
            assertEquals(java.util.List.of("stranger@hospital"), r.hospital.door("A3").sessions(), "kept alive");
            r.sim.runFor(70_000);
            assertTrue(r.hospital.door("A3").sessions().isEmpty(), "lapsed after 60 s of silence");
            assertEquals(Performative.REFUSE, await(r, p.ask("door-A3", new OpenRequest("x"))).getPerformative());
        }
    }

    @Test
    void aTaskWithdrawnByTheStaffStopsItsChairAndNobodyElseCanWithdrawIt() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(12, FaultPlan.NONE, 1)) {
            var f = r.medical.transport(3, 9, 3, 30);
            assertTrue(r.sim.runUntil(() -> r.log.stream().anyMatch(l -> l.startsWith("control-chair1: starts T1")), 60_000));
            r.sim.runFor(5_000);
            // A stranger's CANCEL in the task's conversation changes nothing.
            Probe p = probe(r, "stranger", 1_000);
            AclMessage cancel = new AclMessage(Performative.CANCEL);
            cancel.addReceiver(AID.local("control-chair1", "hospital"));
            cancel.setConversationId("T1-1");
            cancel.setContent(new Withdrawal("T1").encode());
            p.send(cancel);
            r.sim.runFor(2_000);
            assertTrue(r.log.contains("control-chair1: ignores a CANCEL of T1 from stranger@hospital: only medical@hospital, who gave it, "
                    + "may withdraw it"), String.join("\n", ScenarioTest.tail(r.log, 10)));
            assertEquals(TaskView.State.TO_PICKUP, r.hospital.control("chair1").tasks().get(0).state());
            // A member that did not ask for it cannot have the Medical agent withdraw it either.
            AclMessage refused = await(r, p.ask("medical", "((cancel-request :task T1 :reason \"not mine\"))"));
            assertEquals(Performative.REFUSE, refused.getPerformative(), refused.getContent());
            assertTrue(WheelchairMessage.reasonOf(refused).startsWith(
                    "stranger@hospital did not ask for T1 (medical@hospital did): a member cancels only the transports it asked for, an operator any"),
                    WheelchairMessage.reasonOf(refused));
            AclMessage unknown = await(r, p.ask("medical", "((cancel-request :task T7))"));
            assertEquals(Performative.REFUSE, unknown.getPerformative(), unknown.getContent());
            assertTrue(WheelchairMessage.reasonOf(unknown).startsWith("no transport T7 under way"), unknown.getContent());
            assertEquals(TaskView.State.TO_PICKUP, r.hospital.control("chair1").tasks().get(0).state());
            // The staff withdraw it: the chair stops and drops it.
            var withdrawn = r.medical.cancel("T1", "the patient went home");
            assertTrue(r.sim.runUntil(withdrawn::isDone, 1_000) && withdrawn.join());
            r.sim.runFor(3_000);
            double at = r.world.chair("chair1").distanceTravelled();
            r.sim.runFor(30_000);
            assertTrue(f.isDone() && !f.join().done());
            assertEquals("withdrawn: the patient went home", f.join().reason());
            assertEquals(TaskView.State.CANCELLED, r.hospital.control("chair1").tasks().get(0).state());
            assertTrue(r.world.chair("chair1").distanceTravelled() - at < 0.05, "the chair stands");
            assertTrue(r.log.contains("control-chair1: task T1 withdrawn by medical"));
        }
    }

    /**
     * A transport the staff asked for (as the demo's {@code --tasks} do) is withdrawn by a member
     * carrying an operator's signed order, once: an order of a key the ward did not configure, an
     * order for another transport, a tampered one and the same order again are refused, each
     * saying why, and the transport goes on until the good one.
     */
    @Test
    void anOperatorsSignedCancelWithdrawsTheStaffsTransportOnce() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(12, FaultPlan.NONE, 1)) {
            io.concord.layers.authority.OperatorKey ada = io.concord.layers.authority.OperatorKey.generate("nurse Ada");
            io.concord.layers.authority.OperatorKey eve = io.concord.layers.authority.OperatorKey.generate("eve");
            r.medical.operators(io.concord.layers.authority.Operators.of(ada.operator()));
            var f = r.medical.transport(3, 9, 3, 30);
            assertTrue(r.sim.runUntil(() -> r.log.stream().anyMatch(l -> l.startsWith("control-chair1: starts T1")), 60_000));
            Probe p = probe(r, "desk", 1_000);
            java.util.function.Function<String, String> refusal = order -> {
                AclMessage a = await(r, p.ask("medical", new CancelRequest("T1", "the patient went home", order)));
                assertEquals(Performative.REFUSE, a.getPerformative(), a.getContent());
                return WheelchairMessage.reasonOf(a);
            };
            long now = r.rt.clock().epochMillis();
            assertTrue(refusal.apply(eve.sign("cancel", "T1", now).encode()).startsWith("the operator's order is refused: eve is not an operator of this ward"));
            assertTrue(refusal.apply(ada.sign("cancel", "T2", now).encode()).startsWith("the operator's order is refused: "));
            assertTrue(refusal.apply(ada.sign("resume", "T1", now).encode()).startsWith("the operator's order is refused: "));
            String good = ada.sign("cancel", "T1", now).encode();
            String tampered = good.replace("|" + now + "|", "|" + (now + 1) + "|");
            assertFalse(tampered.equals(good));
            assertTrue(refusal.apply(tampered).startsWith("the operator's order is refused: "));
            assertFalse(f.isDone(), "T1 goes on after every refusal");
            assertEquals(TaskView.State.TO_PICKUP, r.hospital.control("chair1").tasks().get(0).state());
            CompletableFuture<AclMessage> agreement = new CompletableFuture<>();
            AclMessage ask = new AclMessage(Performative.REQUEST);
            ask.addReceiver(AID.local("medical", "hospital"));
            ask.setContent(new CancelRequest("T1", "the patient went home", good).encode());
            p.asks.ask(ask, 30_000, agreement::complete);
            AclMessage agreed = await(r, agreement);
            assertEquals(Performative.AGREE, agreed.getPerformative(), agreed.getContent());
            assertTrue(r.sim.runUntil(f::isDone, 1_000));
            assertEquals("withdrawn: the patient went home (by operator nurse Ada, asked by desk)", f.join().reason());
            assertTrue(r.sim.runUntil(() -> r.hospital.control("chair1").tasks().get(0).state() == TaskView.State.CANCELLED, 5_000));
            // The same order again: seen before (and the transport has ended).
            assertEquals(Performative.REFUSE, await(r, p.ask("medical", new CancelRequest("T1", "again", good))).getPerformative());
        }
    }

    /**
     * A trolley left across the chair's way out of the lobby: the obstacle filter between its route
     * follower and its supervisor stops it short, and the edge is reported blocked; with the filter
     * switched off (the test's switch), the same chair on the same seed drives into the trolley.
     */
    @Test
    void theObstacleFilterStopsAChairShortOfATrolleyAndWithoutItTheChairHitsIt() {
        assertEquals(0, trolleyRun(true), "with the filter: no contact");
        assertTrue(trolleyRun(false) > 0, "without the filter the chair drives into the trolley");
    }

    /** Contacts of a chair sent from the lobby (node 19) to node 3 past a trolley on its way. */
    private static long trolleyRun(boolean filter) {
        try (ScenarioTest.Run r = new ScenarioTest.Run(7, FaultPlan.NONE, 1)) {
            r.world.addBox("trolley", new io.concord.agents.map.Point(24, 6.0), 1.6, 0.5, 0);
            r.hospital.control("chair1").obstacleFilter().enabled(filter);
            r.medical.transport(19, 3, 0, 1);
            if (filter) {
                assertTrue(r.sim.runUntil(() -> r.log.stream().anyMatch(l -> l.startsWith("control-chair1: stops: something")), 60_000),
                        String.join("\n", ScenarioTest.tail(r.log, 20)));
                assertTrue(r.sim.runUntil(() -> r.log.stream().anyMatch(l -> l.contains("blocked")), 30_000),
                        "stopped 15 s on the edge, it is reported blocked: " + String.join("\n", ScenarioTest.tail(r.log, 20)));
                assertTrue(r.hospital.control("chair1").obstacleFilter().counts().get("obstacle-stop") > 0);
            } else {
                r.sim.runUntil(() -> r.world.collisionCount() > 0, 60_000);
            }
            return r.world.collisionCount();
        }
    }

    @Test
    void aTaskWhoseChairCrashesIsAuctionedAgainAndDone() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(11, FaultPlan.NONE, 2)) {
            var f = r.medical.transport(3, 9, 3, 30);
            // chair1 (parked at 19, a little nearer) wins and sets off; its agent dies at once, leaving the
            // chair where it stood, off chair2's way.
            assertTrue(r.sim.runUntil(() -> r.log.stream().anyMatch(l -> l.startsWith("control-chair1: starts T1")), 60_000),
                    String.join("\n", r.log));
            AID c1 = r.rt.agents().stream().filter(a -> a.localName().equals("control-chair1")).findFirst().orElseThrow();
            r.rt.crashAgent(c1);
            double before = r.world.chair("chair1").distanceTravelled();
            boolean ended = r.sim.runUntil(f::isDone, 1_800_000);
            r.writeLogs("crash");
            assertTrue(ended, String.join("\n", ScenarioTest.tail(r.log, 30)));
            MedicalAgent.Outcome o = f.join();
            assertTrue(o.done(), o.toString());
            assertEquals("control-chair2", o.chair());
            assertEquals(2, o.auctions());
            assertTrue(r.log.contains("medical: control-chair1 went silent on T1"));
            assertTrue(r.world.chair("chair1").distanceTravelled() - before < 0.3, "the abandoned chair does not drive on");
        }
    }

    @Test
    void theScenarioSurvivesALossyNetwork() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(5, FaultPlan.lossy(0.2, 0.1, 0.1, 0.02), 1)) {
            var f = r.medical.transport(3, 9, 3, 60);
            assertTrue(r.sim.runUntil(f::isDone, 900_000), String.join("\n", ScenarioTest.tail(r.log, 30)));
            assertTrue(f.join().done(), f.join() + "\n" + String.join("\n", ScenarioTest.tail(r.log, 30)));
            assertTrue(r.world.chair("chair1").truePose().distanceTo(40.5, 6) < 0.2);
        }
    }


    @Test
    void theContainersHostDiesMidTaskAndTheTaskIsStillDone() {
        io.concord.testkit.Simulation sim = new io.concord.testkit.Simulation(13, FaultPlan.NONE);
        sim.platformName("hospital");
        try (sim) {
            java.util.function.Function<io.concord.core.agent.AgentRuntime, io.concord.layers.Platform> platformOn =
                    rt -> io.concord.layers.Platform.builder().runtime(rt)
                            .ports(new io.concord.core.agent.PortRange(7001, 200, 10))
                            .safetyStack(io.concord.layers.SafetyStack.builder().profile(io.concord.layers.Profile.CLOSED).build())
                            .build();
            // The oldest agent becomes the container: it runs in a process of its own.
            var infra = sim.newRuntime("h1");
            var registry = new Agent() { };
            platformOn.apply(infra).startAgent("registry", registry);
            sim.runFor(2_000);
            var ward = sim.newRuntime("h1");
            var wardPlatform = platformOn.apply(ward);
            var world = io.concord.sim.world.HospitalWorld.builder(ScenarioTest.MAP).seed(13).build();
            world.addChair("chair1", ChairConfig.standard().withWatchdog(0.3), world.poseAt(19, 90));
            world.attach(ward);
            java.util.List<String> log = new java.util.ArrayList<>();
            var hospital = io.concord.sim.Hospital.start(wardPlatform, world, log::add);
            var staff = sim.newRuntime("h1");
            MedicalAgent medical = new MedicalAgent(log::add);
            platformOn.apply(staff).startAgent("medical", medical);
            assertTrue(sim.runUntil(hospital::ready, 60_000));
            assertTrue(sim.runUntil(() -> io.concord.layers.Platform.of(medical).agents().size() >= 22, 30_000));
            assertEquals("registry@hospital", io.concord.layers.Platform.of(medical).container(), "the registry is container");
            var f = medical.transport(3, 9, 3, 30);
            assertTrue(sim.runUntil(() -> log.stream().anyMatch(l -> l.startsWith("control-chair1: starts T1")), 60_000));
            sim.runFor(20_000);
            sim.crash(infra);
            assertTrue(sim.runUntil(() -> !"registry@hospital".equals(io.concord.layers.Platform.of(medical).container())
                    && io.concord.layers.Platform.of(medical).container() != null, 30_000), "a new container");
            assertTrue(sim.runUntil(f::isDone, 900_000), String.join("\n", ScenarioTest.tail(log, 30)));
            assertTrue(f.join().done(), f.join().toString());
            assertEquals(1, f.join().auctions(), "the same chair finished it");
            assertTrue(world.chair("chair1").truePose().distanceTo(40.5, 6) < 0.2);
        }
    }

    @Test
    void aTransportAskedForByAclIsAgreedAndReportedDone() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(3, FaultPlan.NONE, 1)) {
            Probe ward = new Probe();
            r.platform.startAgent("ward-nurse", ward);
            r.sim.runFor(2_000);
            java.util.List<AclMessage> agreed = new java.util.ArrayList<>();
            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(AID.local("medical", "hospital"));
            m.setContent("((transport-request :from 3 :to 9 :priority 1.5 :unload 30))");
            var answer = ward.asks.ask(m, 900_000, agreed::add);
            assertTrue(r.sim.runUntil(answer::isDone, 900_000), String.join("\n", ScenarioTest.tail(r.log, 20)));
            assertEquals(1, agreed.size(), "AGREE first");
            assertEquals(Performative.INFORM, answer.join().getPerformative());
            Done done = WheelchairMessage.decode(answer.join(), Done.class);
            assertEquals("control-chair1", done.chair());
            AclMessage bad = await(r, ward.ask("medical", "((transport-request :from 3))"));
            assertEquals(Performative.REFUSE, bad.getPerformative());
            assertTrue(bad.getContent().contains("missing mandatory slot :to of transport-request"), bad.getContent());
            AclMessage urgent = await(r, ward.ask("medical", "((transport-request :from 3 :to 9 :priority 7.0))"));
            assertEquals(Performative.REFUSE, urgent.getPerformative());
            assertTrue(WheelchairMessage.reasonOf(urgent).contains("priority is 0 to 3"), urgent.getContent());
            // What the Medical agent does not take is answered too, not left in its mailbox.
            AclMessage old = await(r, ward.ask("medical", "transport; from=3; to=9"));
            assertEquals(Performative.NOT_UNDERSTOOD, old.getPerformative());
            assertTrue(old.getContent().startsWith("content is not FIPA-SL"), old.getContent());
            AclMessage other = await(r, ward.ask("medical", "((teleport :to 9))"));
            assertEquals(Performative.NOT_UNDERSTOOD, other.getPerformative());
            assertEquals("unknown request 'teleport'; the Medical agent takes transport-request and cancel-request (docs/wheelchair-protocol.md)", other.getContent());
            AclMessage toChair = await(r, ward.ask("control-chair1", "((teleport :to 9))"));
            assertEquals(Performative.NOT_UNDERSTOOD, toChair.getPerformative(), "a control agent answers too");
        }
    }

    @Test
    void aChairBlockedOnAnEdgeTellsItsPlannerAndDrivesAroundIt() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(4, FaultPlan.NONE, 0)) {
            r.world.addChair("chair1", ChairConfig.standard().withWatchdog(0.3), r.world.poseAt(22, -90));
            r.hospital.addChair(r.platform, r.world, r.world.chair("chair1"), r.log::add);
            assertTrue(r.sim.runUntil(r.hospital::ready, 60_000));
            // A trolley left on the lobby's edge 22-19.
            r.world.addBox("trolley", new io.concord.agents.map.Point(24, 5.0), 0.8, 0.5, 0);
            var f = r.medical.transport(19, 21, 0, 10);
            assertTrue(r.sim.runUntil(f::isDone, 900_000), String.join("\n", ScenarioTest.tail(r.log, 30)));
            assertTrue(f.join().done(), f.join() + "\n" + String.join("\n", ScenarioTest.tail(r.log, 30)));
            assertTrue(r.log.stream().anyMatch(l -> l.startsWith("control-chair1: edge 22-19 blocked")), String.join("\n", r.log));
            assertTrue(r.log.stream().anyMatch(l -> l.startsWith("planner-chair1: edge 19-22 blocked")));
            assertTrue(r.log.stream().anyMatch(l -> l.startsWith("control-chair1: new plan [22, 23, 19]")), String.join("\n", r.log));
            assertEquals(0, r.world.collisionCount(), "stopped short of the trolley: " + r.world.collisions());
        }
    }
}
