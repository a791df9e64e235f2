package io.concord.sim.scenario;

import io.concord.agents.chair.Pose;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.traffic.TrafficRules;
import io.concord.sim.render.HospitalPicture;
import io.concord.sim.world.SimChair;
import io.concord.testkit.FaultPlan;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Two chairs in ward A's corridor (nodes 1, 2, 4, 5 on one line, 5 m apart, every room a dead
 * end off it), in the simulated hospital: two transports the same way are driven down the
 * corridor at once, the second chair an edge or more behind the first; two the opposite way meet
 * on the one lane and get past each other without a deadlock. The chairs start at nodes 2 and 1
 * (the default hospital with its parking places in that order).
 */
class CorridorTest {
    /** The default hospital with its chairs starting in ward A's corridor: the first at node 2, the second at node 1. */
    static final HospitalMap WARD_A = wardA("[2, 1, 19, 23]");
    /** The chairs start at the corridor's two ends, nodes 1 and 5. */
    static final HospitalMap WARD_A_ENDS = wardA("[1, 5, 19, 23]");
    /** The chairs start at nodes 2 and 4, where the corridor carries two lanes (edges 1-2, 2-4, 4-5). */
    static final HospitalMap WARD_A_LANES = wardA("[2, 4, 19, 23]");
    /** The same with one lane everywhere: the corridor's line only. */
    static final HospitalMap WARD_A_ONE_LANE = wardA("[2, 4, 19, 23]", true);

    private static HospitalMap wardA(String parking) {
        return wardA(parking, false);
    }

    private static HospitalMap wardA(String parking, boolean oneLane) {
        try (java.io.InputStream in = HospitalMap.class.getResourceAsStream("/io/concord/agents/map/hospital.json")) {
            String json = new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
            String moved = json.replaceFirst("\"parking\": \\[[^]]*]", "\"parking\": " + parking);
            if (moved.equals(json) || !json.contains(", \"lanes\": 2")) {
                throw new IllegalStateException("the default hospital has no parking list to change, or no lanes");
            }
            if (oneLane) {
                moved = moved.replace(", \"lanes\": 2", "");
            }
            return HospitalMap.parse(moved, "ward-a");
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** Both chairs on the corridor's line between nodes 1 and 5, both driving. */
    private static boolean bothDriveDownTheCorridor(ScenarioTest.Run r) {
        for (SimChair c : r.world.chairs()) {
            Pose p = c.truePose();
            boolean onIt = p.x() > 3.0 && p.x() < 17.0 && Math.abs(p.y() - 10.8) < 0.6;
            if (!onIt || c.forwardSpeed() < 0.1) {
                return false;
            }
        }
        return true;
    }

    /** Two transports east, from rooms off node 5 (A4, A8) to rooms off node 4 (A3, A7): both chairs drive the corridor at once. */
    @Test
    void aCorridorCarriesTwoChairsGoingTheSameWayAtOnce() {
        sameWay(TrafficRules.IN_ORDER, true);
    }

    /** With whole routes (the rules before), the second chair waits at the corridor's start until the first has left it. */
    @Test
    void withWholeRoutesTheSecondChairWaitsForTheCorridor() {
        sameWay(TrafficRules.WHOLE_ROUTES, false);
    }

    private static void sameWay(TrafficRules rules, boolean together) {
        try (ScenarioTest.Run r = new ScenarioTest.Run(WARD_A, 37, FaultPlan.NONE, 2, rules, MedicalAgent.Settings.standard())) {
            boolean[] seen = new boolean[1];
            r.world.addStepHook(() -> {
                if (!seen[0] && bothDriveDownTheCorridor(r)) {
                    seen[0] = true;
                    HospitalPicture.write(r.world, Path.of("target", "pictures", "corridor-" + rules + ".png"),
                            "two chairs down ward A's corridor, " + (rules == TrafficRules.IN_ORDER ? "rules in order" : "whole routes") + String.format(java.util.Locale.ROOT, ", t = %.1f s",
                                    r.world.worldTimeNs() / 1e9), r.hospital.traffic().holders(), r.hospital.traffic().lanes());
                }
            });
            CompletableFuture<MedicalAgent.Outcome> first = r.medical.transport(20, 17, 3, 10);
            r.sim.runFor(2_000);
            CompletableFuture<MedicalAgent.Outcome> second = r.medical.transport(21, 18, 3, 10);
            assertTrue(r.sim.runUntil(() -> first.isDone() && second.isDone(), 1_800_000), "both ended; log:\n"
                    + String.join("\n", ScenarioTest.tail(r.log, 40)));
            r.writeLogs("corridor-" + rules);
            assertTrue(first.join().done(), first.join().toString());
            assertTrue(second.join().done(), second.join().toString());
            assertEquals(2, first.join().chair().equals(second.join().chair()) ? 1 : 2, "one transport each");
            assertEquals(0, r.world.collisionCount(), "no contact: " + r.world.collisions());
            assertEquals(together, seen[0], together ? "the corridor never carried both chairs at once"
                    : "both drove the corridor at once under whole routes");
        }
    }

    /**
     * Head-on in two lanes: one chair takes a patient from room A6 (south of node 2) to room A7
     * (south of node 4), the other from A3 (north of 4) to A2 (north of 2). Each enters the
     * corridor from a room on its right and leaves it to one on its right, so each keeps its lane
     * (lane 0 east, 0.8 m south of the line; lane 1 west, north of it): the two are on the edge
     * 2-4 at once, driving opposite ways, and pass each other. The picture shows the lanes and the
     * traffic agent's queues in them (target/pictures/corridor-lanes.png).
     */
    @Test
    void twoChairsMeetingHeadOnInTwoLanesPassEachOther() {
        headOn(WARD_A_LANES, true);
    }

    /** The same corridor with one lane: the second chair waits until the first has left the edge 2-4 (what the lanes add). */
    @Test
    void withOneLaneTheSecondChairWaitsForTheFirstToPass() {
        headOn(WARD_A_ONE_LANE, false);
    }

    private static void headOn(HospitalMap map, boolean lanes) {
        try (ScenarioTest.Run r = new ScenarioTest.Run(map, 37, FaultPlan.NONE, 2, TrafficRules.IN_ORDER, MedicalAgent.Settings.standard())) {
            boolean[] passed = new boolean[1];
            boolean[] drawn = new boolean[1];
            double[] closest = {Double.MAX_VALUE};
            r.world.addStepHook(() -> {
                SimChair c0 = r.world.chairs().get(0);
                SimChair c1 = r.world.chairs().get(1);
                if (onEdge2to4(c0) && onEdge2to4(c1) && Math.cos(c0.truePose().heading() - c1.truePose().heading()) < -0.9) {
                    closest[0] = Math.min(closest[0], c0.truePose().distanceTo(c1.truePose().x(), c1.truePose().y()));
                    passed[0] = true;
                    if (!drawn[0] && Math.abs(c0.truePose().x() - c1.truePose().x()) < 0.8) {
                        drawn[0] = true; // side by side
                        HospitalPicture.write(r.world, Path.of("target", "pictures", "corridor-" + (lanes ? "lanes" : "one-lane") + ".png"),
                                "two chairs meet head-on in ward A's corridor, " + (lanes ? "two lanes" : "one lane")
                                        + String.format(java.util.Locale.ROOT, ", t = %.1f s", r.world.worldTimeNs() / 1e9),
                                r.hospital.traffic().holders(), r.hospital.traffic().lanes());
                    }
                }
            });
            CompletableFuture<MedicalAgent.Outcome> east = r.medical.transport(16, 18, 3, 10);
            CompletableFuture<MedicalAgent.Outcome> west = r.medical.transport(17, 3, 3, 10);
            assertTrue(r.sim.runUntil(() -> east.isDone() && west.isDone(), 1_800_000), "both ended; log:\n"
                    + String.join("\n", ScenarioTest.tail(r.log, 60)));
            r.writeLogs("corridor-" + (lanes ? "lanes" : "one-lane"));
            assertTrue(east.join().done(), east.join().toString());
            assertTrue(west.join().done(), west.join().toString());
            assertEquals(0, r.world.collisionCount(), "no contact: " + r.world.collisions());
            assertEquals(lanes, passed[0], lanes ? "the chairs were never on the edge 2-4 at once, driving opposite ways"
                    : "one lane, yet both chairs drove the edge 2-4 at once");
            if (lanes) {
                assertTrue(closest[0] > 2 * HospitalMap.LANE_OFFSET_M - 0.3, "they passed " + closest[0] + " m apart, centre to centre");
            }
            assertEquals(0, r.hospital.traffic().waits().size(), "nobody left waiting: " + r.hospital.traffic().waits());
        }
    }

    /** Between nodes 2 and 4 (x 7.5 to 12.5 m), within the corridor, driving. */
    private static boolean onEdge2to4(SimChair c) {
        Pose p = c.truePose();
        return p.x() > 8.2 && p.x() < 11.8 && Math.abs(p.y() - 10.8) < 1.2 && c.forwardSpeed() > 0.1;
    }

    /**
     * Head-on on one lane: the chairs stand at the corridor's ends (nodes 1 and 5), each takes a
     * patient from where it stands to where the other stands, and neither can pass the other on
     * the line. Each waits for the other (a deadlock); one steps aside out of the corridor (node 6,
     * beyond door WA), the other drives through, and the first comes back. Both end, with no
     * contact and no chair left waiting.
     */
    @Test
    void twoChairsMeetingOnOneLaneGetPastEachOther() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(WARD_A_ENDS, 37, FaultPlan.NONE, 2, TrafficRules.IN_ORDER,
                MedicalAgent.Settings.standard())) {
            CompletableFuture<MedicalAgent.Outcome> east = r.medical.transport(1, 5, 3, 10);
            CompletableFuture<MedicalAgent.Outcome> west = r.medical.transport(5, 1, 3, 10);
            assertTrue(r.sim.runUntil(() -> east.isDone() && west.isDone(), 1_800_000), "both ended; log:\n"
                    + String.join("\n", ScenarioTest.tail(r.log, 60)));
            r.writeLogs("corridor-head-on");
            HospitalPicture.write(r.world, Path.of("target", "pictures", "corridor-head-on.png"));
            assertTrue(east.join().done(), east.join().toString());
            assertTrue(west.join().done(), west.join().toString());
            assertTrue(r.hospital.traffic().deadlocks() >= 1, "they met: " + r.log.stream().filter(l -> l.startsWith("traffic")).toList());
            assertTrue(r.log.stream().anyMatch(l -> l.matches("traffic: control-chair\\d makes way from node [15] to node 6 .*")),
                    "one stepped aside beyond the corridor: " + r.log.stream().filter(l -> l.startsWith("traffic")).toList());
            assertEquals(0, r.world.collisionCount(), "no contact: " + r.world.collisions());
            assertEquals(0, r.hospital.traffic().waits().size(), "nobody left waiting: " + r.hospital.traffic().waits());
        }
    }
}
