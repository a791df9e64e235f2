package io.concord.agents.control;

import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.*;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The traffic client alone: the test is the traffic agent (or its absence) and answers by hand. */
class TrafficClientTest {
    static final AID TRAFFIC = new AID("traffic@test");

    AID trafficAgent = TRAFFIC;
    final List<String> refused = new ArrayList<>();
    final Traffic out = new Traffic();
    final List<AclMessage> sent = out.sent;
    final List<CompletableFuture<AclMessage>> answers = out.answers;

    final TrafficClient client = new TrafficClient(out, (node, why) -> refused.add(node + " " + why));

    /** The traffic agent as the yellow pages give it (or none), over a recording outbox. */
    final class Traffic extends Fakes.Recording implements TrafficClient.Port {
        @Override
        public AID trafficAgent() {
            return trafficAgent;
        }
    }

    private String said(int i) {
        return sent.get(i).getPerformative() + " " + sent.get(i).getContent();
    }

    private static AclMessage answer(Performative p, WheelchairMessage w) {
        return new AclMessage(p).setContent(w.encode());
    }

    @Test
    void withNoTrafficAgentEveryRouteMayBeDrivenAtOnce() {
        trafficAgent = null;
        assertTrue(client.mayDrive(List.of(1, 2, 3), List.of(1), false));
        client.idle(1);
        client.alive(List.of(1));
        client.keepOnly(List.of(2, 3));
        assertTrue(sent.isEmpty());
    }

    @Test
    void aRouteIsAskedForOnceWholeAndDrivenOnceGranted() {
        List<Integer> route = new ArrayList<>(List.of(1, 2, 3));
        assertFalse(client.mayDrive(route, List.of(1), false));
        assertFalse(client.mayDrive(route, List.of(1), false));
        assertEquals(1, sent.size(), "asked once");
        assertEquals("REQUEST ((reserve :aside false :at (sequence 1) :path (sequence 1 2 3)))", said(0));
        answers.get(0).complete(answer(Performative.INFORM, new Granted(List.of(1, 2, 3))));
        assertTrue(client.mayDrive(route, List.of(1), false));
        assertTrue(client.mayDriveNow(route));
        assertFalse(client.mayDriveNow(new ArrayList<>(route)), "a grant is for that very route");
        assertEquals(List.of(1, 2, 3), client.held());
    }

    /**
     * Granted behind another chair: it may drive only as far as {@code upto}; a {@code clear} in the
     * grant's conversation lets it on, one of another conversation (an old grant) does not, and a
     * FAILURE after the grant (the chair ahead fell silent) ends the grant and is told.
     */
    @Test
    void aGrantInOrderIsDrivenUpToWhereItIsClear() {
        List<Integer> route = new ArrayList<>(List.of(1, 2, 3));
        client.mayDrive(route, List.of(1), false);
        answers.get(0).complete(answer(Performative.INFORM, new Granted(List.of(1, 2, 3), 2))
                .setConversationId("c1"));
        assertTrue(client.mayDrive(route, List.of(1), false));
        assertTrue(client.mayGoOn(route, 1));
        assertFalse(client.mayGoOn(route, 2), "node 3 is not its turn yet");
        assertEquals(3, client.waitsAt());
        AclMessage old = answer(Performative.INFORM, new Clear(3)).setConversationId("c0");
        assertFalse(client.isAboutGrant(old));
        client.aboutGrant(old);
        assertFalse(client.mayGoOn(route, 2), "a clear of another reservation changes nothing");
        client.aboutGrant(answer(Performative.INFORM, new Clear(3)).setConversationId("c1"));
        assertTrue(client.mayGoOn(route, 2));
        assertEquals(-1, client.waitsAt());
        client.aboutGrant(answer(Performative.FAILURE, new Failure(null, 3, "x is silent"))
                .setConversationId("c1"));
        assertEquals(List.of("3 FAILURE: x is silent"), refused);
        assertFalse(client.mayDriveNow(route), "the grant is over");
    }

    /**
     * The traffic agent grants up to node 1 and, in the same instant, clears the way to node 3; the
     * chair's mailbox hands the clear over before the grant (the depot soak's seed 153: the clear
     * was dropped as stale, and the chair waited for good at its grant's end, 13 chairs behind it).
     * Kept, it counts once the grant comes.
     */
    @Test
    void aClearReadBeforeItsGrantCountsWhenTheGrantComes() {
        List<Integer> route = new ArrayList<>(List.of(1, 2, 3));
        client.mayDrive(route, List.of(1), false);
        sent.get(0).setConversationId("c1"); // as the agent's asks name the request's conversation
        client.aboutGrant(answer(Performative.INFORM, new Clear(3)).setConversationId("c1"));
        answers.get(0).complete(answer(Performative.INFORM, new Granted(List.of(1, 2, 3), 1)).setConversationId("c1"));
        assertTrue(client.mayDrive(route, List.of(1), false));
        assertTrue(client.mayGoOn(route, 2), "cleared to node 3 by the clear read first");
        assertEquals(-1, client.waitsAt());
    }

    /** A clear of another conversation read before a grant is not kept for it. */
    @Test
    void aClearOfAnotherConversationBeforeTheGrantIsNotKept() {
        List<Integer> route = new ArrayList<>(List.of(1, 2, 3));
        client.mayDrive(route, List.of(1), false);
        sent.get(0).setConversationId("c1");
        client.aboutGrant(answer(Performative.INFORM, new Clear(3)).setConversationId("c0"));
        answers.get(0).complete(answer(Performative.INFORM, new Granted(List.of(1, 2, 3), 1)).setConversationId("c1"));
        assertFalse(client.mayGoOn(route, 2));
        assertEquals(2, client.waitsAt());
    }

    @Test
    void aStepAsideIsAskedWithPriority() {
        client.mayDrive(List.of(4, 5), List.of(4), true);
        assertEquals("REQUEST ((reserve :aside true :at (sequence 4) :path (sequence 4 5)))", said(0));
    }

    @Test
    void eachNodeLeftIsGivenBack() {
        List<Integer> route = List.of(1, 2, 3);
        client.mayDrive(route, List.of(1), false);
        answers.get(0).complete(answer(Performative.INFORM, new Granted(List.of())));
        client.keepOnly(List.of(2, 3));
        assertEquals("INFORM ((release :node 1))", said(1));
        client.keepOnly(List.of(2, 3));
        assertEquals(2, sent.size(), "given back once");
        assertEquals(List.of(2, 3), client.held());
    }

    @Test
    void aRouteThatCannotBeGrantedIsToldWithTheNodeInTheWayButAMakeWayOrASupersededWaitIsNot() {
        client.mayDrive(List.of(1, 2, 3), List.of(1), false);
        answers.get(0).complete(answer(Performative.FAILURE, new Failure(null, 2, "a silent chair stands there")));
        assertEquals(List.of("2 FAILURE: a silent chair stands there"), refused);

        client.mayDrive(List.of(1, 5), List.of(1), false);
        answers.get(1).complete(answer(Performative.FAILURE, new Failure(null, null, "make-way")));
        client.mayDrive(List.of(1, 6), List.of(1), false);
        answers.get(2).complete(answer(Performative.REFUSE, Refused.because("superseded by a newer request")));
        assertEquals(1, refused.size(), refused.toString());
    }

    @Test
    void anAnswerToAQuestionDroppedSinceIsIgnored() {
        List<Integer> route = List.of(1, 2, 3);
        client.mayDrive(route, List.of(1), false);
        client.reset();
        answers.get(0).complete(answer(Performative.INFORM, new Granted(List.of())));
        assertFalse(client.mayDriveNow(route));
        assertFalse(client.mayDrive(route, List.of(1), false), "asked anew");
        assertEquals(2, sent.size());
    }

    @Test
    void noAnswerAsksAgainOnTheNextStep() {
        List<Integer> route = List.of(1, 2);
        client.mayDrive(route, List.of(1), false);
        answers.get(0).complete(null);
        assertFalse(client.mayDrive(route, List.of(1), false));
        assertEquals(2, sent.size());
    }

    @Test
    void idleIsSaidOncePerNodeAndAliveSaysWhereItStands() {
        client.idle(7);
        client.idle(7);
        assertEquals(List.of("INFORM ((idle :at (sequence 7)))"), List.of(said(0)));
        assertEquals(1, sent.size());
        client.alive(List.of(7, 8));
        assertEquals("INFORM ((here :at (sequence 7 8)))", said(1));
        client.idle(8);
        assertEquals("INFORM ((idle :at (sequence 8)))", said(2));
        assertEquals(List.of(8), client.held());
    }
}
