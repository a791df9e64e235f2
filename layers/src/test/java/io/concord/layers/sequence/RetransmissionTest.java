package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.layers.frame.Frames;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

/** The sending side alone: numbering, what a NAK brings back, probes, SKIP past what is gone. */
class RetransmissionTest {
    private static final SequenceLayer.Config SMALL = new SequenceLayer.Config(4, 4, 5, 32, 20, 3, 10, 40, 64);
    private final Parts a = new Parts(SMALL, true);
    private final SenderState o = a.sending.sender(Parts.PEER, Parts.PEER_AT);

    private Envelope send(String text) {
        a.sending.transmit(a.ctx(), Parts.payload(text), o);
        return a.harness.pollDown();
    }

    /** A NAK from the peer of this agent's stream, asking for the numbers given. */
    private void nak(long... seqs) {
        byte[] b = new byte[SequenceLayer.HEADER_BYTES + 2 + 8 * seqs.length + 12];
        b[0] = (byte) SequenceLayer.NAK;
        Frames.putInt(b, 1, a.control.stream());
        Frames.putShort(b, 13, seqs.length);
        for (int i = 0; i < seqs.length; i++) {
            Frames.putLong(b, 15 + 8 * i, seqs[i]);
        }
        Envelope e = Envelope.incoming(Parts.PEER_AT, b, 0, b.length, 0);
        e.setPeerId(Parts.PEER);
        a.sending.onNak(a.ctx(), e, Parts.PEER, a.control.stream(), b, 0);
    }

    @Test
    void framesAreNumberedFromOneAndANakBringsBackTheFrameKeptAsItWas() {
        Envelope first = send("one");
        send("two");
        assertEquals(1, Parts.seq(first));
        nak(1);
        Envelope again = a.harness.pollDown();
        assertEquals(SequenceLayer.DATA, Parts.kind(again));
        assertEquals(1, Parts.seq(again));
        assertEquals("one", new String(again.data(), again.offset() + SequenceLayer.HEADER_BYTES,
                again.length() - SequenceLayer.HEADER_BYTES, StandardCharsets.UTF_8));
        nak(1, 1, 1);
        assertEquals(1, Parts.seq(a.harness.pollDown()));
        assertNull(a.harness.pollDown(), "a number asked for three times in one NAK is sent once");
    }

    @Test
    void aFrameNoLongerKeptIsSkippedPast() {
        for (int i = 1; i <= 6; i++) {
            send("m" + i);
        }
        nak(1);
        Envelope skip = a.harness.pollDown();
        assertEquals(SequenceLayer.SKIP, Parts.kind(skip), "the ring holds 4: 1 is gone");
        assertEquals(3, Parts.seq(skip), "skip to the oldest still kept");
    }

    @Test
    void unacknowledgedFramesAreProbedForWithBackOffCountedAfterMaxProbesAndStillAskedNowAndThen() {
        send("one");
        a.harness.advanceMs(20);
        Envelope probe = a.harness.pollDown();
        assertEquals(SequenceLayer.PROBE, Parts.kind(probe));
        assertEquals(1, Parts.seq(probe), "the last number sent");
        a.harness.advanceMs(40);
        assertEquals(SequenceLayer.PROBE, Parts.kind(a.harness.pollDown()), "again after twice as long");
        a.harness.advanceMs(80);
        a.harness.pollDown();
        a.harness.advanceMs(160);
        assertEquals(1, a.harness.drops().get("unacknowledged"), "three probes unanswered: counted, said once");
        // Then asked now and then, at the longest interval: a peer that was only stopped (SIGSTOP,
        // a shut laptop) answers when it goes on, and what waits for it flows again.
        assertEquals(SequenceLayer.PROBE, Parts.kind(a.harness.pollDown()), "still asked after it was given up on");
        a.harness.advanceMs(160);
        assertNull(a.harness.pollDown(), "not before the longest interval");
        a.harness.advanceMs(160);
        assertEquals(SequenceLayer.PROBE, Parts.kind(a.harness.pollDown()), "at the longest interval");
    }
}
