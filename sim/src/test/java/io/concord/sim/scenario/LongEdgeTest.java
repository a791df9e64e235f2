package io.concord.sim.scenario;

import io.concord.agents.chair.Pose;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.traffic.TrafficSettings;
import io.concord.sim.VirtualHospital;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.SimChair;
import io.concord.testkit.FaultPlan;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Edges of 10 m (issue 47): a corridor 2.2 m wide along the south of a hall, its 10 m edge ending
 * 1.1 m from the end wall where the chair turns north into the hall, then 9.8 m west along the
 * hall. A chair whose wheels differ in size by the worst of the hospital's chairs (three times
 * the standard chair's 0.2 %, drawn per wheel) drives a transport there and back. With floor
 * markers along the long edges ({@link HospitalMap#edgeMarkers()}: none more than 3 m apart) it
 * keeps within 0.2 m of its lines and touches nothing; with markers at the nodes only, its
 * heading drifts along the edge, it arrives up to half a metre off its line and touches a wall
 * where it turns, in at least one of the seeds.
 */
class LongEdgeTest {
    static final HospitalMap MAP = HospitalMap.parse("""
            {"format": "concord-hospital-map/1", "name": "long-edges",
             "walls": [{"id": "outer", "path": [[0, 0], [14, 0], [14, 6], [0, 6], [0, 0]]},
                       {"id": "corridor", "from": [0, 2.2], "to": [11.6, 2.2]}],
             "areas": [{"id": "ward", "kind": "ward", "polygon": [[0, 0], [14, 0], [14, 6], [0, 6]]},
                       {"id": "c", "kind": "corridor", "ward": "ward", "polygon": [[0, 0], [14, 0], [14, 2.2], [0, 2.2]]},
                       {"id": "h", "kind": "hall", "ward": "ward", "polygon": [[0, 2.2], [14, 2.2], [14, 6], [0, 6]]}],
             "nodes": [{"id": 1, "at": [2.8, 1.1], "name": "west end"},
                       {"id": 2, "at": [12.8, 1.1], "name": "east end"},
                       {"id": 3, "at": [12.8, 4.5], "name": "hall, east"},
                       {"id": 4, "at": [3, 4.5], "name": "hall, west"}],
             "edges": [{"from": 1, "to": 2}, {"from": 2, "to": 3}, {"from": 3, "to": 4}],
             "parking": [1]}
            """, "long-edges");
    static final int SEEDS = 4;

    record Outcome(long seed, boolean done, long contacts, double worstOffLineM) {
    }

    /** The chair's true distance from the line of the edge it drives (the nearest of the three). */
    static double offLine(Pose p) {
        double south = Math.abs(p.y() - 1.1);
        double east = Math.abs(p.x() - 12.8);
        double north = Math.abs(p.y() - 4.5);
        return Math.min(south, Math.min(east, north));
    }

    static Outcome run(long seed, boolean edgeMarkers) {
        List<String> log = new ArrayList<>();
        ChairConfig worst = ChairConfig.standard().withWatchdog(0.3).withWheelErrors(0.006, 0.002);
        try (VirtualHospital v = new VirtualHospital(MAP, seed, FaultPlan.NONE, 1, TrafficSettings.standard(),
                MedicalAgent.Settings.standard(), log::add, worst, HospitalWorld.builder(MAP).seed(seed).edgeMarkers(edgeMarkers))) {
            assertTrue(v.ready(), "the hospital starts: " + log);
            v.sim.runFor(5_000); // a map with no doors is ready at once: the chair's agent registers in the yellow pages meanwhile
            SimChair chair = v.world.chair("chair1");
            double[] worstOff = {0};
            v.world.addStepHook(() -> worstOff[0] = Math.max(worstOff[0], offLine(chair.truePose())));
            CompletableFuture<MedicalAgent.Outcome> f = v.medical.transport(4, 1, MedicalAgent.PRIORITIES[0], 10);
            v.sim.runUntil(f::isDone, 600_000);
            if (!f.isDone() || !f.join().done()) {
                System.out.println("seed " + seed + ": " + (f.isDone() ? f.join() : "not done") + "\n  " + String.join("\n  ",
                        log.subList(Math.max(0, log.size() - 15), log.size())));
            }
            return new Outcome(seed, f.isDone() && f.join().done(), v.world.collisionCount(), worstOff[0]);
        }
    }

    @Test
    void withMarkersAlongTheLongEdgesTheWorstChairKeepsItsLinesAndTouchesNothing() {
        for (long seed = 1; seed <= SEEDS; seed++) {
            Outcome o = run(seed, true);
            System.out.printf(Locale.ROOT, "long edges, markers along them, seed %d: done %s, %d contacts, %.2f m off its line at worst%n",
                    seed, o.done(), o.contacts(), o.worstOffLineM());
            assertTrue(o.done(), o.toString());
            assertEquals(0, o.contacts(), o.toString());
            assertTrue(o.worstOffLineM() < 0.2, "within 0.2 m of its line: " + o);
        }
    }

    @Test
    void withMarkersAtTheNodesOnlyTheWorstChairDriftsIntoAWall() {
        List<Outcome> all = new ArrayList<>();
        for (long seed = 1; seed <= SEEDS; seed++) {
            Outcome o = run(seed, false);
            System.out.printf(Locale.ROOT, "long edges, markers at the nodes only, seed %d: done %s, %d contacts, %.2f m off its line at worst%n",
                    seed, o.done(), o.contacts(), o.worstOffLineM());
            all.add(o);
        }
        assertTrue(all.stream().anyMatch(o -> o.contacts() > 0), "the hazard: a contact where it turns: " + all);
    }
}
