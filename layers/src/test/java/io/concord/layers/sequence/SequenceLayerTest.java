package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.StackEvent;
import io.concord.core.net.Address;
import io.concord.testkit.LayerHarness;
import io.concord.layers.frame.Frames;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The sequence layer alone: a sender harness and a receiver harness, frames carried by hand. */
class SequenceLayerTest {
    private static final Address A = new Address("h", 1);
    private static final Address B = new Address("h", 2);
    private static final long A_ID = 11;
    private static final long B_ID = 22;

    private final LayerHarness sender = new LayerHarness(new SequenceLayer(SequenceLayer.Config.defaults()));
    private final LayerHarness receiver = new LayerHarness(new SequenceLayer(SequenceLayer.Config.defaults()));

    private static Envelope payload(String text) {
        byte[] b = text.getBytes(StandardCharsets.UTF_8);
        byte[] buf = new byte[Frames.HEADROOM + b.length];
        System.arraycopy(b, 0, buf, Frames.HEADROOM, b.length);
        return Envelope.control(B_ID, B, buf, Frames.HEADROOM, b.length);
    }

    private static Envelope arriving(Envelope sent, Address from, long fromId) {
        byte[] wire = sent.dataCopy();
        Envelope e = Envelope.incoming(from, wire, 0, wire.length, 0);
        e.setPeerId(fromId);
        return e;
    }

    private List<Envelope> sendAll(String... texts) {
        List<Envelope> frames = new ArrayList<>();
        for (String t : texts) {
            sender.sendDown(payload(t));
            frames.add(sender.pollDown());
        }
        return frames;
    }

    private List<String> delivered() {
        List<String> out = new ArrayList<>();
        Envelope e;
        while ((e = receiver.pollUp()) != null) {
            out.add(new String(e.data(), e.offset(), e.length(), StandardCharsets.UTF_8));
        }
        return out;
    }

    private static int kind(Envelope e) {
        return e.data()[e.offset()];
    }

    /** An ack of the sender's stream up to {@code seq}, from session 7, with the given window. */
    private static Envelope ack(Envelope sentData, long seq, int window) {
        byte[] b = new byte[SequenceLayer.HEADER_BYTES + 16];
        b[0] = 1;
        System.arraycopy(sentData.data(), sentData.offset() + 1, b, 1, 4); // the sender's stream
        Frames.putLong(b, 5, seq);
        Frames.putInt(b, 13, 7);
        Frames.putLong(b, 17, 1);
        Frames.putInt(b, 25, window);
        Envelope e = Envelope.incoming(B, b, 0, b.length, 0);
        e.setPeerId(B_ID);
        return e;
    }

    @Test
    void onlyTheLatestAcknowledgementsWindowCounts() {
        List<Envelope> f = sendAll("m1", "m2", "m3");
        sender.receiveUp(ack(f.get(0), 3, 0)); // all taken, and the window shut: its mailbox is full
        sender.sendDown(payload("m4"));
        assertNull(sender.pollDown(), "held while the window is shut");
        sender.receiveUp(ack(f.get(0), 2, 256)); // an older ack, overtaken (reordered, or a late copy)
        assertNull(sender.pollDown(), "an overtaken acknowledgement opens nothing");
        sender.receiveUp(ack(f.get(0), 3, 256)); // the receiver's agent took its mailbox down
        Envelope next = sender.pollDown();
        assertEquals(0, kind(next), "the held frame goes as the window opens");
    }

    @Test
    void deliversInOrderWhateverOrderFramesArriveIn() {
        List<Envelope> f = sendAll("one", "two", "three", "four");
        receiver.receiveUp(arriving(f.get(2), A, A_ID));
        receiver.receiveUp(arriving(f.get(3), A, A_ID));
        assertEquals(List.of(), delivered(), "held until the gap is filled");
        receiver.receiveUp(arriving(f.get(0), A, A_ID));
        receiver.receiveUp(arriving(f.get(1), A, A_ID));
        assertEquals(List.of("one", "two", "three", "four"), delivered());
    }

    @Test
    void dropsRepetitionsBothDeliveredAndWaiting() {
        List<Envelope> f = sendAll("one", "two", "three");
        receiver.receiveUp(arriving(f.get(0), A, A_ID));
        receiver.receiveUp(arriving(f.get(0), A, A_ID));
        receiver.receiveUp(arriving(f.get(2), A, A_ID));
        receiver.receiveUp(arriving(f.get(2), A, A_ID));
        assertEquals(2, receiver.drops().get("repeated"));
        receiver.receiveUp(arriving(f.get(1), A, A_ID));
        assertEquals(List.of("one", "two", "three"), delivered());
    }

    @Test
    void asksAtOnceForWhatIsMissingAndTheSenderSendsItAgain() {
        List<Envelope> f = sendAll("one", "two", "three");
        receiver.receiveUp(arriving(f.get(2), A, A_ID));
        Envelope nak = receiver.pollDown();
        assertEquals(2, kind(nak), "a NAK");
        assertEquals(2, Frames.getShort(nak.data(), nak.offset() + 13), "for 1 and 2");
        sender.receiveUp(arriving(nak, B, B_ID));
        receiver.receiveUp(arriving(sender.pollDown(), A, A_ID));
        receiver.receiveUp(arriving(sender.pollDown(), A, A_ID));
        assertEquals(List.of("one", "two", "three"), delivered());
    }

    @Test
    void aNakCannotMakeTheSenderRepeatAFrameOrSendMoreThanSixtyFour() {
        List<Envelope> f = sendAll("one", "two", "three");
        receiver.receiveUp(arriving(f.get(2), A, A_ID));
        Envelope real = receiver.pollDown();
        byte[] r = real.dataCopy();
        // The same NAK, but asking 1,000 times for frame 1 (its session tail kept, so it is believed).
        int entries = 1_000;
        byte[] forged = new byte[15 + 8 * entries + 12];
        System.arraycopy(r, 0, forged, 0, 13);
        Frames.putShort(forged, 13, entries);
        for (int i = 0; i < entries; i++) {
            Frames.putLong(forged, 15 + 8 * i, 1);
        }
        System.arraycopy(r, 15 + 16, forged, 15 + 8 * entries, 12);
        Envelope e = Envelope.incoming(B, forged, 0, forged.length, 0);
        e.setPeerId(B_ID);
        sender.receiveUp(e);
        int resent = 0;
        while (sender.pollDown() != null) {
            resent++;
        }
        assertEquals(1, resent, "frame 1 once");
        assertEquals(1, sender.drops().get("nak-limit"));
    }

    @Test
    void aSenderWithoutAcknowledgementProbesAndALostLastFrameIsRecovered() {
        List<Envelope> f = sendAll("one", "two");
        receiver.receiveUp(arriving(f.get(0), A, A_ID)); // "two" is lost
        while (receiver.pollDown() != null) {
            // no acknowledgement reaches the sender
        }
        sender.advanceMs(20);
        Envelope probe = sender.pollDown();
        assertEquals(3, kind(probe), "a probe");
        receiver.receiveUp(arriving(probe, A, A_ID));
        Envelope nak = null;
        Envelope e;
        while ((e = receiver.pollDown()) != null) {
            if (kind(e) == 2) {
                nak = e;
            }
        }
        sender.receiveUp(arriving(nak, B, B_ID));
        receiver.receiveUp(arriving(sender.pollDown(), A, A_ID));
        assertEquals(List.of("one", "two"), delivered());
    }

    @Test
    void anAcknowledgementStopsTheProbes() {
        List<Envelope> f = sendAll("one");
        receiver.receiveUp(arriving(f.get(0), A, A_ID));
        receiver.advanceMs(5);
        Envelope ack = receiver.pollDown();
        assertEquals(1, kind(ack), "an ACK after the ack delay");
        sender.receiveUp(arriving(ack, B, B_ID));
        sender.advanceMs(1_000);
        assertNull(sender.pollDown(), "nothing to probe for");
    }

    @Test
    void whatTheSenderNoLongerHasIsSkippedAndCountedAsLost() {
        // With flow control a sender never has more unacknowledged than the window; without it (a
        // peer that has none) it runs past its buffer, and the receiver is told what is gone.
        skipped(java.util.EnumSet.of(io.concord.layers.defence.Defence.FLOW_CONTROL));
    }

    private void skipped(java.util.Set<io.concord.layers.defence.Defence> off) {
        SequenceLayer.Config small = new SequenceLayer.Config(4, 4, 5, 32, 20, 30, 10, 40, 16);
        LayerHarness s = new LayerHarness(new SequenceLayer(small, off));
        LayerHarness r = new LayerHarness(new SequenceLayer(small, off));
        List<Envelope> frames = new ArrayList<>();
        for (int i = 0; i < 10; i++) {
            s.sendDown(payload("m" + i));
            frames.add(s.pollDown());
        }
        r.receiveUp(arriving(frames.get(9), A, A_ID)); // beyond the window of 4
        assertEquals(1, r.drops().get("reorder-overflow"));
        Envelope nak = r.pollDown();
        s.receiveUp(arriving(nak, B, B_ID));
        Envelope skip = s.pollDown();
        assertEquals(4, kind(skip), "the first frames are gone: SKIP");
        r.receiveUp(arriving(skip, B, A_ID));
        assertEquals(1, r.drops().get("lost"));
        for (int i = 6; i < 10; i++) {
            r.receiveUp(arriving(frames.get(i), A, A_ID));
        }
        assertEquals(4, countUp(r));
    }

    @Test
    @org.junit.jupiter.api.Timeout(value = 60, threadMode = org.junit.jupiter.api.Timeout.ThreadMode.SEPARATE_THREAD)
    void aSkipToAFarSequenceNumberCostsNoMoreThanTheWindow() {
        // The hang guard above is not a timing assertion: counting up to 2^62 takes years.
        List<Envelope> frames = sendAll("m0", "m1", "m2");
        receiver.receiveUp(arriving(frames.get(0), A, A_ID));
        receiver.receiveUp(arriving(frames.get(2), A, A_ID)); // 2 waits for 1
        byte[] skip = frames.get(0).dataCopy();
        skip[0] = 4;
        Frames.putLong(skip, 5, 1L << 62);
        Envelope e = Envelope.incoming(A, skip, 0, HEADER, 0);
        e.setPeerId(A_ID);
        receiver.receiveUp(e);
        assertEquals(1, receiver.drops().get("lost"));
        assertEquals(List.of("m0"), delivered(), "what waited below the skip is gone, not delivered");
        receiver.receiveUp(arriving(frames.get(1), A, A_ID));
        assertEquals(List.of(), delivered(), "frames below the skipped-to number are old now");
    }

    private static final int HEADER = SequenceLayer.HEADER_BYTES;

    private static int countUp(LayerHarness h) {
        int n = 0;
        while (h.pollUp() != null) {
            n++;
        }
        return n;
    }

    @Test
    void aRestartedPeerStartsANewStreamAndOldFramesStayRefused() {
        List<Envelope> old = sendAll("before restart");
        receiver.receiveUp(arriving(old.get(0), A, A_ID));
        io.concord.core.time.ManualClock later = new io.concord.core.time.ManualClock();
        later.advanceMs(1); // the peer starts again a moment later: another stream
        LayerHarness restarted = new LayerHarness("harness", later, new SequenceLayer(SequenceLayer.Config.defaults()));
        restarted.sendDown(payload("after restart"));
        receiver.receiveUp(arriving(restarted.pollDown(), A, A_ID));
        assertEquals(List.of("before restart", "after restart"), delivered());
        receiver.receiveUp(arriving(old.get(0), A, A_ID));
        assertTrue(delivered().isEmpty(), "a replay from the earlier session is refused");
        assertEquals(1, receiver.drops().get("repeated"));
    }

    /** Carries every frame waiting at a harness's bottom to another, as from an address and id. */
    private static void carryAll(LayerHarness from, LayerHarness to, Address fromAddress, long fromId) {
        Envelope e;
        while ((e = from.pollDown()) != null) {
            to.receiveUp(arriving(e, fromAddress, fromId));
        }
    }

    private static List<String> texts(LayerHarness h) {
        List<String> out = new ArrayList<>();
        Envelope e;
        while ((e = h.pollUp()) != null) {
            out.add(new String(e.data(), e.offset(), e.length(), StandardCharsets.UTF_8));
        }
        return out;
    }

    @Test
    void aRestartedReceiverIsNotGivenAgainWhatItsPreviousSessionGot() {
        SequenceLayer.Config eager = new SequenceLayer.Config(256, 1024, 5, 1, 20, 30, 10, 40, 16);
        LayerHarness s = new LayerHarness(new SequenceLayer(eager));
        LayerHarness r1 = new LayerHarness(new SequenceLayer(eager));
        for (String m : List.of("m1", "m2", "m3")) {
            s.sendDown(payload(m));
        }
        carryAll(s, r1, A, A_ID);
        assertEquals(List.of("m1", "m2", "m3"), texts(r1));
        carryAll(r1, s, B, B_ID);      // its acknowledgements
        // The receiver restarts: a new session, with nothing of the old one.
        io.concord.core.time.ManualClock later = new io.concord.core.time.ManualClock();
        later.advanceMs(1);
        LayerHarness r2 = new LayerHarness("harness", later, new SequenceLayer(eager));
        s.sendDown(payload("m4"));
        carryAll(s, r2, A, A_ID);      // m4 waits: 1 to 3 are missing, the new session asks for them
        carryAll(r2, s, B, B_ID);      // the NAK names the new session: the sender skips to m4
        assertEquals(0, s.drops().get("receiver-restarted"), "all three were acknowledged: nothing given up");
        carryAll(s, r2, A, A_ID);      // the SKIP
        s.sendDown(payload("m5"));
        carryAll(s, r2, A, A_ID);
        carryAll(r2, s, B, B_ID);
        carryAll(s, r2, A, A_ID);
        assertEquals(List.of("m4", "m5"), texts(r2), "nothing the previous session got, and nothing lost since");
    }

    @Test
    void aResendRequestFromAboveLetsTheSameFrameThroughOnce() {
        List<Envelope> f = sendAll("joining");
        receiver.receiveUp(arriving(f.get(0), A, A_ID));
        Envelope refused = receiver.pollUp();
        while (receiver.pollDown() != null) {
            // drain acks
        }
        receiver.fireEvent(new StackEvent(SequenceLayer.RESEND_REQUEST, refused, false));
        Envelope nak = receiver.pollDown();
        assertEquals(2, kind(nak));
        sender.receiveUp(arriving(nak, B, B_ID));
        receiver.receiveUp(arriving(sender.pollDown(), A, A_ID));
        assertEquals(List.of("joining"), delivered(), "passed up once more");
        receiver.receiveUp(arriving(f.get(0), A, A_ID));
        assertTrue(delivered().isEmpty(), "but only once");
    }
}
