package io.concord.agents.traffic;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.traffic.Reservations.Clear;
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
 * room off its middle (6, a dead end), and chairs a, b, c, d. Time is whatever the test says. The
 * rules in order (the default) unless a test says whole routes.
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

    private final Reservations<String> r = new Reservations<>(MAP, TrafficRules.IN_ORDER);
    private final Reservations<String> whole = new Reservations<>(MAP, TrafficRules.WHOLE_ROUTES);

    private static <T extends Outcome<String>> List<T> only(List<Outcome<String>> out, Class<T> kind) {
        return out.stream().filter(kind::isInstance).map(kind::cast).toList();
    }

    private List<Outcome<String>> reserve(String chair, String ticket, List<Integer> at, List<Integer> path, long now) {
        return reserve(r, chair, ticket, at, path, now);
    }

    private static List<Outcome<String>> reserve(Reservations<String> rules, String chair, String ticket, List<Integer> at,
                                                 List<Integer> path, long now) {
        rules.heard(chair, now);
        return rules.reserve(chair, ticket, at, path, false, now);
    }

    @Test
    void aFreeRouteIsGrantedAtOnceAndHeldUntilGivenBack() {
        List<Outcome<String>> out = reserve("a", "t1", List.of(1), List.of(1, 2, 3), 0);
        assertEquals(List.of(new Granted<>("a", "t1", List.of(1, 2, 3), 3)), out, "all of it, up to its end");
        assertEquals(Map.of(1, List.of("a"), 2, List.of("a"), 3, List.of("a")), r.holders());
        r.release("a", 1, 10);
        assertEquals(Set.of(2, 3), r.holders().keySet());
        assertEquals(1, r.grants());
    }

    /**
     * The wait a quote includes: none on a free way; with chairs holding or queued for nodes of the
     * way, each counted once, for as long as chairs have held those nodes (the pass time before any
     * node was given back, then what was measured: a chair that stood 60 s at node 3 makes node 3
     * a long wait).
     */
    @Test
    void aQuoteWithChairsAheadOnItsWayWaitsLongerAndLearnsHowLongANodeIsHeld() {
        assertEquals(0, r.expectedWaitS("c", List.of(1, 2, 3, 4, 5)), 1e-9, "nobody on the way");
        reserve("a", "ta", List.of(3), List.of(3, 4), 0);
        reserve("b", "tb", List.of(4), List.of(4, 5), 0);
        double two = r.expectedWaitS("c", List.of(1, 2, 3, 4, 5));
        assertEquals(2 * Reservations.PASS_MS / 1000.0, two, 1e-9, "a and b ahead, a pass each, a counted once over 3 and 4");
        assertEquals(0, r.expectedWaitS("a", List.of(2, 3)), 1e-9, "its own reservations are no wait");
        assertEquals(Reservations.PASS_MS / 1000.0, r.expectedWaitS("c", List.of(1, 2, 3)), 1e-9, "only a on 1-2-3");
        // a stands at 3 for 60 s before it leaves it: 3's hold is learnt, and the next quote through 3 is longer.
        r.release("a", 3, 60_000);
        reserve("d", "td", List.of(2), List.of(2, 3), 60_000);
        double learnt = r.expectedWaitS("c", List.of(1, 2, 3));
        assertTrue(learnt > Reservations.PASS_MS / 1000.0, "d ahead on 3, which was held 60 s (a moving mean): " + learnt);
    }

    /**
     * In order, a chair follows another down the corridor: granted at once behind it, up to the
     * node before the one the first still holds, and told to go on as the first leaves each node.
     */
    @Test
    void aChairFollowsAnotherDownTheCorridorInTheSameDirection() {
        reserve("a", "ta", List.of(2), List.of(2, 3, 4, 5), 0);
        List<Outcome<String>> out = reserve("b", "tb", List.of(1), List.of(1, 2, 3, 4), 0);
        assertEquals(List.of(new Granted<>("b", "tb", List.of(1, 2, 3, 4), 1)), out, "granted behind a: up to node 1, where it stands");
        assertEquals(List.of("a", "b"), r.holders().get(3), "node 3's queue: a, then b");
        assertEquals(List.of("b -> [1, 2, 3, 4] at node 1 (ahead at node 2: [a])"), r.waits());
        assertEquals(List.of(new Clear<>("b", "tb", 2)), r.release("a", 2, 60), "a reached 3 and left 2: b may drive to 2, not 3");
        assertEquals(List.of(new Clear<>("b", "tb", 3)), r.release("a", 3, 70), "a reached 4: b may drive to 3");
        assertEquals(List.of(new Clear<>("b", "tb", 4)), r.release("a", 4, 80), "a reached 5: b may drive to its end");
        assertEquals(2, r.grants());
    }

    /** Whole routes, as before issue 37: the follower waits until the chair ahead has given back every node of its route. */
    @Test
    void withWholeRoutesARouteThroughAnotherChairsNodesWaitsUntilTheyAreGivenBack() {
        reserve(whole, "a", "ta", List.of(3), List.of(3, 4), 0);
        List<Outcome<String>> out = reserve(whole, "b", "tb", List.of(1), List.of(1, 2, 3), 0);
        assertEquals(List.of(new Waiting<>("b", "tb", List.of("a"))), out, "b waits, told who is in the way");
        assertEquals(List.of("b -> [1, 2, 3] (in the way: [a])"), whole.waits());
        assertEquals(List.of(new Granted<>("b", "tb", List.of(1, 2, 3), null)), whole.release("a", 3, 100), "granted once a has left 3");
    }

    /** A chair never drives through a node where another ends its route (it would stop there): the route waits. */
    @Test
    void aRouteThroughAnotherChairsDestinationWaitsForIt() {
        reserve("a", "ta", List.of(2), List.of(2, 3), 0);
        List<Outcome<String>> out = reserve("b", "tb", List.of(1), List.of(1, 2, 3, 4), 0);
        assertEquals(List.of(new Waiting<>("b", "tb", List.of("a"))), out);
        r.release("a", 2, 10);
        r.heard("a", 20);
        List<Outcome<String>> after = r.idle("a", List.of(3), 20);
        List<MakeWay> moved = only(after, MakeWay.class);
        assertEquals(List.of("a"), moved.stream().map(MakeWay::chair).toList(), "a, idle on b's route, makes way: " + after);
    }

    /**
     * Two chairs on one lane, the second following the first, and the first turns back (a new
     * plan): each waits for the other, a deadlock; the one that stands still steps aside into the
     * dead end, and the one under way drives on.
     */
    @Test
    void aChairTurningBackBeforeOneFollowingItStepsAsideIntoTheDeadEnd() {
        reserve("a", "ta", List.of(2), List.of(2, 3, 4), 0);
        reserve("b", "tb", List.of(1), List.of(1, 2, 3), 0);
        r.release("a", 2, 10); // a reached 3
        r.release("b", 1, 20); // b reached 2
        List<Outcome<String>> out = reserve("a", "ta2", List.of(3), List.of(3, 2, 1), 30);
        assertEquals(1, r.deadlocks(), out.toString());
        assertEquals(List.of(new MakeWay<>("a", 3, 6, List.of(6))), only(out, MakeWay.class));
        r.heard("a", 40);
        r.reserve("a", "ta3", List.of(3), List.of(3, 6), true, 40);
        assertEquals(List.of(new Clear<>("b", "tb", 3)), only(r.release("a", 3, 50), Clear.class), "a left 3 for the dead end: b drives on");
    }

    /**
     * The same, with every node a could step aside to taken: nobody can step aside, so b, under
     * way, gives its route back (keeping node 2, where it stands) and is told to ask again.
     */
    @Test
    void aDeadlockNobodyCanStepAsideFromTakesAGrantBack() {
        reserve("a", "ta", List.of(2), List.of(2, 3, 4, 5), 0);
        reserve("b", "tb", List.of(1), List.of(1, 2, 3), 0);
        r.release("a", 2, 10);
        r.release("b", 1, 20);
        r.heard("c", 20);
        r.idle("c", List.of(6), 20);
        r.heard("d", 20);
        r.idle("d", List.of(4), 20); // after a in 4's queue: it takes 4 once a gives it back
        List<Outcome<String>> out = reserve("a", "ta3", List.of(3), List.of(3, 2, 1), 30);
        List<MakeWay> moved = only(out, MakeWay.class);
        assertEquals(List.of(), moved, "nowhere to step aside to");
        List<Failed> failed = only(out, Failed.class);
        assertEquals(List.of(new Failed<>("b", "tb", "deadlock [a, b]: the route is given back, ask again", null)), failed, out.toString());
        assertEquals(List.of("b"), r.holders().get(2), "b keeps where it stands");
        assertEquals(List.of("a"), r.holders().get(3));
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
        assertEquals(List.of(new Granted<>("b", "tb", List.of(1, 2, 3, 4), 4)), granted, "b goes once a has left 3");
    }

    /** Out of the way is never a patient's room: with the room off the corridor a room, the chair goes to the corridor's end. */
    @Test
    void anIdleChairNeverStepsAsideIntoAPatientsRoom() {
        Reservations<String> rooms = new Reservations<>(HospitalMap.parse(CORRIDOR.replace("""
                    {"id": "ward", "kind": "ward", "name": "Ward", "polygon": [[0, 0], [30, 0], [30, 12], [0, 12]]}
                """, """
                    {"id": "ward", "kind": "ward", "name": "Ward", "polygon": [[0, 0], [30, 0], [30, 12], [0, 12]]},
                    {"id": "r6", "kind": "room", "ward": "ward", "polygon": [[10, 7], [16, 7], [16, 12], [10, 12]]}
                """), "test"), TrafficRules.IN_ORDER);
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
        assertEquals(List.of(new Failed<>("b", "tb", "superseded by a new route", null), new Granted<>("b", "tb2", List.of(1, 2), 2)), out);
    }

    @Test
    void aRouteOffTheMapIsRefusedAndChangesNothing() {
        reserve("a", "ta", List.of(1), List.of(1, 2), 0);
        Map<Integer, List<String>> before = r.holders();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> r.reserve("a", "tx", List.of(1), List.of(1, 5), false, 1));
        assertTrue(e.getMessage().contains("no edge 1-5"), e.getMessage());
        assertEquals(before, r.holders());
    }

    @Test
    void withoutTheRulesEveryRouteIsGrantedWhoeverHoldsIt() {
        Reservations<String> off = new Reservations<>(MAP, TrafficRules.NONE);
        off.heard("a", 0);
        off.reserve("a", "ta", List.of(3), List.of(3, 4), false, 0);
        off.heard("b", 0);
        List<Outcome<String>> out = off.reserve("b", "tb", List.of(2), List.of(2, 3, 4), false, 0);
        assertEquals(List.of(new Granted<>("b", "tb", List.of(2, 3, 4), null)), out);
        assertEquals(List.of("a", "b"), off.holders().get(3));
    }

    // ---- liveness (issue 47) ---------------------------------------------------------------------

    /**
     * A cycle through a chair sent aside that does not get there: a stands on 2 and b on 4, each
     * asking through the other (a deadlock); a is sent aside to the dead end 1. Before it moves, c
     * appears on 1 and asks for a route through 2: a's way aside waits for c, c waits for a. While a
     * is on its way (the grace), the cycle is left to end by itself; after it, a's order is called
     * off and the cycle is broken by the other rules (a steps aside to 6 instead).
     */
    @Test
    void aCycleThroughAChairSentAsideIsBrokenOnceItsGraceIsOver() {
        List<Outcome<String>> moved = cycleThroughAChairSentAside(r);
        assertEquals(List.of(new MakeWay<>("a", 2, 6, List.of(3, 6))), only(moved, MakeWay.class), moved.toString());
        assertTrue(moved.stream().anyMatch(o -> o instanceof Failed<String> f && f.chair().equals("a") && f.reason().contains("called off")), moved.toString());
    }

    /**
     * A lane (1-2-3) to a patient's room (4) off its end, and a bay (5, then 6) off node 3: b, deep
     * in the lane at 1, must reach 4; a is idle on 3, c idle on 5. The only free node a could step
     * to is 2, on b's way: a cannot make way (the depot's seed 6, where a chair at the depot's exit
     * stood idle in the way for good and its neighbour idle beside it).
     */
    static final String BAY_JSON = """
            {
              "format": "concord-hospital-map/1",
              "name": "bay",
              "walls": [
                {"id": "outer", "path": [[0, 0], [30, 0], [30, 12], [0, 12], [0, 0]]}
              ],
              "areas": [
                {"id": "ward", "kind": "ward", "name": "Ward", "polygon": [[0, 0], [30, 0], [30, 12], [0, 12]]}
              ],
              "nodes": [
                {"id": 1, "at": [3, 4]}, {"id": 2, "at": [8, 4]}, {"id": 3, "at": [13, 4]},
                {"id": 4, "at": [13, 9], "name": "the patient's room"}, {"id": 5, "at": [18, 4]}, {"id": 6, "at": [23, 4]}
              ],
              "edges": [
                {"from": 1, "to": 2}, {"from": 2, "to": 3}, {"from": 3, "to": 4}, {"from": 3, "to": 5}, {"from": 5, "to": 6}
              ]
            }
            """;
    static final HospitalMap BAY = HospitalMap.parse(BAY_JSON, "test");

    private static List<Outcome<String>> walledIn(Reservations<String> rules) {
        rules.heard("a", 0);
        rules.idle("a", List.of(3), 0);
        rules.heard("c", 0);
        rules.idle("c", List.of(5), 0);
        return reserve(rules, "b", "tb", List.of(1), List.of(1, 2, 3, 4), 0);
    }

    @Test
    void anIdleChairWalledInByAnotherIsClearedForByPushingThatOneFirst() {
        Reservations<String> rules = new Reservations<>(BAY, TrafficSettings.standard());
        List<Outcome<String>> out = walledIn(rules);
        assertEquals(List.of(new MakeWay<>("c", 5, 6, List.of(6))), only(out, MakeWay.class), out.toString());
        // c drives into the bay's end and leaves 5: a takes it, and b's way is clear.
        rules.heard("c", 10);
        rules.reserve("c", "tc", List.of(5), List.of(5, 6), true, 10);
        List<Outcome<String>> next = rules.release("c", 5, 20);
        assertEquals(List.of(new MakeWay<>("a", 3, 5, List.of(5))), only(next, MakeWay.class), next.toString());
        rules.heard("a", 30);
        rules.reserve("a", "ta", List.of(3), List.of(3, 5), true, 30);
        List<Granted> granted = only(rules.release("a", 3, 40), Granted.class);
        assertEquals(List.of(new Granted<>("b", "tb", List.of(1, 2, 3, 4), 4)), granted, "b goes once a has left 3");
    }

    /**
     * A late release (the depot soak's seed 12): a was ordered aside to node 3 while its own route
     * through node 3 was on its way to the traffic agent; its refusal of the order, giving node 3
     * back, comes after that route was granted. d, in the room, is granted its way out behind a.
     */
    private static List<Outcome<String>> lateRelease(Reservations<String> rules) {
        reserve(rules, "a", "ta", List.of(1), List.of(1, 2, 3, 4), 0);
        List<Outcome<String>> d = reserve(rules, "d", "td", List.of(6), List.of(6, 3, 2, 1), 0);
        assertEquals(List.of(new Granted<>("d", "td", List.of(6, 3, 2, 1), 6)), only(d, Granted.class), "behind a: d stays in the room");
        rules.heard("a", 10);
        return rules.release("a", 3, 10);
    }

    /** The node stays a's: d is not cleared into it (it would meet a head-on between 2 and 3), until a has left it. */
    @Test
    void aNodeGivenBackAheadOfTheChairOnItsRouteStaysItsAndNobodyIsClearedIntoIt() {
        List<Outcome<String>> out = lateRelease(r);
        assertEquals(List.of(), only(out, Clear.class), out.toString());
        assertEquals(List.of("a", "d"), r.holders().get(3), "a first at node 3 still");
        assertEquals(1, r.staleReleases());
        // a drives on: it leaves 1, 2 and then 3, and d goes once a is at 4.
        r.release("a", 1, 20);
        r.release("a", 2, 30);
        assertEquals(List.of(new Clear<>("d", "td", 1)), only(r.release("a", 3, 40), Clear.class));
    }

    /** With the rule off the late release is obeyed: d is cleared into node 3, which a is granted to drive through. */
    @Test
    void withoutTheRuleALateReleaseClearsAnotherChairIntoTheNodeHeadOn() {
        Reservations<String> off = new Reservations<>(MAP, TrafficSettings.standard().without(TrafficSettings.Rule.RELEASE_BEHIND));
        List<Outcome<String>> out = lateRelease(off);
        assertTrue(out.stream().anyMatch(o -> o instanceof Clear<String> c && c.chair().equals("d")), out.toString());
        assertTrue(off.cleared().get("a").contains(3), "a still cleared through 3: " + off.cleared());
    }

    /**
     * The bay one node deeper (5, 6, then 7): c idle on 5 is walled in by e idle on 6 (the depot's
     * seed 49: a full lobby, a chair on the store room's door in the way of the chair sent there).
     */
    static final HospitalMap DEEP_BAY = HospitalMap.parse(BAY_JSON.replace(
            "{\"id\": 6, \"at\": [23, 4]}", "{\"id\": 6, \"at\": [23, 4]}, {\"id\": 7, \"at\": [27, 4]}").replace(
            "{\"from\": 5, \"to\": 6}", "{\"from\": 5, \"to\": 6}, {\"from\": 6, \"to\": 7}"), "test");

    /** e, the one that can move, goes first; c and then a each take the node freed; b goes. */
    @Test
    void aChainOfIdleChairsWalledInIsClearedFromItsFarEnd() {
        Reservations<String> rules = new Reservations<>(DEEP_BAY, TrafficSettings.standard());
        rules.heard("e", 0);
        rules.idle("e", List.of(6), 0);
        List<Outcome<String>> out = walledIn(rules);
        assertEquals(List.of(new MakeWay<>("e", 6, 7, List.of(7))), only(out, MakeWay.class), out.toString());
        rules.reserve("e", "te", List.of(6), List.of(6, 7), true, 10);
        List<Outcome<String>> next = rules.release("e", 6, 20);
        assertEquals(List.of(new MakeWay<>("c", 5, 6, List.of(6))), only(next, MakeWay.class), next.toString());
        rules.reserve("c", "tc", List.of(5), List.of(5, 6), true, 30);
        next = rules.release("c", 5, 40);
        assertEquals(List.of(new MakeWay<>("a", 3, 5, List.of(5))), only(next, MakeWay.class), next.toString());
        rules.reserve("a", "ta", List.of(3), List.of(3, 5), true, 50);
        List<Granted> granted = only(rules.release("a", 3, 60), Granted.class);
        assertEquals(List.of(new Granted<>("b", "tb", List.of(1, 2, 3, 4), 4)), granted, "b goes once a has left 3");
    }

    /**
     * The same with the chain off (and the walled-in refusal, which would answer b's wait instead):
     * only a's own neighbour c is tried, it cannot move, and b waits for good.
     */
    @Test
    void withoutTheChainAPushStopsAtTheFirstWalledInChair() {
        Reservations<String> off = new Reservations<>(DEEP_BAY, TrafficSettings.standard().without(TrafficSettings.Rule.PUSH_CHAIN, TrafficSettings.Rule.WALLED_IN));
        off.heard("e", 0);
        off.idle("e", List.of(6), 0);
        List<Outcome<String>> out = walledIn(off);
        for (long t = 1_000; t <= 600_000; t += 1_000) {
            for (String c : List.of("a", "b", "c", "e")) {
                off.heard(c, t);
            }
            out.addAll(off.review(t));
        }
        assertEquals(List.of(), only(out, MakeWay.class), out.toString());
        assertTrue(off.waits().stream().anyMatch(w -> w.startsWith("b")), off.waits().toString());
    }

    /**
     * Walled in: b at 2 must reach the room (6, off 3); a idle on 3, c on 4 and d on 5 (a dead
     * end) fill the rest, so no idle chair can go anywhere but b's way (the depot soak's seed 59: a
     * full lobby whose one way out the waiting chair stood on).
     */
    private static List<Outcome<String>> walledInFull(Reservations<String> rules) {
        for (String[] c : new String[][] {{"a", "3"}, {"c", "4"}, {"d", "5"}}) {
            rules.heard(c[0], 0);
            rules.idle(c[0], List.of(Integer.parseInt(c[1])), 0);
        }
        List<Outcome<String>> out = new java.util.ArrayList<>(reserve(rules, "b", "tb", List.of(2), List.of(2, 3, 6), 0));
        for (long t = 1_000; t <= 300_000; t += 1_000) {
            for (String c : List.of("a", "b", "c", "d")) {
                rules.heard(c, t);
            }
            out.addAll(rules.review(t));
        }
        return out;
    }

    /** After a minute b's wait is refused, naming node 3, where a stands: b plans around it (its task goes to another chair). */
    @Test
    void aChairWalledInByIdleChairsNoneCanMoveIsRefusedNamingTheNodeInTheWay() {
        Reservations<String> rules = new Reservations<>(MAP, TrafficSettings.standard());
        List<Outcome<String>> out = walledInFull(rules);
        assertEquals(List.of(), only(out, MakeWay.class), "nobody can move: " + out);
        List<Failed> failed = only(out, Failed.class);
        assertEquals(1, failed.size(), out.toString());
        assertEquals("b", failed.get(0).chair());
        assertEquals(3, failed.get(0).node());
        assertTrue(failed.get(0).reason().startsWith("walled in: [a]"), failed.get(0).reason());
        assertTrue(rules.waits().stream().noneMatch(w -> w.startsWith("b")), rules.waits().toString());
    }

    /** With the rule off b waits for good. */
    @Test
    void withoutTheRuleAChairWalledInWaitsForGood() {
        Reservations<String> off = new Reservations<>(MAP, TrafficSettings.standard().without(TrafficSettings.Rule.WALLED_IN));
        List<Outcome<String>> out = walledInFull(off);
        assertEquals(List.of(), only(out, Failed.class), out.toString());
        assertTrue(off.waits().stream().anyMatch(w -> w.startsWith("b")), off.waits().toString());
    }

    /** The same with the rule off (and the walled-in refusal): a cannot make way, c is in nobody's way, and b waits for good. */
    @Test
    void withoutPushAnIdleChairWalledInStaysInTheWayForGood() {
        Reservations<String> off = new Reservations<>(BAY, TrafficSettings.standard().without(TrafficSettings.Rule.PUSH, TrafficSettings.Rule.WALLED_IN));
        List<Outcome<String>> out = walledIn(off);
        assertEquals(List.of(), only(out, MakeWay.class), out.toString());
        for (long t = 1_000; t <= 600_000; t += 1_000) {
            off.heard("a", t);
            off.heard("b", t);
            off.heard("c", t);
            out = off.review(t);
            assertEquals(List.of(), only(out, MakeWay.class), "at " + t + " ms: " + out);
        }
        assertTrue(off.waits().stream().anyMatch(w -> w.startsWith("b")), off.waits().toString());
    }

    /** The same with the rule off (a cycle with a chair sent aside is left alone, as before): nobody moves, ever. */
    @Test
    void withoutTheRuleACycleThroughAChairSentAsideIsNeverBroken() {
        Reservations<String> off = new Reservations<>(MAP, TrafficSettings.standard().without(TrafficSettings.Rule.ANY_CYCLE));
        List<Outcome<String>> moved = cycleThroughAChairSentAside(off);
        assertEquals(List.of(), only(moved, MakeWay.class), "stuck for good: " + off.waits());
    }

    private static List<Outcome<String>> cycleThroughAChairSentAside(Reservations<String> rules) {
        reserve(rules, "a", "ta", List.of(2), List.of(2), 0);
        reserve(rules, "b", "tb", List.of(4), List.of(4), 0);
        reserve(rules, "a", "ta2", List.of(2), List.of(2, 3, 4), 1);
        List<Outcome<String>> first = reserve(rules, "b", "tb2", List.of(4), List.of(4, 3, 2), 2);
        assertEquals(List.of(new MakeWay<>("a", 2, 1, List.of(1))), only(first, MakeWay.class), first.toString());
        // c appears on 1 before a gets there, and asks for a route through 2, where a stands.
        reserve(rules, "c", "tc", List.of(1), List.of(1), 3);
        rules.heard("a", 4);
        rules.reserve("a", "ta3", List.of(2), List.of(2, 1), true, 4); // a's way aside, to 1
        reserve(rules, "c", "tc2", List.of(1), List.of(1, 2, 3), 5);
        List<Outcome<String>> during = new java.util.ArrayList<>();
        for (long t = 6_000; t < Reservations.ASIDE_GRACE_MS; t += 1_000) {
            heardAll(rules, t);
            during.addAll(rules.review(t));
        }
        assertEquals(List.of(), only(during, MakeWay.class), "within the grace, a is on its way aside: " + during);
        List<Outcome<String>> after = new java.util.ArrayList<>();
        for (long t = Reservations.ASIDE_GRACE_MS; t < 10 * Reservations.ASIDE_GRACE_MS; t += 1_000) {
            heardAll(rules, t);
            after.addAll(rules.review(t));
        }
        return after;
    }

    private static void heardAll(Reservations<String> rules, long t) {
        for (String c : List.of("a", "b", "c")) {
            rules.heard(c, t);
        }
    }

    static final HospitalMap PARKED = HospitalMap.parse(CORRIDOR.replace("""
                {"id": "ward", "kind": "ward", "name": "Ward", "polygon": [[0, 0], [30, 0], [30, 12], [0, 12]]}
            """, """
                {"id": "ward", "kind": "ward", "name": "Ward", "polygon": [[0, 0], [30, 0], [30, 12], [0, 12]]},
                {"id": "r6", "kind": "room", "ward": "ward", "polygon": [[10, 7], [16, 7], [16, 12], [10, 12]]}
            """).replace("""
              ]
            }
            """, """
              ],
              "parking": [5, 1]
            }
            """), "test");

    /**
     * An idle chair goes home: idle in the patient's room (6) for 30 s, it is sent to the nearest
     * parking place nobody holds: 1 and 5 are both three hops away, and the map names 5 first. Once
     * there, idle again, it stays.
     */
    @Test
    void anIdleChairInAPatientsRoomGoesToTheNearestFreeParkingPlace() {
        Reservations<String> rules = new Reservations<>(PARKED, TrafficSettings.standard());
        rules.heard("a", 0);
        assertEquals(List.of(), only(rules.idle("a", List.of(6), 0), MakeWay.class), "not at once: a next task usually comes sooner");
        rules.heard("a", 29_999);
        assertEquals(List.of(), only(rules.review(29_999), MakeWay.class));
        rules.heard("a", 30_000);
        List<Outcome<String>> out = rules.review(30_000);
        assertEquals(List.of(new MakeWay<>("a", 6, 5, List.of(3, 4, 5))), only(out, MakeWay.class), out.toString());
        rules.heard("a", 30_010);
        rules.reserve("a", "home", List.of(6), List.of(6, 3, 4, 5), true, 30_010);
        for (int n : List.of(6, 3, 4)) {
            rules.release("a", n, 30_020);
        }
        rules.idle("a", List.of(5), 30_030);
        rules.heard("a", 90_000);
        assertEquals(List.of(), only(rules.review(90_000), MakeWay.class), "home: it stays");
        // Another idle in the room goes to 1: 5 is taken.
        rules.heard("b", 90_000);
        rules.idle("b", List.of(6), 90_000);
        rules.heard("a", 120_000);
        rules.heard("b", 120_000);
        assertEquals(List.of(new MakeWay<>("b", 6, 1, List.of(3, 2, 1))), only(rules.review(120_000), MakeWay.class));
    }

    /**
     * No parking place it can reach when the chair's 30 s are up (b stands on 3, the room's only
     * way out): it is said once, and the chair goes home as soon as the way is free (before, the
     * one try was all, and the chair stayed in the patient's room for good: a newcomer's run on
     * the default hospital).
     */
    @Test
    void anIdleChairWithNoPlaceToReachGoesHomeOnceTheWayIsFree() {
        Reservations<String> rules = new Reservations<>(PARKED, TrafficSettings.standard());
        reserve(rules, "b", "tb", List.of(3), List.of(3), 0);   // b stands on 3 with its task
        rules.heard("a", 0);
        rules.idle("a", List.of(6), 0);
        List<Outcome<String>> out = new java.util.ArrayList<>();
        for (long t = 1_000; t <= 60_000; t += 1_000) {
            rules.heard("a", t);
            rules.heard("b", t);
            out.addAll(rules.review(t));
        }
        assertEquals(List.of(), only(out, MakeWay.class), "nowhere to go yet");
        assertEquals(1, out.stream().filter(o -> o.toString().contains("none is free to go to")).count(), out.toString());
        // b drives on to 2 and leaves 3.
        reserve(rules, "b", "tb2", List.of(3), List.of(3, 2), 61_000);
        out = new java.util.ArrayList<>(rules.release("b", 3, 62_000));
        rules.heard("a", 63_000);
        out.addAll(rules.review(63_000));
        assertEquals(List.of(new MakeWay<>("a", 6, 5, List.of(3, 4, 5))), only(out, MakeWay.class), out.toString());
    }

    /** The same with the rule off: the chair stays in the patient's room. */
    @Test
    void withoutTheRuleAnIdleChairStaysInThePatientsRoom() {
        Reservations<String> rules = new Reservations<>(PARKED, TrafficSettings.standard().without(TrafficSettings.Rule.HOME));
        rules.heard("a", 0);
        List<Outcome<String>> out = new java.util.ArrayList<>(rules.idle("a", List.of(6), 0));
        for (long t = 1_000; t < 600_000; t += 1_000) {
            rules.heard("a", t);
            out.addAll(rules.review(t));
        }
        assertEquals(List.of(), only(out, MakeWay.class));
    }

    /**
     * The fleet monitor: a chair with work that makes no progress for the limit is reported, naming
     * what it waits for (here its turn behind b, who stands where it must go), and reported again at
     * twice and four times the limit while the wait goes on; idle chairs are never reported.
     */
    @Test
    void aChairWithWorkAndNoProgressForTheLimitRaisesAnAlarmNamingWhatItWaitsForAndRaisesItAgain() {
        Reservations<String> rules = new Reservations<>(MAP, TrafficSettings.standard());
        reserve(rules, "b", "tb", List.of(3), List.of(3), 0); // b stands on 3, with work (loading, say)
        reserve(rules, "a", "ta", List.of(1), List.of(1, 2, 3, 4), 0);
        rules.heard("c", 0);
        rules.idle("c", List.of(5), 0);
        List<Reservations.Stalled<String>> alarms = new java.util.ArrayList<>();
        for (long t = 1_000; t <= 500_000; t += 1_000) {
            for (String c : List.of("a", "b", "c")) {
                rules.heard(c, t);
            }
            alarms.addAll(only(rules.review(t), Reservations.Stalled.class).stream().map(x -> (Reservations.Stalled<String>) x).toList());
        }
        assertEquals(List.of("a", "a", "a", "b", "b", "b"), alarms.stream().map(Reservations.Stalled::chair).sorted().toList(),
                "at 120, 240 and 480 s each, never the idle c: " + alarms);
        List<Long> aFor = alarms.stream().filter(x -> x.chair().equals("a")).map(Reservations.Stalled::forMs).toList();
        assertEquals(List.of(120_000L, 240_000L, 480_000L), aFor, "raised again, less often the longer the wait");
        Reservations.Stalled<String> a = alarms.stream().filter(x -> x.chair().equals("a")).findFirst().orElseThrow();
        assertEquals("its route [1, 2, 3, 4] (in the way: [b])", a.waitsFor());
        assertEquals(6, rules.alarms());
    }

    /** With the alarm off, the same wait is never reported. */
    @Test
    void withoutTheAlarmTheSameWaitIsNeverReported() {
        Reservations<String> rules = new Reservations<>(MAP, TrafficSettings.standard().without(TrafficSettings.Rule.ALARM));
        reserve(rules, "b", "tb", List.of(3), List.of(3), 0);
        reserve(rules, "a", "ta", List.of(1), List.of(1, 2, 3, 4), 0);
        for (long t = 1_000; t <= 300_000; t += 1_000) {
            rules.heard("a", t);
            rules.heard("b", t);
            assertEquals(List.of(), only(rules.review(t), Reservations.Stalled.class));
        }
        assertEquals(0, rules.alarms());
    }

    /**
     * Admission: no chair is cleared into a node it could not leave. a is granted 1-2-3-4 behind
     * b, granted 3-4-5 before it; b's task is dropped as it drives to 4, and it stands there idle,
     * giving 3 back: a may stay at 2, not drive into 3, whose next node b stands on (b is sent out
     * of the way meanwhile). With the rule off a is cleared into 3, where it would stand with nowhere
     * to go.
     */
    @Test
    void aChairIsNotClearedIntoANodeItCouldNotLeave() {
        assertEquals(2, clearedUpToBehindAChairThatStops(TrafficSettings.standard()));
    }

    @Test
    void withoutAdmissionAChairIsClearedIntoANodeItCouldNotLeave() {
        assertEquals(3, clearedUpToBehindAChairThatStops(TrafficSettings.standard().without(TrafficSettings.Rule.ADMISSION)));
    }

    private static int clearedUpToBehindAChairThatStops(TrafficSettings settings) {
        Reservations<String> rules = new Reservations<>(MAP, settings);
        reserve(rules, "b", "tb", List.of(3), List.of(3, 4, 5), 0);
        reserve(rules, "a", "ta", List.of(1), List.of(1, 2, 3, 4), 0); // behind b: up to 2
        rules.heard("b", 20);
        rules.idle("b", List.of(4), 20); // b, its task dropped on the edge to 4, stands there idle: 3 is given back
        List<Integer> cleared = rules.cleared().get("a");
        return cleared.get(cleared.size() - 1);
    }
}
