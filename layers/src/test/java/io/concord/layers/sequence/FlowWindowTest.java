package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.SendRejectedException;
import io.concord.layers.frame.Frames;
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
            a.sending.probeLater(a.ctx(), Parts.PEER, o);
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

    /**
     * The receiver's answer to a probe, as its sequence layer sends it: everything up to
     * {@code seq} taken, its session, and the window it announces.
     */
    private void ack(long seq, int window) {
        byte[] b = new byte[SequenceLayer.HEADER_BYTES + 16];
        b[0] = (byte) SequenceLayer.ACK;
        Frames.putInt(b, 1, a.control.stream());
        Frames.putLong(b, 5, seq);
        Frames.putInt(b, SequenceLayer.HEADER_BYTES, 77);
        Frames.putInt(b, SequenceLayer.HEADER_BYTES + 12, window);
        Envelope e = Envelope.incoming(Parts.PEER_AT, b, 0, b.length, 0);
        e.setPeerId(Parts.PEER);
        a.sending.onAck(a.ctx(), e, Parts.PEER, a.control.stream(), seq, b, 0);
    }

    /** A receiver whose mailbox is full has taken all it was sent and shut its window: the next frame waits for it. */
    private SenderState shutWithAFrameHeld() {
        SenderState o = a.sending.sender(Parts.PEER, Parts.PEER_AT);
        send(o, "m1");
        ack(1, 0);
        send(o, "m2");
        assertEquals(1, o.held.size());
        assertTrue(a.harness.backpressured(), "a shut window holds the agent back");
        return o;
    }

    @Test
    void aReceiverThatKeepsItsWindowShutAndAnswersEachProbeIsSlowNotGoneAndHoldsTheAgentBack() {
        SenderState o = shutWithAFrameHeld();
        for (int i = 0; i < 100; i++) {
            a.harness.advanceMs(50);
            ack(1, 0);   // the receiver answers the probe: still there, its window still shut
        }
        assertTrue(a.harness.backpressured(), "5 s of answers with a shut window: the agent waits for its receiver");
        assertEquals(1, o.held.size());
        ack(1, 4);
        assertFalse(a.harness.backpressured(), "the window opens: the frame goes and the agent goes on");
        assertTrue(o.held.isEmpty());
    }

    @Test
    void aReceiverThatShutItsWindowAndThenFellSilentNoLongerHoldsTheAgentBack() {
        // The console's mailbox filled, then the console closed (or was stopped): before, the agent
        // it sniffed stayed paused for good, and so did every conversation of that agent.
        SenderState o = shutWithAFrameHeld();
        a.harness.advanceMs(FlowWindow.SILENT_MS + 400);
        assertFalse(a.harness.backpressured(), "silent for longer than " + FlowWindow.SILENT_MS + " ms: the agent goes on");
        assertEquals(1, o.held.size(), "what waits for the receiver still waits");
        ack(1, 0);
        assertTrue(a.harness.backpressured(), "it answers again, its window shut: slow, not gone, it holds the agent back again");
        ack(1, 4);
        assertFalse(a.harness.backpressured());
        assertTrue(o.held.isEmpty());
    }

    @Test
    void whatTheLayersSendOnTheirOwnWaitsInOrderButPausesNobody() {
        // A member whose mailbox is full shuts its window to every sender: the container's lists
        // and heartbeats to it wait, but the container's own agent goes on (before, it was paused,
        // and with it every conversation it had).
        SenderState o = a.sending.sender(Parts.PEER, Parts.PEER_AT);
        send(o, "m1");
        ack(1, 0);
        for (int i = 0; i < 3; i++) {
            a.flow.hold(a.ctx(), Parts.platformFrame("list " + i), o);
        }
        assertFalse(a.harness.backpressured(), "the platform's frames pause nobody");
        send(o, "the agent's own");
        assertTrue(a.harness.backpressured(), "the agent's own message behind them pauses it");
        assertEquals(4, o.held.size());
        ack(1, 2);
        assertTrue(a.harness.backpressured(), "two of the platform's go; the agent's still waits");
        ack(3, 4);
        assertFalse(a.harness.backpressured(), "its own has gone: the agent goes on");
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
