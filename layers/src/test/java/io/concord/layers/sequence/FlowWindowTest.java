package io.concord.layers.sequence;

import io.concord.core.layer.SendRejectedException;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The flow window alone: what a sender holds, when its agent is paused, what a receiver announces. */
class FlowWindowTest {
    private static final SequenceLayer.Config WINDOW_OF_4 = new SequenceLayer.Config(4, 16, 5, 32, 20, 30, 10, 40, 64);
    private final Parts a = new Parts(WINDOW_OF_4, true);

    /** Sends through the window as the layer does: held if it must, else transmitted. */
    private void send(SenderState o, String text) {
        if (a.flow.mustHold(o)) {
            a.flow.hold(a.ctx(), Parts.payload(text), o);
        } else {
            a.sending.transmit(a.ctx(), Parts.payload(text), o);
        }
    }

    @Test
    void aSenderHoldsWhatExceedsTheReceiversWindowAndPausesItsAgentUntilAnAcknowledgementOpensIt() {
        SenderState o = a.sending.sender(Parts.PEER, Parts.PEER_AT);
        for (int i = 1; i <= 6; i++) {
            send(o, "m" + i);
        }
        assertEquals(4, a.harness.downCount(), "the window's four go");
        assertEquals(2, o.held.size(), "the rest is held");
        assertTrue(a.harness.backpressured(), "and the agent paused");
        o.acked = 2;
        a.flow.credit(o, 4);
        a.flow.release(a.ctx(), o, a.sending);
        assertEquals(6, a.harness.downCount(), "two acknowledged: two more go");
        assertFalse(a.harness.backpressured(), "nothing held: the agent goes on");
    }

    @Test
    void aReceiverThatAnnouncesAShutWindowGetsNothingMoreUntilItOpensIt() {
        SenderState o = a.sending.sender(Parts.PEER, Parts.PEER_AT);
        send(o, "m1");
        o.acked = 1;
        a.flow.credit(o, 0);
        send(o, "m2");
        assertEquals(1, o.held.size(), "a window of 0 takes nothing");
        a.flow.credit(o, -3);
        a.flow.release(a.ctx(), o, a.sending);
        assertEquals(1, o.held.size(), "a negative window counts as shut");
        a.flow.credit(o, 1);
        a.flow.release(a.ctx(), o, a.sending);
        assertTrue(o.held.isEmpty());
    }

    @Test
    void pastTheHeldLimitASendIsRefusedWithFlowControl() {
        SenderState o = a.sending.sender(Parts.PEER, Parts.PEER_AT);
        for (int i = 0; i < 4 + SequenceLayer.MAX_HELD; i++) {
            send(o, "m");
        }
        SendRejectedException e = assertThrows(SendRejectedException.class, () -> send(o, "one more"));
        assertEquals("flow-control", e.reason());
    }

    @Test
    void aReceiverAnnouncesItsWholeWindowAndNoneWhileItsMailboxIsFull() {
        ReceiverState in = new ReceiverState(4);
        assertEquals(4, a.flow.windowToAnnounce(a.ctx(), in));
        assertFalse(in.closed);
        a.harness.setInboxFull(true);
        assertEquals(0, a.flow.windowToAnnounce(a.ctx(), in));
        assertTrue(in.closed, "remembered, to announce it open once the mailbox is taken down");
    }

    @Test
    void switchedOffForTheThreatTestsItHoldsNothing() {
        Parts off = new Parts(WINDOW_OF_4, false);
        SenderState o = off.sending.sender(Parts.PEER, Parts.PEER_AT);
        o.nextSeq = 100;
        assertFalse(off.flow.mustHold(o));
        off.harness.setInboxFull(true);
        assertEquals(4, off.flow.windowToAnnounce(off.ctx(), new ReceiverState(4)));
    }
}
