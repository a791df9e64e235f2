package io.concord.agents.control;

import io.concord.agents.chair.Pose;
import io.concord.agents.map.Edge;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static io.concord.agents.control.Fakes.SMALL;
import static io.concord.agents.control.Fakes.clear;
import static io.concord.agents.control.Fakes.reading;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The route follower alone, on a chair that records its commands and a map of three nodes: the
 * corridor from node 3 (8, 2) west to node 1 (5, 2), and through door D1 north to the room's node 2.
 * Time is the readings' (the chair's clock), set by each test.
 */
class RouteFollowerTest {
    static final Pose AT_3_FACING_WEST = new Pose(8, 2, Math.PI);
    static final Pose AT_1_FACING_NORTH = new Pose(5, 2, Math.PI / 2);

    final Fakes.Chair chair = new Fakes.Chair();
    final io.concord.agents.chair.ObstacleFilter filter = new io.concord.agents.chair.ObstacleFilter(chair);
    final RouteFollower follower = new RouteFollower(filter, SMALL);
    final List<String> told = new ArrayList<>();
    boolean trafficGrants = true;
    boolean doorOpen = true;
    /** The last index of the route it may drive to (the traffic agent's upto). */
    int clearTo = Integer.MAX_VALUE;

    final RouteFollower.Way way = new RouteFollower.Way() {
        @Override
        public boolean mayDrive(List<Integer> route, List<Integer> standsOn) {
            told.add("may I drive " + route + " from " + standsOn);
            return trafficGrants;
        }

        @Override
        public boolean mayGoOn(List<Integer> route, int index) {
            if (index > clearTo) {
                told.add("not my turn at " + route.get(index));
            }
            return index <= clearTo;
        }

        @Override
        public boolean mayEnter(Edge edge, int fromId, Pose pose) {
            told.add("may I pass " + edge.door());
            return doorOpen;
        }

        @Override
        public void setOff(List<Integer> standsOn) {
            told.add("sets off on " + standsOn);
        }

        @Override
        public void reached(Edge edge, List<Integer> rest) {
            told.add("reached " + rest.get(0) + (edge == null ? " (back on the route)" : " by " + edge.a() + "-" + edge.b())
                    + ", ahead " + rest);
        }
    };

    final RouteFollower.Events events = new RouteFollower.Events() {
        @Override
        public void arrived(long nowMs) {
            told.add("arrived at " + nowMs);
        }

        @Override
        public void broken(int fromId, String why) {
            told.add("broken at " + fromId + ": " + why);
        }

        @Override
        public void blocked(int fromId, int toId) {
            told.add("blocked " + fromId + "-" + toId);
        }

        @Override
        public void say(String s) {
            told.add("says " + s);
        }
    };

    private void step(long ms, Pose pose, double frontM) {
        follower.step(reading(ms, pose, frontM, 3.0), follower.locate(reading(ms, pose, frontM, 3.0)), ms, way, events);
    }

    @Test
    void drivesStraightOnTowardTheNextNodeOnceTheTrafficAgentGrantsTheRoute() {
        follower.follow(List.of(3, 1));
        step(0, AT_3_FACING_WEST, 3.0);
        assertEquals(List.of("may I drive [3, 1] from [3]", "sets off on [3, 1]"), told);
        double[] p = chair.lastPowers();
        assertTrue(p[0] > 0 && Math.abs(p[0] - p[1]) < 1e-9, "straight ahead at cruise power: " + chair.last());
        assertEquals(List.of(3, 1), follower.standsOn(), "on the edge, its body takes both ends");
    }

    @Test
    void standsUntilTheRouteIsGranted() {
        trafficGrants = false;
        follower.follow(List.of(3, 1));
        step(0, AT_3_FACING_WEST, 3.0);
        step(100, AT_3_FACING_WEST, 3.0);
        assertEquals(List.of("stop", "stop"), chair.commands);
        assertTrue(told.stream().noneMatch(s -> s.startsWith("sets off")), "it never set off: " + told);
    }

    /** Granted only up to the node it stands on (another chair is ahead): it stands there, not on the edge, until told to go on. */
    @Test
    void standsAtItsNodeUntilTheNextIsItsTurn() {
        clearTo = 0;
        follower.follow(List.of(3, 1));
        step(0, AT_3_FACING_WEST, 3.0);
        step(100, AT_3_FACING_WEST, 3.0);
        assertEquals(List.of("stop", "stop"), chair.commands);
        assertTrue(told.stream().noneMatch(s -> s.startsWith("sets off")), "it never set off: " + told);
        assertEquals(List.of(3), follower.standsOn(), "its body takes only node 3");
        clearTo = 1;
        step(200, AT_3_FACING_WEST, 3.0);
        assertTrue(told.contains("sets off on [3, 1]"), told.toString());
        assertTrue(chair.lastPowers()[0] > 0, chair.last());
    }

    @Test
    void slowsForWhatIsNearAheadAndStopsForWhatIsClose() {
        follower.follow(List.of(3, 1));
        step(0, AT_3_FACING_WEST, 3.0);
        double cruise = chair.lastPowers()[0];
        step(100, AT_3_FACING_WEST, 1.0);
        assertEquals(cruise * io.concord.agents.chair.ObstacleFilter.SLOW_SCALE, chair.lastPowers()[0], 1e-9, "slow zone");
        step(200, AT_3_FACING_WEST, 0.4);
        assertEquals("stop", chair.last(), "stop zone");
        assertTrue(told.contains("says stops: something 0.40 m ahead"), told.toString());
        step(300, AT_3_FACING_WEST, 2.0);
        assertEquals(cruise, chair.lastPowers()[0], 1e-9, "clear again: cruise");
    }

    @Test
    void anEdgeBlockedForFifteenSecondsIsReportedOnce() {
        follower.follow(List.of(3, 1));
        for (long ms = 0; ms <= RouteFollower.BLOCKED_AFTER_MS; ms += 1_000) {
            step(ms, AT_3_FACING_WEST, 0.3);
        }
        assertTrue(told.stream().noneMatch(s -> s.startsWith("blocked")), "not yet at exactly 15 s: " + told);
        step(RouteFollower.BLOCKED_AFTER_MS + 1, AT_3_FACING_WEST, 0.3);
        assertEquals(1, told.stream().filter(s -> s.equals("blocked 3-1")).count(), told.toString());
        step(RouteFollower.BLOCKED_AFTER_MS + 1_000, AT_3_FACING_WEST, 0.3);
        assertEquals(1, told.stream().filter(s -> s.equals("blocked 3-1")).count(), "counted again from the report: " + told);
    }

    /**
     * Stopped 15 s with its heading 15 degrees off its way (depot seed 190: its front infrared on a
     * corridor's wall, and the small steering of a drive forward never came): it turns on the spot
     * to face its way first, and calls the edge blocked only if it is still stopped 15 s after that.
     */
    @Test
    void stoppedLongWithItsHeadingOffItTurnsToFaceItsWayBeforeItCallsTheEdgeBlocked() {
        Pose off = new Pose(8, 2, Math.PI - Math.toRadians(15));
        follower.follow(List.of(3, 1));
        for (long ms = 0; ms <= RouteFollower.BLOCKED_AFTER_MS; ms += 1_000) {
            step(ms, off, 0.3);
        }
        step(RouteFollower.BLOCKED_AFTER_MS + 1, off, 0.3);
        assertTrue(told.contains("says turns on the spot to face node 1 (15 degrees off its way, stopped 15 s)"), told.toString());
        assertTrue(told.stream().noneMatch(s -> s.startsWith("blocked")), "not blocked yet: " + told);
        step(RouteFollower.BLOCKED_AFTER_MS + 100, off, 0.3);
        double[] p = chair.lastPowers();
        assertTrue(p[0] != 0 && Math.abs(p[0] + p[1]) < 1e-9, "a turn on the spot, which the filter lets through: " + chair.last());
        // Facing its way, still stopped: blocked 15 s later.
        long t = RouteFollower.BLOCKED_AFTER_MS + 200;
        for (long ms = t; ms <= t + RouteFollower.BLOCKED_AFTER_MS + 1_000; ms += 1_000) {
            step(ms, AT_3_FACING_WEST, 0.3);
        }
        assertEquals(1, told.stream().filter(s -> s.equals("blocked 3-1")).count(), told.toString());
    }

    @Test
    void aStopThatClearsStartsTheBlockedCountAgain() {
        follower.follow(List.of(3, 1));
        step(0, AT_3_FACING_WEST, 0.3);
        step(10_000, AT_3_FACING_WEST, 3.0);
        step(11_000, AT_3_FACING_WEST, 0.3);
        step(20_000, AT_3_FACING_WEST, 0.3);
        assertTrue(told.stream().noneMatch(s -> s.startsWith("blocked")), told.toString());
    }

    @Test
    void reachingEachNodeIsToldWithTheRestOfTheRouteAndTheLastIsArrival() {
        follower.follow(List.of(3, 1, 2));
        step(0, AT_3_FACING_WEST, 3.0);
        told.clear();
        step(5_000, new Pose(5, 2, Math.PI), 3.0);
        assertEquals(List.of("may I drive [3, 1, 2] from [3, 1]", "reached 1 by 1-3, ahead [1, 2]"), told);
        assertEquals(1, follower.here());
        told.clear();
        step(9_000, new Pose(5, 6.5, Math.PI / 2), 3.0);
        assertEquals(List.of("may I drive [3, 1, 2] from [1]", "reached 2 by 1-2, ahead [2]", "arrived at 9000"), told);
    }

    /**
     * The part of the route not yet driven is kept, and driven on from where the chair is: not taken
     * for arrived (a chair that kept its route with its patient on board would have let the patient
     * off at the wrong node).
     */
    @Test
    void aTrimmedRouteIsDrivenOnFromWhereTheChairIsNotTakenForArrived() {
        follower.follow(List.of(3, 1, 2));
        step(0, AT_3_FACING_WEST, 3.0);
        step(5_000, new Pose(5, 2, Math.PI), 3.0);
        assertEquals(1, follower.here());
        follower.trim();
        assertEquals(List.of(1, 2), follower.route());
        assertTrue(follower.leadsTo(2), "still to drive to node 2");
        told.clear();
        step(5_100, AT_1_FACING_NORTH, 3.0);
        assertTrue(told.stream().noneMatch(s -> s.startsWith("arrived")), "not arrived at node 1: " + told);
        assertTrue(chair.lastPowers()[0] > 0, "drives on to node 2: " + chair.last());
    }

    @Test
    void waitsAtADoorItMayNotPass() {
        doorOpen = false;
        follower.follow(List.of(1, 2));
        step(0, AT_1_FACING_NORTH, 3.0);
        assertEquals("stop", chair.last());
        assertTrue(told.contains("may I pass D1"), told.toString());
        doorOpen = true;
        step(100, AT_1_FACING_NORTH, 3.0);
        assertTrue(chair.lastPowers()[0] > 0, "the door let it: on it goes, " + chair.last());
    }

    @Test
    void aNewPlanFromBehindDrivesBackToItsFirstNodeAtHalfPowerFirst() {
        follower.follow(List.of(3, 1));
        step(0, AT_3_FACING_WEST, 3.0);
        double cruise = chair.lastPowers()[0];
        follower.followBack(List.of(3, 1));
        told.clear();
        step(100, new Pose(3, 2, 0), 3.0);
        assertEquals(cruise * 0.5, Math.max(chair.lastPowers()[0], chair.lastPowers()[1]), 1e-9, "back to node 3: " + chair.last());
        step(200, new Pose(8, 2, Math.PI), 3.0);
        assertTrue(told.contains("reached 3 (back on the route), ahead [3, 1]"), told.toString());
    }

    @Test
    void aRouteOverAnEdgeTheMapHasNotIsBroken() {
        follower.follow(List.of(3, 2));
        step(0, AT_3_FACING_WEST, 3.0);
        assertTrue(told.contains("broken at 3: the plan has no edge 3-2"), told.toString());
    }

    @Test
    void withNoRouteItKeepsTheChairStopped() {
        step(0, AT_3_FACING_WEST, 3.0);
        follower.follow(List.of(3, 1));
        follower.clear();
        step(100, AT_3_FACING_WEST, 3.0);
        assertEquals(List.of("stop", "stop"), chair.commands);
        assertEquals(3, follower.nearestNode());
    }
}
