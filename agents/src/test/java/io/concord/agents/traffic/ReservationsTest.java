package io.concord.agents.traffic;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.traffic.Reservations.Failed;
import io.concord.agents.traffic.Reservations.Granted;
import io.concord.agents.traffic.Reservations.MakeWay;
import io.concord.agents.traffic.Reservations.Outcome;
import io.concord.agents.traffic.Reservations.Waiting;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The traffic rules alone, with no agent and no clock: a corridor of five nodes (1-2-3-4-5) with a
 * room off its middle (6, a dead end), and chairs a, b, c. Time is whatever the test says.
 */
class ReservationsTest {
    static final String CORRIDOR = """
            {
              "format": "concord-hospital-map/1",
              "name": "corridor",
              "walls": [
                {"id": "outer", "path": [[0, 0], [30, 0], [30, 12], [0, 12], [0, 0]]}
              ],
              "areas": [
                {"id": "ward", "kind": "ward", "name": "Ward", "polygon": [[0, 0], [30, 0], [30, 12], [0, 12]]}
              ],
              "nodes": [
                {"id": 1, "at": [3, 4]},
                {"id": 2, "at": [8, 4]},
                {"id": 3, "at": [13, 4]},
                {"id": 4, "at": [18, 4]},
                {"id": 5, "at": [23, 4]},
                {"id": 6, "at": [13, 9], "name": "room"}
              ],
              "edges": [
                {"from": 1, "to": 2}, {"from": 2, "to": 3}, {"from": 3, "to": 4}, {"from": 4, "to": 5}, {"from": 3, "to": 6}
              ]
            }
            """;
    static final HospitalMap MAP = HospitalMap.parse(CORRIDOR, "test");

    private final Reservations<String> r = new Reservations<>(MAP, true);

    private static <T extends Outcome<String>> List<T> only(List<Outcome<String>> out, Class<T> kind) {
        return out.stream().filter(kind::isInstance).map(kind::cast).toList();
    }

    private List<Outcome<String>> reserve(String chair, String ticket, List<Integer> at, List<Integer> path, long now) {
        r.heard(chair, now);
        return r.reserve(chair, ticket, at, path, false, now);
    }

    @Test
    void aFreeRouteIsGrantedAtOnceAndHeldUntilGivenBack() {
        List<Outcome<String>> out = reserve("a", "t1", List.of(1), List.of(1, 2, 3), 0);
        assertEquals(List.of(new Granted<>("a", "t1", List.of(1, 2, 3))), out);
        assertEquals(Map.of(1, Set.of("a"), 2, Set.of("a"), 3, Set.of("a")), r.holders());
        r.release("a", 1, 10);
        assertEquals(Set.of(2, 3), r.holders().keySet());
        assertEquals(1, r.grants());
    }

    @Test
    void aRouteThroughAnotherChairsNodesWaitsAndIsGrantedWhenTheyAreGivenBack() {
        reserve("a", "ta", List.of(3), List.of(3, 4), 0);
        List<Outcome<String>> out = reserve("b", "tb", List.of(1), List.of(1, 2, 3), 0);
        assertEquals(List.of(new Waiting<>("b", "tb", List.of("a"))), out, "b waits, told who is in the way");
        assertEquals(List.of("b -> [1, 2, 3] (in the way: [a])"), r.waits());
        assertEquals(List.of(new Granted<>("b", "tb", List.of(1, 2, 3))), r.release("a", 3, 100), "granted once a has left 3");
    }

    @Test
    void theWaitEndsWhenTheLastNodeInTheWayIsGivenBack() {
        reserve("a", "ta", List.of(2), List.of(2, 3, 4), 0);
        reserve("b", "tb", List.of(1), List.of(1, 2), 0);
        assertEquals(List.of(), only(r.release("a", 3, 50), Granted.class), "2 is still a's");
        List<Granted> granted = only(r.release("a", 2, 60), Granted.class);
        assertEquals(List.of(new Granted<>("b", "tb", List.of(1, 2))), granted);
    }

    @Test
    void anIdleChairInTheWayIsSentToTheNearestDeadEndNobodyNeeds() {
        r.heard("a", 0);
        r.idle("a", List.of(3), 0);
        List<Outcome<String>> out = reserve("b", "tb", List.of(1), List.of(1, 2, 3, 4), 0);
        List<MakeWay> moved = only(out, MakeWay.class);
        assertEquals(List.of(new MakeWay<>("a", 3, 6, List.of(6))), moved, "the room off the corridor: a dead end");
        assertEquals(1, r.moves());
        r.heard("a", 10);
        r.reserve("a", "ta", List.of(3), List.of(3, 6), true, 10);
        List<Granted> granted = only(r.release("a", 3, 20), Granted.class);
        assertEquals(List.of(new Granted<>("b", "tb", List.of(1, 2, 3, 4))), granted, "b goes once a has left 3");
    }

    /** Out of the way is never a patient's room: with the room off the corridor a room, the chair goes to the corridor's end. */
    @Test
    void anIdleChairNeverStepsAsideIntoAPatientsRoom() {
        Reservations<String> rooms = new Reservations<>(HospitalMap.parse(CORRIDOR.replace("""
                    {"id": "ward", "kind": "ward", "name": "Ward", "polygon": [[0, 0], [30, 0], [30, 12], [0, 12]]}
                """, """
                    {"id": "ward", "kind": "ward", "name": "Ward", "polygon": [[0, 0], [30, 0], [30, 12], [0, 12]]},
                    {"id": "r6", "kind": "room", "ward": "ward", "polygon": [[10, 7], [16, 7], [16, 12], [10, 12]]}
                """), "test"), true);
        rooms.heard("a", 0);
        rooms.idle("a", List.of(3), 0);
        rooms.heard("b", 0);
        List<MakeWay> moved = only(rooms.reserve("b", "tb", List.of(1), List.of(1, 2, 3), false, 0), MakeWay.class);
        assertEquals(List.of(new MakeWay<>("a", 3, 5, List.of(4, 5))), moved, "the corridor's end, not room 6 one hop away");
    }

    @Test
    void aDeadlockIsFoundAndBrokenByMovingOneChairOfIt() {
        reserve("a", "ta", List.of(2), List.of(2), 0); // a stands on 2
        reserve("b", "tb", List.of(4), List.of(4), 0); // b stands on 4
        reserve("a", "ta2", List.of(2), List.of(2, 3, 4), 1); // a waits for b
        List<Outcome<String>> out = reserve("b", "tb2", List.of(4), List.of(4, 3, 2), 2); // and b for a
        assertEquals(1, r.deadlocks());
        List<MakeWay> moved = only(out, MakeWay.class);
        assertEquals(1, moved.size(), out.toString());
        String victim = moved.get(0).chair();
        List<Failed> failed = only(out, Failed.class);
        assertEquals(List.of(victim), failed.stream().map(Failed::chair).toList(), "its own wait ends: make-way");
        assertEquals("make-way", failed.get(0).reason());
    }

    @Test
    void aSilentChairKeepsOnlyWhereItStandsAndWhoWaitsForThatNodeIsTold() {
        reserve("a", "ta", List.of(3), List.of(3, 4, 5), 0);
        r.standing("a", List.of(3));
        reserve("b", "tb", List.of(1), List.of(1, 2, 3), 1_000);
        r.heard("b", Reservations.SILENT_MS);
        List<Outcome<String>> out = r.review(Reservations.SILENT_MS + 1);
        assertEquals(Set.of(3), r.holders().entrySet().stream().filter(e -> e.getValue().contains("a")).map(Map.Entry::getKey)
                .collect(java.util.stream.Collectors.toSet()), "a keeps the node its body takes");
        List<Failed> failed = only(out, Failed.class);
        assertEquals(List.of(new Failed<>("b", "tb", "a is silent and stands on the route", 3)), failed);
        assertTrue(r.heard("a", Reservations.SILENT_MS + 2).stream().anyMatch(o -> o.toString().contains("heard again")));
    }

    @Test
    void aNewRequestSupersedesTheChairsWait() {
        reserve("a", "ta", List.of(3), List.of(3), 0);
        reserve("b", "tb", List.of(1), List.of(1, 2, 3), 0);
        List<Outcome<String>> out = reserve("b", "tb2", List.of(1), List.of(1, 2), 5);
        assertEquals(List.of(new Failed<>("b", "tb", "superseded by a new route", null), new Granted<>("b", "tb2", List.of(1, 2))), out);
    }

    @Test
    void aRouteOffTheMapIsRefusedAndChangesNothing() {
        reserve("a", "ta", List.of(1), List.of(1, 2), 0);
        Map<Integer, Set<String>> before = r.holders();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> r.reserve("a", "tx", List.of(1), List.of(1, 5), false, 1));
        assertTrue(e.getMessage().contains("no edge 1-5"), e.getMessage());
        assertEquals(before, r.holders());
    }

    @Test
    void withoutTheRulesEveryRouteIsGrantedWhoeverHoldsIt() {
        Reservations<String> off = new Reservations<>(MAP, false);
        off.heard("a", 0);
        off.reserve("a", "ta", List.of(3), List.of(3, 4), false, 0);
        off.heard("b", 0);
        List<Outcome<String>> out = off.reserve("b", "tb", List.of(2), List.of(2, 3, 4), false, 0);
        assertEquals(List.of(new Granted<>("b", "tb", List.of(2, 3, 4))), out);
        assertEquals(Set.of("a", "b"), off.holders().get(3));
    }
}
