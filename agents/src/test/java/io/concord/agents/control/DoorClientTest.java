package io.concord.agents.control;

import io.concord.agents.chair.Pose;
import io.concord.agents.map.Door;
import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Point;
import io.concord.agents.proto.WheelchairMessage.Refused;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;

import static io.concord.agents.control.Fakes.SMALL;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The door client alone: door D1 (centred at (5, 4)) between the corridor's node 1 (5, 2) and the
 * room's node 2 (5, 6.5); its agent is "door-D1", and the test answers for it.
 */
class DoorClientTest {
    static final AID DOOR_AGENT = new AID("door-D1@test");
    final Edge d1 = SMALL.edge(1, 2).orElseThrow();
    final Edge corridor = SMALL.edge(1, 3).orElseThrow();

    final Map<String, AID> agents = new HashMap<>(Map.of("D1", DOOR_AGENT));
    final List<String> closed = new ArrayList<>();
    final Doors out = new Doors();
    final List<AclMessage> sent = out.sent;
    final List<CompletableFuture<AclMessage>> answers = out.answers;
    final List<Long> timeouts = out.timeouts;

    final DoorClient client = new DoorClient(out, SMALL, "chair1", (from, why) -> closed.add(from + ": " + why), s -> { });

    /** The door agents as the yellow pages give them, over a recording outbox. */
    final class Doors extends Fakes.Recording implements DoorClient.Doors {
        @Override
        public AID agentOf(String id) {
            return agents.get(id);
        }
    }

    /** The chair on the line from node 1 to the door, {@code m} metres south of the door's centre. */
    static Pose south(double m) {
        return new Pose(5, 4 - m, Math.PI / 2);
    }

    private static String said(AclMessage m) {
        return m.getPerformative() + " " + m.getContent() + " to " + m.getReceivers().get(0).name();
    }

    @Test
    void farFromTheDoorTheChairDrivesOnAndNothingIsAsked() {
        assertTrue(client.mayEnter(d1, 1, south(DoorClient.ANNOUNCE_M + 0.1)));
        assertTrue(sent.isEmpty());
    }

    @Test
    void nearTheDoorItAsksOnceAndWaitsOutOfTheLeafsWay() {
        assertTrue(client.mayEnter(d1, 1, south(3.0)), "asked, and still beyond the waiting distance");
        assertTrue(client.mayEnter(d1, 1, south(2.5)));
        assertFalse(client.mayEnter(d1, 1, south(2.2)), "within 2.3 m of the door it waits");
        assertEquals(1, sent.size(), "one request");
        assertEquals("REQUEST ((open-request :body chair1)) to door-D1@test", said(sent.get(0)));
        assertEquals(DoorClient.OPEN_TIMEOUT_MS, timeouts.get(0));
    }

    @Test
    void onceTheDoorIsOpenForItTheChairPassesAndTellsTheDoorFromTheNodeBeyond() {
        client.mayEnter(d1, 1, south(3.0));
        answers.get(0).complete(new AclMessage(Performative.INFORM));
        assertTrue(client.mayEnter(d1, 1, south(1.0)));
        assertTrue(client.mayEnter(d1, 1, south(-1.0)), "in the doorway");
        client.reached(d1);
        assertEquals("INFORM ((passed :body chair1)) to door-D1@test", said(sent.get(1)));
        client.reached(d1);
        assertEquals(2, sent.size(), "told once");
        client.mayEnter(d1, 1, south(3.0));
        assertEquals(3, sent.size(), "the next time it comes, it asks again");
    }

    @Test
    void aNodeReachedOnAnEdgeWithoutTheDoorTellsNoDoor() {
        client.mayEnter(d1, 1, south(3.0));
        answers.get(0).complete(new AclMessage(Performative.INFORM));
        client.mayEnter(d1, 1, south(1.0));
        client.reached(corridor);
        assertEquals(1, sent.size());
    }

    @Test
    void aRefusalOrNoAnswerAsksForAPlanAroundTheDoorAndTheNextApproachAsksAgain() {
        client.mayEnter(d1, 1, south(3.0));
        answers.get(0).complete(new AclMessage(Performative.REFUSE).setContent(Refused.because("out of order").encode()));
        assertEquals(List.of("1: door D1 answered REFUSE: out of order"), closed);
        assertFalse(client.mayEnter(d1, 1, south(2.0)), "still closed for it");
        assertEquals(2, sent.size(), "asked again");
        answers.get(1).complete(null);
        assertEquals("1: door D1 did not open within 60 s", closed.get(1));
    }

    @Test
    void anAnswerForARouteGivenUpIsIgnored() {
        client.mayEnter(d1, 1, south(3.0));
        client.newRoute();
        answers.get(0).complete(new AclMessage(Performative.INFORM));
        assertFalse(client.mayEnter(d1, 1, south(2.0)), "not granted: it asks anew");
        assertEquals(2, sent.size());
        assertTrue(closed.isEmpty());
    }

    @Test
    void aDoorWithNoAgentIsPlannedAround() {
        agents.clear();
        assertFalse(client.mayEnter(d1, 1, south(3.0)));
        assertEquals(List.of("1: door D1 has no agent"), closed);
    }

    @Test
    void theDoorsAheadAreToldItStillMeansToPass() {
        Set<String> ahead = new LinkedHashSet<>(List.of("D1", "D9"));
        client.keepAlive(ahead);
        assertEquals(1, sent.size(), "D9 has no agent");
        assertEquals("INFORM ((here :body chair1)) to door-D1@test", said(sent.get(0)));
    }

    /**
     * A wide hinged leaf swinging towards the chair: it waits beyond the leaf's quarter circle
     * (1.6 m about the hinge, 2.68 m from the centre for a 1.2 m reach), where a fixed 2.3 m let the
     * leaf open to 0.1 m of it; on the far side of the same door, and at a sliding door, 2.3 m.
     */
    @Test
    void theChairWaitsOutsideTheLeafsSwingComputedFromTheLeaf() {
        HospitalMap wide = HospitalMap.parse("""
                {"format": "concord-hospital-map/1", "name": "wide door",
                 "walls": [{"id": "outer", "path": [[0, 0], [10, 0], [10, 9], [0, 9], [0, 0]]},
                           {"id": "w1", "from": [0, 4], "to": [4.2, 4]}, {"id": "w2", "from": [5.8, 4], "to": [10, 4]}],
                 "doors": [{"id": "D1", "kind": "hinged", "from": [4.2, 4], "to": [5.8, 4], "hinge": "from", "swing": "right"}],
                 "nodes": [{"id": 1, "at": [5, 0.8]}, {"id": 2, "at": [5, 7.5]}],
                 "edges": [{"from": 1, "to": 2, "door": "D1"}]}
                """, "test");
        Edge through = wide.edge(1, 2).orElseThrow();
        assertEquals(2.683, wide.door("D1").clearDistance(new Point(5, 1), DoorClient.LEAF_REACH_M), 0.001);
        DoorClient swingSide = new DoorClient(out, wide, "chair1", (from, why) -> closed.add(from + ": " + why), s -> { });
        assertTrue(swingSide.mayEnter(through, 1, south(2.8)), "beyond the swing");
        assertFalse(swingSide.mayEnter(through, 1, south(2.5)), "2.5 m from a 1.6 m leaf swinging this way: it waits");
        DoorClient farSide = new DoorClient(out, wide, "chair1", (from, why) -> closed.add(from + ": " + why), s -> { });
        Pose north = new Pose(5, 4 + 2.5, -Math.PI / 2);
        assertTrue(farSide.mayEnter(through, 2, north), "the leaf swings away from it: 2.3 m is enough");
        assertEquals(0, new Door("S", Door.Kind.SLIDING, new Point(0, 0), new Point(2, 0), Door.End.FROM, null)
                .clearDistance(new Point(1, -1), 1.2));
    }
}
