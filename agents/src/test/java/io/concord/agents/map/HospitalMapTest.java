package io.concord.agents.map;

import org.junit.jupiter.api.Test;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The map format: the default hospital as the scenario needs it, and every refusal with its message. */
class HospitalMapTest {

    /** A small valid map: a room with a hinged door onto a corridor. Tests break one thing at a time. */
    static final String SMALL = """
            {
              "format": "concord-hospital-map/1",
              "name": "small",
              "walls": [
                {"id": "outer", "path": [[0, 0], [10, 0], [10, 8], [0, 8], [0, 0]]},
                {"id": "w1", "from": [0, 4], "to": [4.4, 4]},
                {"id": "w2", "from": [5.6, 4], "to": [10, 4]}
              ],
              "areas": [
                {"id": "ward", "kind": "ward", "name": "Ward", "polygon": [[0, 0], [10, 0], [10, 8], [0, 8]]},
                {"id": "room", "kind": "room", "name": "Room 1", "ward": "ward", "polygon": [[0, 4], [10, 4], [10, 8], [0, 8]]}
              ],
              "doors": [
                {"id": "D1", "kind": "hinged", "from": [4.4, 4], "to": [5.6, 4], "hinge": "from", "swing": "left"}
              ],
              "nodes": [
                {"id": 1, "at": [5, 2], "name": "corridor"},
                {"id": 2, "at": [5, 6.5], "name": "room"},
                {"id": 3, "at": [8, 2]}
              ],
              "edges": [
                {"from": 1, "to": 2, "door": "D1"},
                {"from": 1, "to": 3}
              ]
            }
            """;

    private static MapException refused(String json) {
        return assertThrows(MapException.class, () -> HospitalMap.parse(json, "test"));
    }

    private static void assertProblem(MapException e, String... fragments) {
        for (String p : e.problems()) {
            boolean all = true;
            for (String f : fragments) {
                all &= p.contains(f);
            }
            if (all) {
                return;
            }
        }
        throw new AssertionError("no problem mentions " + List.of(fragments) + " in:\n" + e.getMessage());
    }

    @Test
    void theSmallMapLoads() {
        HospitalMap m = HospitalMap.parse(SMALL, "test");
        assertEquals(3, m.nodes().size());
        assertEquals("D1", m.edge(1, 2).orElseThrow().door());
        assertEquals("room", m.node(2).area());
        assertEquals(6, m.walls().size(), "a path of five points is four walls, plus two");
    }

    /** A node is named by its number or its room's name (A2, Room A2, a2); anything else is refused naming the rooms. */
    @Test
    void aNodeIsNamedByItsNumberOrItsRoom() {
        HospitalMap m = HospitalMap.defaultHospital();
        assertEquals(3, m.nodeNamed("3"));
        assertEquals(3, m.nodeNamed("A2"));
        assertEquals(3, m.nodeNamed(" room a2 "));
        assertEquals(9, m.nodeNamed("Room B7"));
        assertEquals(9, m.nodeNamed("b7"));
        assertEquals(14, m.nodeNamed("A1"));
        assertEquals("no node 99 in " + m.name(), assertThrows(IllegalArgumentException.class, () -> m.nodeNamed("99")).getMessage());
        String e = assertThrows(IllegalArgumentException.class, () -> m.nodeNamed("Lobby")).getMessage();
        assertTrue(e.startsWith("no node or room 'Lobby' in " + m.name() + "; rooms: A1, A2, A3, A4, A5, A6, A7, A8, B1, ") && e.endsWith("B8; or a node's number"), e);
        assertThrows(IllegalArgumentException.class, () -> m.nodeNamed(""));
    }

    @Test
    void theDefaultHospitalHasTwoWardsJoinedByCorridorsAndEnoughNodes() {
        HospitalMap m = HospitalMap.defaultHospital();
        long wards = m.areas().stream().filter(a -> a.kind() == Area.Kind.WARD).count();
        assertTrue(wards >= 2, "wards: " + wards);
        assertTrue(m.areas().stream().anyMatch(a -> a.kind() == Area.Kind.CORRIDOR));
        assertTrue(m.nodes().size() >= 25, "nodes: " + m.nodes().size());
        for (Door.Kind k : Door.Kind.values()) {
            assertTrue(m.doors().stream().anyMatch(d -> d.kind() == k), "no " + k + " door");
        }
    }

    @Test
    void theScenarioNodesSitAsInTheDissertation() {
        HospitalMap m = HospitalMap.defaultHospital();
        Area ward3 = m.wardAt(m.node(3).at()).orElseThrow();
        Area ward9 = m.wardAt(m.node(9).at()).orElseThrow();
        assertFalse(ward3.id().equals(ward9.id()), "3 and 9 must be in different wards");
        assertEquals(Area.Kind.ROOM, m.areaAt(m.node(3).at()).orElseThrow().kind());
        assertEquals(Area.Kind.ROOM, m.areaAt(m.node(9).at()).orElseThrow().kind());
        assertNotNull(m.node(19));
        List<Edge> route = route(m, 19, 3);
        route.addAll(route(m, 3, 9));
        Set<String> doors = new HashSet<>();
        Set<Door.Kind> kinds = new HashSet<>();
        for (Edge e : route) {
            if (e.door() != null) {
                doors.add(e.door());
                kinds.add(m.door(e.door()).kind());
            }
        }
        assertTrue(doors.size() >= 2, "doors on 19 -> 3 -> 9: " + doors);
        assertEquals(Set.of(Door.Kind.values()), kinds, "every kind of door lies on the route: " + doors);
    }

    /** Fewest edges between two nodes (breadth first); enough to see which doors a route crosses. */
    private static List<Edge> route(HospitalMap m, int a, int b) {
        Map<Integer, Edge> via = new HashMap<>();
        ArrayDeque<Integer> q = new ArrayDeque<>(List.of(a));
        via.put(a, null);
        while (!q.isEmpty()) {
            int n = q.poll();
            for (Edge e : m.edgesAt(n)) {
                int o = e.other(n);
                if (!via.containsKey(o)) {
                    via.put(o, e);
                    q.add(o);
                }
            }
        }
        assertTrue(via.containsKey(b), "no route from " + a + " to " + b);
        List<Edge> out = new java.util.ArrayList<>();
        for (int n = b; n != a; ) {
            Edge e = via.get(n);
            out.add(0, e);
            n = e.other(n);
        }
        return out;
    }

    @Test
    void malformedJsonIsRefusedWithItsPlace() {
        MapException e = refused("{\"format\": \"concord-hospital-map/1\", \"name\": \"x\",\n \"walls\": [ }");
        assertProblem(e, "not valid JSON", "line 2");
    }

    @Test
    void anUnknownNodeInAnEdgeIsRefused() {
        MapException e = refused(SMALL.replace("{\"from\": 1, \"to\": 3}", "{\"from\": 1, \"to\": 42}"));
        assertProblem(e, "edge 1-42", "no node 42");
    }

    /** A newcomer's map: an edge drawn straight over a node it does not stop at; a chair parked there froze the fleet. */
    @Test
    void anEdgeOverANodeItDoesNotStopAtIsRefused() {
        MapException e = refused(SMALL.replace("{\"id\": 3, \"at\": [8, 2]}", "{\"id\": 3, \"at\": [8, 2]}, {\"id\": 4, \"at\": [2, 2.3]}")
                .replace("{\"from\": 1, \"to\": 3}", "{\"from\": 1, \"to\": 3}, {\"from\": 4, \"to\": 3}"));
        assertProblem(e, "edge 4-3", "from node 1", "would block it", "4-1 and 1-3");
        // Joined through the node instead, it loads.
        HospitalMap.parse(SMALL.replace("{\"id\": 3, \"at\": [8, 2]}", "{\"id\": 3, \"at\": [8, 2]}, {\"id\": 4, \"at\": [2, 2.3]}")
                .replace("{\"from\": 1, \"to\": 3}", "{\"from\": 1, \"to\": 3}, {\"from\": 4, \"to\": 1}"), "test");
    }

    @Test
    void aDoorNotOnAWallGapIsRefused() {
        MapException e = refused(SMALL.replace("\"from\": [4.4, 4], \"to\": [5.6, 4], \"hinge\"",
                "\"from\": [4.4, 3], \"to\": [5.6, 3], \"hinge\""));
        assertProblem(e, "door 'D1'", "not on a wall gap");
    }

    @Test
    void aWallAcrossADoorwayIsRefused() {
        MapException e = refused(SMALL.replace("{\"id\": \"w2\", \"from\": [5.6, 4], \"to\": [10, 4]}",
                "{\"id\": \"w2\", \"from\": [5.6, 4], \"to\": [10, 4]}, {\"id\": \"post\", \"from\": [5, 3], \"to\": [5, 5]}"));
        assertProblem(e, "door 'D1'", "wall 'post'", "blocks its opening");
    }

    @Test
    void overlappingNodesAreRefused() {
        MapException e = refused(SMALL.replace("{\"id\": 3, \"at\": [8, 2]}", "{\"id\": 3, \"at\": [5.1, 2]}"));
        assertProblem(e, "nodes 1 and 3 overlap");
    }

    @Test
    void aWallOfZeroLengthIsRefused() {
        MapException e = refused(SMALL.replace("{\"id\": \"w2\", \"from\": [5.6, 4], \"to\": [10, 4]}",
                "{\"id\": \"w2\", \"from\": [5.6, 4], \"to\": [10, 4]}, {\"id\": \"dot\", \"from\": [7, 6], \"to\": [7, 6]}"));
        assertProblem(e, "wall 'dot'", "zero length");
    }

    @Test
    void aNodeInsideAWallIsRefused() {
        MapException e = refused(SMALL.replace("{\"id\": 3, \"at\": [8, 2]}", "{\"id\": 3, \"at\": [8, 4.02]}"));
        assertProblem(e, "node 3", "inside wall 'w2'");
    }

    @Test
    void aNodeTooCloseToAWallIsRefused() {
        MapException e = refused(SMALL.replace("{\"id\": 3, \"at\": [8, 2]}", "{\"id\": 3, \"at\": [8, 3.7]}"));
        assertProblem(e, "node 3", "from the face of wall 'w2'", "clearance");
    }

    @Test
    void anEdgeThroughAWallIsRefused() {
        MapException e = refused(SMALL.replace("{\"from\": 1, \"to\": 3}", "{\"from\": 1, \"to\": 3}, {\"from\": 2, \"to\": 3}"));
        assertProblem(e, "edge 2-3", "runs through wall 'w2'");
    }

    @Test
    void anEdgeThroughADoorMustNameIt() {
        MapException e = refused(SMALL.replace("{\"from\": 1, \"to\": 2, \"door\": \"D1\"}", "{\"from\": 1, \"to\": 2}"));
        assertProblem(e, "edge 1-2", "passes through door 'D1' without naming it");
    }

    @Test
    void anEdgeNamingADoorItMissesIsRefused() {
        MapException e = refused(SMALL.replace("{\"from\": 1, \"to\": 3}", "{\"from\": 1, \"to\": 3, \"door\": \"D1\"}"));
        assertProblem(e, "edge 1-3", "names door 'D1' but does not pass through");
    }

    @Test
    void anUnknownDoorKindAndAMissingFieldAreRefused() {
        MapException e = refused(SMALL.replace("\"kind\": \"hinged\"", "\"kind\": \"trapdoor\"")
                .replace("{\"id\": 3, \"at\": [8, 2]}", "{\"id\": 3}"));
        assertProblem(e, "door 'D1'", "'trapdoor'", "hinged, sliding, rotating");
        assertProblem(e, "node 3", "at", "[x, y]");
    }

    @Test
    void aTypoInAFieldNameIsRefused() {
        MapException e = refused(SMALL.replace("\"swing\": \"left\"", "\"swnig\": \"left\""));
        assertProblem(e, "door 'D1'", "unknown field \"swnig\"");
        assertProblem(e, "door 'D1'", "\"swing\" is missing");
    }

    @Test
    void duplicateIdsAreRefused() {
        MapException e = refused(SMALL.replace("{\"id\": 3, \"at\": [8, 2]}", "{\"id\": 2, \"at\": [8, 2]}"));
        assertProblem(e, "node 2", "used by another node");
    }

    @Test
    void aMissingFileSaysWhatToGive() {
        MapException e = assertThrows(MapException.class, () -> HospitalMap.load(Path.of("no-such-map.json")));
        assertProblem(e, "no such file", "docs/hospital-map.md");
    }

    @Test
    void everyProblemIsListedAtOnce() {
        MapException e = refused(SMALL.replace("{\"from\": 1, \"to\": 3}", "{\"from\": 1, \"to\": 42}")
                .replace("{\"id\": 3, \"at\": [8, 2]}", "{\"id\": 3, \"at\": [5.1, 2]}"));
        assertTrue(e.problems().size() >= 2, e.getMessage());
    }

    /** The example in docs/hospital-map.md is a map this reader loads. */
    @Test
    void theDocumentedExampleLoads() throws Exception {
        Path doc = Path.of("..", "docs", "hospital-map.md");
        String text = Files.readString(doc);
        Matcher m = Pattern.compile("```json\\n(.*?)```", Pattern.DOTALL).matcher(text);
        assertTrue(m.find(), "docs/hospital-map.md has a ```json example");
        HospitalMap map = HospitalMap.parse(m.group(1), "docs/hospital-map.md");
        assertFalse(map.nodes().isEmpty());
    }

    /** A node no edge leads to is refused: the planner could never send a chair there. */
    @Test
    void aNodeOffTheGraphIsRefused() {
        MapException e = refused(SMALL.replace("{\"id\": 3, \"at\": [8, 2]}", "{\"id\": 3, \"at\": [8, 2]},\n    {\"id\": 4, \"at\": [8, 6.5]}"));
        assertProblem(e, "node 4 is not connected to node 1", "add an edge");
        MapException two = refused(SMALL.replace("{\"from\": 1, \"to\": 3}", "{\"from\": 2, \"to\": 2}"));
        assertProblem(two, "node 3 is not connected");
    }

    /** Parking places are read in order; an unknown node, one named twice, or one in a patient's room is refused. */
    @Test
    void parkingPlacesAreKnownNodesOutsideRooms() {
        String withParking = SMALL.replace("""
                  ]
                }
                """, """
                  ],
                  "parking": [3, 1]
                }
                """);
        assertEquals(List.of(3, 1), HospitalMap.parse(withParking, "test").parking());
        assertEquals(List.of(), HospitalMap.parse(SMALL, "test").parking());
        assertProblem(refused(withParking.replace("[3, 1]", "[3, 7]")), "parking: no node 7");
        assertProblem(refused(withParking.replace("[3, 1]", "[3, 1, 3]")), "parking: node 3 is named twice");
        assertProblem(refused(withParking.replace("[3, 1]", "[3, 2]")), "parking: node 2 is in room 'room'", "never in a patient's room");
        assertProblem(refused(withParking.replace("[3, 1]", "[3, \"x\"]")), "parking #2: must be a node id");
    }
}
