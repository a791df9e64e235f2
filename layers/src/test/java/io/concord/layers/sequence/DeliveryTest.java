package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.layers.frame.Frames;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

/** The receiving side alone: order, gaps asked for, repetitions refused, acknowledgements. */
class DeliveryTest {
    private final Parts b = new Parts(SequenceLayer.Config.defaults(), true);

    private void arrive(long seq, String text) {
        b.receiving.onData(b.ctx(), Parts.fromPeer(SequenceLayer.DATA, seq, text), Parts.PEER, 5, seq);
    }

    private List<String> delivered() {
        List<String> out = new ArrayList<>();
        Envelope e;
        while ((e = b.harness.pollUp()) != null) {
            out.add(Parts.text(e));
        }
        return out;
    }

    @Test
    void framesOutOfOrderAreDeliveredInOrderAndTheGapIsAskedForAtOnce() {
        arrive(1, "one");
        arrive(3, "three");
        Envelope nak = b.harness.pollDown();
        assertEquals(SequenceLayer.NAK, Parts.kind(nak), "a new gap: a NAK at once");
        assertEquals(1, nak.data()[nak.offset() + SequenceLayer.HEADER_BYTES + 1], "for one frame");
        assertEquals(2, Frames.getLong(nak.data(), nak.offset() + SequenceLayer.HEADER_BYTES + 2),
                "number 2");
        arrive(2, "two");
        assertEquals(List.of("one", "two", "three"), delivered());
    }

    @Test
    void aRepetitionIsDroppedAndCounted() {
        arrive(1, "one");
        arrive(1, "one again");
        arrive(3, "three");
        arrive(3, "three again");
        assertEquals(List.of("one"), delivered());
        assertEquals(2, b.harness.drops().get("repeated"), "one delivered already, one waiting already");
    }

    @Test
    void deliveriesAreAcknowledgedAfterTheDelayOrAtOnceAfterAckEvery() {
        arrive(1, "one");
        assertNull(b.harness.pollDown(), "not at once");
        b.harness.advanceMs(5);
        Envelope ack = b.harness.pollDown();
        assertEquals(SequenceLayer.ACK, Parts.kind(ack));
        assertEquals(1, Parts.seq(ack), "up to 1");
        for (long s = 2; s <= 33; s++) {
            arrive(s, "m" + s);
        }
        ack = b.harness.pollDown();
        assertEquals(SequenceLayer.ACK, Parts.kind(ack), "the 32nd delivery is acknowledged at once");
        assertEquals(33, Parts.seq(ack));
    }
}
