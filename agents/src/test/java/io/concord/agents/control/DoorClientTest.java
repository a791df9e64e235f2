package io.concord.agents.control;

import io.concord.agents.chair.Pose;
import io.concord.agents.map.Edge;
import io.concord.agents.proto.Content;
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
        assertEquals("REQUEST " + Content.of("open").with("body", "chair1") + " to door-D1@test", said(sent.get(0)));
        assertEquals(DoorClient.OPEN_TIMEOUT_MS, timeouts.get(0));
    }

    @Test
    void onceTheDoorIsOpenForItTheChairPassesAndTellsTheDoorFromTheNodeBeyond() {
        client.mayEnter(d1, 1, south(3.0));
        answers.get(0).complete(new AclMessage(Performative.INFORM));
        assertTrue(client.mayEnter(d1, 1, south(1.0)));
        assertTrue(client.mayEnter(d1, 1, south(-1.0)), "in the doorway");
        client.reached(d1);
        assertEquals("INFORM " + Content.of("passed").with("body", "chair1") + " to door-D1@test", said(sent.get(1)));
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
        answers.get(0).complete(new AclMessage(Performative.REFUSE).setContent(Content.of("refuse").with("reason", "out of order").toString()));
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
        assertEquals("INFORM " + Content.of("here").with("body", "chair1") + " to door-D1@test", said(sent.get(0)));
    }
}
