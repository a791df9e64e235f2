package io.concord.agents.traffic;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.MapException;
import io.concord.agents.map.Point;
import io.concord.agents.traffic.Reservations.Clear;
import io.concord.agents.traffic.Reservations.Granted;
import io.concord.agents.traffic.Reservations.Outcome;
import io.concord.agents.traffic.Reservations.Waiting;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Two lanes: a corridor 1-2-3-4-5 (x = 3 to 23 m, y = 4 m) whose edges carry two lanes, with side
 * rooms north (6 off 2, 8 off 4) and south (7 off 2, 9 off 4). Lane 0 runs east (its right is
 * south), lane 1 west (its right is north). The same map with one lane shows what the lanes add.
 */
class LanesTest {
    static String corridor(int lanes) {
        String l = lanes == 2 ? ", \"lanes\": 2" : "";
        return """
                {
                  "format": "concord-hospital-map/1",
                  "name": "two lanes",
                  "walls": [
                    {"id": "outer", "path": [[0, 0], [30, 0], [30, 12], [0, 12], [0, 0]]}
                  ],
                  "nodes": [
                    {"id": 1, "at": [3, 4]}, {"id": 2, "at": [8, 4]}, {"id": 3, "at": [13, 4]},
                    {"id": 4, "at": [18, 4]}, {"id": 5, "at": [23, 4]},
                    {"id": 6, "at": [8, 9]}, {"id": 7, "at": [8, 1]}, {"id": 8, "at": [18, 9]}, {"id": 9, "at": [18, 1]}
                  ],
                  "edges": [
                    {"from": 1, "to": 2%1$s}, {"from": 2, "to": 3%1$s}, {"from": 3, "to": 4%1$s}, {"from": 4, "to": 5%1$s},
                    {"from": 2, "to": 6}, {"from": 2, "to": 7}, {"from": 4, "to": 8}, {"from": 4, "to": 9}
                  ]
                }
                """.formatted(l);
    }

    static final HospitalMap LANES = HospitalMap.parse(corridor(2), "two lanes");
    static final HospitalMap ONE = HospitalMap.parse(corridor(1), "one lane");

    private static List<Outcome<String>> reserve(Reservations<String> r, String chair, List<Integer> at, List<Integer> path) {
        r.heard(chair, 0);
        return r.reserve(chair, "t" + chair, at, path, false, 0);
    }

    @Test
    void theMapSaysWhereChairsKeepTheirLanes() {
        assertTrue(LANES.warnings().isEmpty(), LANES.warnings().toString());
        assertEquals(List.of(1, 3), List.of(LANES.laneAxis(2)[0], LANES.laneAxis(2)[1]));
        assertNull(LANES.laneAxis(1), "an end of the corridor has one two-lane edge: no lanes");
        assertNull(LANES.laneAxis(6));
        assertEquals(0, LANES.lane(1, 2, 3), "east, straight on");
        assertEquals(1, LANES.lane(3, 2, 1), "west, straight on");
        assertEquals(0, LANES.lane(1, 2, 7), "east, turning right (south) into 7");
        assertEquals(-1, LANES.lane(1, 2, 6), "east, turning left across the other lane: the whole node");
        assertEquals(1, LANES.lane(6, 2, 1), "from 6 (north) turning west: onto lane 1 from its right");
        assertEquals(-1, LANES.lane(7, 2, 1), "from 7 (south) turning west: across lane 0");
        assertEquals(-1, LANES.lane(3, 2, 3), "turning back: the whole node");
        assertEquals(-1, LANES.lane(-1, 2, 3), "starting there: the whole node");
        assertEquals(new Point(8, 4 - HospitalMap.LANE_OFFSET_M), LANES.lanePoint(2, 0), "lane 0 (east) keeps right: south");
        assertEquals(new Point(8, 4 + HospitalMap.LANE_OFFSET_M), LANES.lanePoint(2, 1));
        assertEquals(LANES.lanePoint(3, 1), LANES.waypoint(4, 3, 2));
        assertEquals(LANES.node(3).at(), ONE.waypoint(4, 3, 2), "one lane: on the line");
    }

    /**
     * Two chairs meet head-on in the corridor, each entering it from a room on its right and
     * leaving it to a room on its right: each keeps its lane, nothing of the other's route is
     * theirs, and both drive at once. With one lane the second waits for the first to pass.
     */
    @Test
    void twoChairsMeetingHeadOnPassEachOtherInTheirLanes() {
        Reservations<String> r = new Reservations<>(LANES, TrafficRules.IN_ORDER);
        assertEquals(List.of(new Granted<>("a", "ta", List.of(7, 2, 3, 4, 9), 9)), reserve(r, "a", List.of(7), List.of(7, 2, 3, 4, 9)));
        assertEquals(List.of(new Granted<>("b", "tb", List.of(8, 4, 3, 2, 6), 6)), reserve(r, "b", List.of(8), List.of(8, 4, 3, 2, 6)),
                "granted all the way at once: a is in the other lane");
        assertEquals(Map.of(2, List.of(List.of("a"), List.of("b")), 3, List.of(List.of("a"), List.of("b")),
                4, List.of(List.of("a"), List.of("b"))), r.lanes(), "a in lane 0, b in lane 1, at every node");
        assertTrue(r.waits().isEmpty(), r.waits().toString());

        Reservations<String> one = new Reservations<>(ONE, TrafficRules.IN_ORDER);
        reserve(one, "a", List.of(7), List.of(7, 2, 3, 4, 9));
        assertEquals(List.of(new Granted<>("b", "tb", List.of(8, 4, 3, 2, 6), 8)), reserve(one, "b", List.of(8), List.of(8, 4, 3, 2, 6)),
                "one lane: b stands until a has passed node 4");
        assertEquals(List.of(), one.release("a", 7, 1), "a on 2: b still waits for 4");
        one.release("a", 2, 2);
        one.release("a", 3, 3);
        assertEquals(List.of(new Clear<>("b", "tb", 6)), one.release("a", 4, 4), "a in room 9: b may go");
    }

    /** A chair turning across the other lane takes the whole node: it waits for the chair passing there in that lane. */
    @Test
    void aChairTurningAcrossTheOtherLaneWaitsForTheChairInIt() {
        Reservations<String> r = new Reservations<>(LANES, TrafficRules.IN_ORDER);
        reserve(r, "b", List.of(8), List.of(8, 4, 3, 2, 6));
        List<Outcome<String>> out = reserve(r, "c", List.of(7), List.of(7, 2, 1));
        assertEquals(List.of(new Granted<>("c", "tc", List.of(7, 2, 1), 7)), out, "from the south across lane 0 and into lane 1, behind b");
        assertEquals(List.of("b", "c"), r.lanes().get(2).get(1), "lane 1 at node 2: b, then c");
        r.release("b", 8, 1);
        r.release("b", 4, 2);
        r.release("b", 3, 3);
        assertEquals(List.of(new Clear<>("c", "tc", 1)), r.release("b", 2, 4), "b left node 2: c may go");
    }

    /** Chairs in the same lane follow each other as on one lane; a chair standing in the corridor takes both lanes. */
    @Test
    void aFollowerKeepsBehindInItsLaneAndAChairStandingThereTakesBoth() {
        Reservations<String> r = new Reservations<>(LANES, TrafficRules.IN_ORDER);
        reserve(r, "a", List.of(2), List.of(2, 3, 4, 5));
        assertEquals(List.of(new Granted<>("f", "tf", List.of(1, 2, 3, 4, 9), 1)), reserve(r, "f", List.of(1), List.of(1, 2, 3, 4, 9)),
                "f follows a: not onto node 2 until a has left it");
        assertEquals(List.of("a", "f"), r.lanes().get(3).get(0), "lane 0 at node 3: a, then f");

        Reservations<String> s = new Reservations<>(LANES, TrafficRules.IN_ORDER);
        s.heard("idle", 0);
        s.idle("idle", List.of(3), 0);
        assertEquals(List.of(List.of("idle"), List.of("idle")), s.lanes().get(3), "standing on 3: both lanes");
        List<Outcome<String>> out = reserve(s, "g", List.of(7), List.of(7, 2, 3, 4, 9));
        assertTrue(out.get(0) instanceof Waiting<String> w && w.heldBy().equals(List.of("idle")), out.toString());
    }

    /**
     * A chair stopped in its lane that asks for a new route from there takes the whole node, and
     * sets off only when the chairs ahead of it in the other lane have passed: its new way may
     * cross that lane (the rule does not look: here it goes on east in its own lane, and waits).
     */
    @Test
    void aChairSettingOffFromItsLaneWaitsForTheOtherLaneToPass() {
        Reservations<String> r = new Reservations<>(LANES, TrafficRules.IN_ORDER);
        reserve(r, "a", List.of(7), List.of(7, 2, 3, 4, 9));
        reserve(r, "b", List.of(5), List.of(5, 4, 3, 2, 1));
        r.release("a", 7, 1);
        r.release("a", 2, 2); // a stands in lane 0 at node 3
        r.heard("a", 3);
        assertEquals(List.of(new Granted<>("a", "ta2", List.of(3, 4, 9), 3)), r.reserve("a", "ta2", List.of(3), List.of(3, 4, 9), false, 3),
                "granted, but it stands until b has passed node 3");
        assertEquals(List.of(List.of("a"), List.of("b", "a")), r.lanes().get(3), "node 3: a in lane 0; b, then a, in lane 1");
        r.release("b", 5, 4);
        assertEquals(List.of(), r.release("b", 4, 5), "b on node 3 (lane 1): a still waits");
        assertEquals(List.of(new Clear<>("a", "ta2", 9)), r.release("b", 3, 6), "b has passed node 3: a goes");
    }

    @Test
    void theReaderAndTheCheckerSayWhatIsWrongWithLanes() {
        MapException e = assertThrows(MapException.class, () -> HospitalMap.parse(corridor(2).replace("\"to\": 2, \"lanes\": 2", "\"to\": 2, \"lanes\": 3"), "x"));
        assertTrue(e.getMessage().contains("\"lanes\" must be 1 or 2"), e.getMessage());
        // A wall 1.3 m south of the corridor's line, face 1.225 m: the line is clear, lane 0 (0.8 m south of it) is not.
        String wall = "\"walls\": [\n {\"id\": \"south\", \"from\": [10.5, 2.7], \"to\": [15.5, 2.7]},";
        HospitalMap tight = HospitalMap.parse(corridor(2).replace("\"walls\": [", wall), "tight");
        assertTrue(tight.warnings().stream().anyMatch(w -> w.startsWith("lane 0 of node 3 at (13, 3.2) is 0.4") && w.contains("m from the face of wall 'south'") && w.endsWith("one lane (leave out \"lanes\")")),
                tight.warnings().toString());
        assertTrue(tight.warnings().stream().anyMatch(w -> w.startsWith("edge 2-3's lane from") && w.contains("passes 0.4") && w.contains("from the face of wall 'south'")),
                tight.warnings().toString());
        assertEquals(List.of(), HospitalMap.parse(corridor(1).replace("\"walls\": [", wall), "one").warnings(), "one lane: on the line, clear");
    }
}
