package io.concord.sim.scenario;

import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.traffic.TrafficSettings;
import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage.Here;
import io.concord.agents.proto.WheelchairMessage.Release;
import io.concord.agents.proto.WheelchairMessage.Reserve;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.TickerBehaviour;
import io.concord.testkit.FaultPlan;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A transport is never abandoned with a patient on board, and a chair held up longer than it quoted
 * is not taken for a silent one: the chair reports its progress (each phase, each node, and every
 * 20 s while the task is its own), each report gives it more time, and once it is at the patient the
 * task is never withdrawn nor auctioned again. Two chairs; another body holds a node of the winner's
 * route through the traffic agent (it stands there, busy, and stays alive) for longer than the
 * Medical agent's deadline for the result (three times the quoted cost and two minutes).
 */
class PatientOnBoardTest {

    /** Stands on a node, as far as the traffic agent knows: holds it, says it is alive, gives it back when told. */
    static final class Blocker extends Agent {
        private final int node;

        Blocker(int node) {
            this.node = node;
        }

        @Override
        protected void setup() {
            tell(Performative.REQUEST, new Reserve(List.of(node), List.of(node), false).encode());
            addBehaviour(new TickerBehaviour(this, 20_000) {
                @Override
                protected void onTick() {
                    tell(Performative.INFORM, new Here(null, List.of(node)).encode());
                }
            });
        }

        void leave() {
            runtime().execute(() -> tell(Performative.INFORM, new Release(node).encode()));
        }

        private void tell(Performative p, String content) {
            AclMessage m = new AclMessage(p);
            m.addReceiver(AID.local("traffic", "hospital"));
            m.setOntology(Services.ONTOLOGY);
            m.setContent(content);
            send(m);
        }
    }

    private static boolean logged(ScenarioTest.Run r, String text) {
        return r.log.stream().anyMatch(l -> l.contains(text));
    }

    private static String tail(ScenarioTest.Run r) {
        return String.join("\n", ScenarioTest.tail(r.log, 40));
    }

    /**
     * Held up on its way to the patient (node 4 of its route is held) for 20 minutes, longer than
     * its quote allows (3 x its cost + 120 s, the cost with the wait for the chair on node 4 in it): its progress reports keep the task its own; no second auction, and it
     * fetches the patient once the way is free.
     */
    @Test
    void aChairHeldUpLongerThanItsQuoteKeepsItsTask() {
        heldUpOnTheWayToThePatient(MedicalAgent.Settings.standard(), true);
    }

    /** The same run with progress reports not counted (the defence off): the task is auctioned again. */
    @Test
    void withoutProgressReportsTheTaskIsAuctionedAgain() {
        heldUpOnTheWayToThePatient(MedicalAgent.Settings.standard().withProgressMs(0), false);
    }

    private static void heldUpOnTheWayToThePatient(MedicalAgent.Settings settings, boolean kept) {
        try (ScenarioTest.Run r = new ScenarioTest.Run(2010, FaultPlan.NONE, 2, true, settings)) {
            Blocker blocker = new Blocker(4);
            r.platform.startAgent("blocker", blocker);
            r.sim.runFor(1_000);
            CompletableFuture<MedicalAgent.Outcome> f = r.medical.transport(3, 9, 3, 60);
            assertTrue(r.sim.runUntil(() -> logged(r, "to-pickup at node"), 60_000), "the chair set off; log:\n" + tail(r));
            r.sim.runFor(1_200_000);
            assertEquals(kept, !logged(r, "(auction 2)"), "a second auction while the chair was held up; log:\n" + tail(r));
            if (!kept) {
                return;
            }
            assertFalse(f.isDone());
            blocker.leave();
            assertTrue(r.sim.runUntil(f::isDone, 900_000), "the transport ended; log:\n" + tail(r));
            MedicalAgent.Outcome o = f.join();
            assertTrue(o.done(), o.toString());
            assertEquals(1, o.auctions(), o.toString());
        }
    }

    /**
     * Held up after loading (node 10 of its way to the drop-off is held) past the Medical agent's
     * deadline, with progress reports not counted so that the deadline passes: the task is neither
     * withdrawn nor auctioned again (the patient is not at node 3 any more); the chair that has the
     * patient delivers them once the way is free, and the Medical agent takes its late result.
     */
    @Test
    void aPatientOnBoardIsNeverFetchedAgain() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(2010, FaultPlan.NONE, 2, true, MedicalAgent.Settings.standard().withProgressMs(0))) {
            Blocker blocker = new Blocker(10);
            r.platform.startAgent("blocker", blocker);
            r.sim.runFor(1_000);
            CompletableFuture<MedicalAgent.Outcome> f = r.medical.transport(3, 9, 3, 60);
            assertTrue(r.sim.runUntil(() -> logged(r, "(the patient is on board)"), 600_000), "the patient got on; log:\n" + tail(r));
            assertTrue(r.sim.runUntil(() -> logged(r, "went silent on T1"), 1_800_000), "the deadline passed; log:\n" + tail(r));
            r.sim.runFor(300_000);
            assertTrue(logged(r, "nobody else is sent"), tail(r));
            assertFalse(logged(r, "(auction 2)"), "a second auction for a patient on board; log:\n" + tail(r));
            assertFalse(logged(r, "withdrawn"), "the task was withdrawn from the chair that has the patient; log:\n" + tail(r));
            assertFalse(f.isDone());
            blocker.leave();
            assertTrue(r.sim.runUntil(f::isDone, 900_000), "the transport ended; log:\n" + tail(r));
            MedicalAgent.Outcome o = f.join();
            assertTrue(o.done(), o.toString());
            assertEquals(1, o.auctions(), o.toString());
        }
    }

    /**
     * The fleet monitor (issue 47): held up after loading (node 10 of its way to the drop-off is
     * held) for longer than the limit (120 s of hospital time), the chair raises an alarm: in the
     * traffic agent's log, naming what it waits for, and to the Medical agent, which marks it urgent
     * since the chair has T1's patient on board.
     */
    @Test
    void aChairHeldPastTheLimitWithAPatientOnBoardRaisesAnUrgentAlarm() {
        List<MedicalAgent.Alarm> alarms = heldWithThePatientOnBoard(TrafficSettings.standard());
        MedicalAgent.Alarm a = alarms.stream().filter(x -> "T1".equals(x.task())).findFirst().orElse(null);
        assertTrue(a != null, "an alarm for T1's chair: " + alarms);
        assertTrue(a.urgent(), "urgent: the patient is on board: " + a);
        assertTrue(a.seconds() >= 120, a.toString());
        assertTrue(a.waits().contains(" 10, ") && a.waits().contains("in the way: [blocker]"), "it names what it waits for: " + a.waits());
    }

    /** The same with the monitor's alarm switched off on this traffic agent: nobody is told. */
    @Test
    void withoutTheMonitorNobodyIsToldOfTheChairHeldWithItsPatient() {
        List<MedicalAgent.Alarm> alarms = heldWithThePatientOnBoard(TrafficSettings.standard().without(TrafficSettings.Rule.ALARM));
        assertEquals(List.of(), alarms.stream().filter(x -> "T1".equals(x.task())).toList(), "no alarm without the rule");
    }

    private static List<MedicalAgent.Alarm> heldWithThePatientOnBoard(TrafficSettings traffic) {
        try (ScenarioTest.Run r = new ScenarioTest.Run(ScenarioTest.MAP, 2010, FaultPlan.NONE, 2, traffic, MedicalAgent.Settings.standard())) {
            Blocker blocker = new Blocker(10);
            r.platform.startAgent("blocker", blocker);
            r.sim.runFor(1_000);
            CompletableFuture<MedicalAgent.Outcome> f = r.medical.transport(3, 9, 3, 60);
            assertTrue(r.sim.runUntil(() -> logged(r, "(the patient is on board)"), 600_000), "the patient got on; log:\n" + tail(r));
            r.sim.runFor(200_000);
            assertFalse(f.isDone(), "still held");
            List<MedicalAgent.Alarm> alarms = r.medical.alarms();
            if (traffic.on(TrafficSettings.Rule.ALARM)) {
                assertTrue(logged(r, "traffic: ALARM"), "in the traffic agent's log too; log:\n" + tail(r));
                assertTrue(logged(r, "URGENT ALARM: T1's patient is on board"), "and the Medical agent's; log:\n" + tail(r));
            }
            blocker.leave();
            assertTrue(r.sim.runUntil(f::isDone, 900_000), "the transport ended; log:\n" + tail(r));
            assertTrue(f.join().done(), f.join().toString());
            return alarms;
        }
    }

    /**
     * A transport asked with 400 s to get the patient on and off (a newcomer's planned long
     * loading): the chair stands 400 s at the pick-up with no progress, and the monitor's alarms at
     * 120 and 240 s are logged by the Medical agent as what was asked, not as alarms; the transport
     * ends with no alarm kept.
     */
    @Test
    void aChairStandingAsAskedWhileThePatientGetsOnRaisesNoAlarm() {
        List<MedicalAgent.Alarm> alarms = standingAsAsked(MedicalAgent.Settings.standard());
        assertEquals(List.of(), alarms, "no alarm for a loading as long as asked");
    }

    /** The same with the planned dwell not known (the rule off): an urgent alarm while the patient gets on. */
    @Test
    void withoutThePlannedDwellTheLongLoadingIsAnUrgentAlarm() {
        List<MedicalAgent.Alarm> alarms = standingAsAsked(MedicalAgent.Settings.standard().withoutDwellKnown());
        assertTrue(alarms.stream().anyMatch(a -> "T1".equals(a.task()) && a.urgent()), alarms.toString());
    }

    private static List<MedicalAgent.Alarm> standingAsAsked(MedicalAgent.Settings settings) {
        try (ScenarioTest.Run r = new ScenarioTest.Run(ScenarioTest.MAP, 2010, FaultPlan.NONE, 2, TrafficSettings.standard(), settings)) {
            r.sim.runFor(1_000);
            CompletableFuture<MedicalAgent.Outcome> f = r.medical.transport(3, 9, 3, 400);
            assertTrue(r.sim.runUntil(f::isDone, 3_600_000), "the transport ended; log:\n" + tail(r));
            assertTrue(f.join().done(), f.join().toString());
            assertTrue(logged(r, "traffic: ALARM"), "the monitor saw the chair stand; log:\n" + tail(r));
            if (settings.dwellKnown()) {
                assertTrue(logged(r, "s of the 400 s asked, not an alarm"), "and the Medical agent said why it is none; log:\n" + tail(r));
            }
            return r.medical.alarms();
        }
    }

    /**
     * The same long loading, and then the way on held (node 4, the first of its way to the
     * drop-off, taken once the patient is on board): the chair never leaves the pick-up. The
     * alarms taken for the loading are not the last word: once the time asked is over and the
     * limit has passed again, the Medical agent raises an urgent alarm of its own.
     */
    @Test
    void aChairThatStaysPastItsLongLoadingRaisesAnUrgentAlarmSoonAfter() {
        List<MedicalAgent.Alarm> alarms = heldAfterLoading(400, MedicalAgent.Settings.standard());
        assertTrue(alarms.stream().anyMatch(a -> "T1".equals(a.task()) && a.urgent() && a.waits().contains("past the time asked")),
                alarms.toString());
    }

    /**
     * A 100 s loading, then the way on held: the monitor's first alarm, 120 s from the chair's
     * arrival, comes 20 s after the patient got on, and is not taken as one; the first alarm kept is
     * the Medical agent's own, the limit after the loading ended.
     */
    @Test
    void anAlarmJustAfterALoadingWaitsForTheLimitFromItsEnd() {
        List<MedicalAgent.Alarm> t1 = heldAfterLoading(100, MedicalAgent.Settings.standard()).stream()
                .filter(a -> "T1".equals(a.task())).toList();
        assertTrue(!t1.isEmpty() && t1.get(0).waits().contains("past the time asked") && t1.get(0).seconds() >= 120, t1.toString());
    }

    /** The same with the planned dwell not known: the first alarm kept is the monitor's, 20 s after the patient got on. */
    @Test
    void withoutThePlannedDwellTheAlarmJustAfterALoadingIsKept() {
        List<MedicalAgent.Alarm> t1 = heldAfterLoading(100, MedicalAgent.Settings.standard().withoutDwellKnown()).stream()
                .filter(a -> "T1".equals(a.task())).toList();
        assertTrue(!t1.isEmpty() && !t1.get(0).waits().contains("past the time asked"), t1.toString());
    }

    private static List<MedicalAgent.Alarm> heldAfterLoading(int loadingS, MedicalAgent.Settings settings) {
        try (ScenarioTest.Run r = new ScenarioTest.Run(ScenarioTest.MAP, 2010, FaultPlan.NONE, 2, TrafficSettings.standard(), settings)) {
            r.sim.runFor(1_000);
            CompletableFuture<MedicalAgent.Outcome> f = r.medical.transport(3, 9, 3, loadingS);
            assertTrue(r.sim.runUntil(() -> logged(r, "(the patient is on board)"), 600_000), "the patient got on; log:\n" + tail(r));
            Blocker blocker = new Blocker(4);
            r.platform.startAgent("blocker", blocker);
            r.sim.runFor(loadingS * 1000L + 150_000);
            List<MedicalAgent.Alarm> alarms = r.medical.alarms();
            blocker.leave();
            assertTrue(r.sim.runUntil(f::isDone, 900_000), "the transport ended; log:\n" + tail(r));
            return alarms;
        }
    }
}
