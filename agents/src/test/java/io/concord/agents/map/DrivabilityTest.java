package io.concord.agents.map;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The drivability rules warn of what a chair could not drive, naming the element, on maps the reader accepts. */
class DrivabilityTest {

    /**
     * A corridor along the south, three rooms north of it. Everything here is legal for the
     * reader, and each thing is wrong for a chair: a 9.8 m edge, a node inside a hinged leaf's
     * swing (0.8 m from its opening, and the edge to it through the swing), a node 0.53 m from a
     * wall, two nodes 1.08 m apart, a
     * sliding door with 0.5 m of wall to slide into, a route straight through a revolving door's
     * pivot from a node 2 m from it.
     */
    static final String BAD = """
            {
              "format": "concord-hospital-map/1",
              "name": "undrivable",
              "walls": [
                {"id": "outer", "path": [[0, 0], [20, 0], [20, 10], [0, 10], [0, 0]], "thickness": 0.25},
                {"id": "c1", "from": [0, 4], "to": [3, 4]},
                {"id": "c2", "from": [4.2, 4], "to": [7, 4]},
                {"id": "c3", "from": [8.2, 4], "to": [8.7, 4]},
                {"id": "c4", "from": [10, 4], "to": [13, 4]},
                {"id": "c5", "from": [16.2, 4], "to": [20, 4]},
                {"id": "p1", "from": [6, 4], "to": [6, 10]},
                {"id": "p2", "from": [8.7, 4], "to": [8.7, 10]}
              ],
              "doors": [
                {"id": "H1", "kind": "hinged", "from": [3, 4], "to": [4.2, 4], "hinge": "from", "swing": "right"},
                {"id": "S1", "kind": "sliding", "from": [7, 4], "to": [8.2, 4], "hinge": "to"},
                {"id": "R1", "kind": "rotating", "from": [13, 4], "to": [16.2, 4]}
              ],
              "nodes": [
                {"id": 1, "at": [2, 2]},
                {"id": 2, "at": [11.8, 2]},
                {"id": 3, "at": [3.6, 3.2]},
                {"id": 4, "at": [3.6, 7]},
                {"id": 5, "at": [7.6, 7]},
                {"id": 6, "at": [7.6, 1.2]},
                {"id": 7, "at": [12.8, 1.6]},
                {"id": 8, "at": [14.6, 2]},
                {"id": 9, "at": [14.6, 7]},
                {"id": 10, "at": [11, 3.4]}
              ],
              "edges": [
                {"from": 1, "to": 2},
                {"from": 1, "to": 3},
                {"from": 3, "to": 4, "door": "H1"},
                {"from": 1, "to": 6},
                {"from": 6, "to": 5, "door": "S1"},
                {"from": 2, "to": 7},
                {"from": 7, "to": 8},
                {"from": 8, "to": 9, "door": "R1"},
                {"from": 2, "to": 10}
              ]
            }
            """;

    @Test
    void aLongEdgeHasFloorMarkersAlongItNoChairDrivesOver3MOnOdometryAlone() {
        HospitalMap map = HospitalMap.parse(BAD, "undrivable");
        // Edge 1-2 runs 9.8 m from (2, 2) to (11.8, 2): four stretches of 2.45 m, three markers between its ends.
        List<Point> along = map.edgeMarkers();
        assertEquals(List.of(new Point(4.45, 2), new Point(6.9, 2), new Point(9.35, 2)),
                along.stream().map(p -> new Point(Math.round(p.x() * 100) / 100.0, Math.round(p.y() * 100) / 100.0)).toList());
        assertTrue(map.markers().containsAll(along) && map.markers().containsAll(map.nodeMarkers()));
        assertEquals(map.nodeMarkers().size() + 3, map.markers().size());
    }

    @Test
    void eachRuleFlagsWhatBreaksItNamingTheElement() {
        List<String> problems = HospitalMap.parse(BAD, "undrivable").warnings();
        List<String> expected = List.of(
                "node 3 at (3.6, 3.2) is in the swing of door 'H1'",
                "edge 1-3 passes 0 m from the swing of door 'H1'",
                "node 3 is 0.8 m from the opening of door 'H1' (edge 3-4)",
                "node 10 at (11, 3.4) is 0.53 m from the face of wall 'c4'",
                "nodes 2 and 7 are 1.08 m apart",
                "sliding door 'S1' runs past its jamb at (8.2, 4) into 0.5 m of wall",
                "edge 8-9 passes 0 m from the open leaf of revolving door 'R1'",
                "node 8 at (14.6, 2) is 2 m from the pivot of revolving door 'R1'");
        for (String e : expected) {
            assertTrue(problems.stream().anyMatch(p -> p.startsWith(e)), "expected \"" + e + "...\" among " + problems);
        }
        assertEquals(expected.size(), problems.size(), String.join("\n", problems));
    }

    @Test
    void aHingedLeafSweepingIntoTheCorridorFlagsTheCorridorEdgesAndNodesInItsWay() {
        // H1 turned to swing into the room instead: the corridor is clear of it, and node 3 is out of its swing.
        String into = BAD.replace("\"hinge\": \"from\", \"swing\": \"right\"", "\"hinge\": \"from\", \"swing\": \"left\"");
        List<String> problems = HospitalMap.parse(into, "swinging in").warnings();
        assertTrue(problems.stream().noneMatch(p -> p.contains("swing of door 'H1'")), String.join("\n", problems));
        // Node 4 in the room is 3.05 m from the hinge: clear. A node put 1.5 m from the opening is not.
        String near = into.replace("{\"id\": 4, \"at\": [3.6, 7]}", "{\"id\": 4, \"at\": [3.6, 5.5]}");
        problems = HospitalMap.parse(near, "node near the leaf").warnings();
        assertTrue(problems.stream().anyMatch(p -> p.startsWith("node 4 at (3.6, 5.5) is 0.42 m from the swing of door 'H1'")),
                String.join("\n", problems));
    }

    /**
     * The default hospital keeps every rule. Its node 10, the node in revolving door WB's lane on
     * Ward B's side, is 1 m from sliding door B5's opening: enough for a sliding door, whose leaf keeps
     * to the wall's line, and not for a hinged one.
     */
    @Test
    void theDefaultHospitalKeepsEveryRule() {
        assertEquals(List.of(), HospitalMap.defaultHospital().warnings());
        String hinged = DEFAULT.replace("{\"id\": \"B5\", \"kind\": \"sliding\", \"from\": [29.9, 9], \"to\": [31.1, 9], \"hinge\": \"to\"}",
                "{\"id\": \"B5\", \"kind\": \"hinged\", \"from\": [29.9, 9], \"to\": [31.1, 9], \"hinge\": \"to\", \"swing\": \"left\"}");
        assertTrue(HospitalMap.parse(hinged, "B5 hinged").warnings().contains(
                "node 10 is 1 m from the opening of door 'B5' (edge 10-26); a chair waiting there for the door needs 1.5 m"),
                HospitalMap.parse(hinged, "B5 hinged").warnings().toString());
    }

    private static final String DEFAULT = read();

    private static String read() {
        try (var in = HospitalMap.class.getResourceAsStream(HospitalMap.DEFAULT_RESOURCE)) {
            return new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
