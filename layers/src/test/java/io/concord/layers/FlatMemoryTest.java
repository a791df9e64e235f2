package io.concord.layers;

import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;
import io.concord.testkit.LayerHarness;
import io.concord.layers.frame.Frames;
import io.concord.layers.sequence.SequenceLayer;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The repetition filter's memory stays flat: two million messages (and a repeat of each) from a
 * hundred peers leave its state bounded by its window, not by the traffic (the dissertation's
 * filter kept every message and decayed after about two million).
 */
class FlatMemoryTest {
    private static Envelope data(long peer, int stream, long seq) {
        byte[] b = new byte[SequenceLayer.HEADER_BYTES + 8];
        b[0] = 0;
        Frames.putInt(b, 1, stream);
        Frames.putLong(b, 5, seq);
        Envelope e = Envelope.incoming(new Address("peer", (int) peer), b, 0, b.length, 0);
        e.setPeerId(peer);
        return e;
    }

    @Test
    void twoMillionMessagesLeaveTheFilterStateBounded() {
        SequenceLayer.Config config = SequenceLayer.Config.defaults();
        SequenceLayer seq = new SequenceLayer(config);
        LayerHarness h = new LayerHarness(seq);
        int peers = 100;
        long total = 2_000_000;
        int maxState = 0;
        long delivered = 0;
        for (long i = 0; i < total; i++) {
            long peer = 1 + (i % peers);
            long n = 1 + i / peers;
            h.receiveUp(data(peer, 7, n));
            h.receiveUp(data(peer, 7, n)); // its repetition
            if (i % 10_000 == 0) {
                maxState = Math.max(maxState, seq.stateSize());
                while (h.pollDown() != null) {
                    // acknowledgements, not kept
                }
            }
            while (h.pollUp() != null) {
                delivered++;
            }
        }
        assertEquals(total, delivered, "each message delivered once");
        assertEquals(total, h.drops().get("repeated"), "each repetition dropped");
        assertTrue(maxState <= peers * 2 + peers * config.reorderWindow(), "filter state stayed bounded: " + maxState);
        assertTrue(seq.stateSize() <= peers * 2, "no frames held once all arrived: " + seq.stateSize());
    }
}
