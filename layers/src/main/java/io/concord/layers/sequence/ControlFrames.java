package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.LayerContext;
import io.concord.core.net.Address;
import io.concord.layers.frame.Frames;

import static io.concord.layers.sequence.SequenceLayer.ACK;
import static io.concord.layers.sequence.SequenceLayer.HEADER_BYTES;
import static io.concord.layers.sequence.SequenceLayer.NAK;

/**
 * This agent's stream, and the control frames both sides of the sequence layer write (ACK, NAK,
 * PROBE, SKIP; see {@link SequenceLayer} for their layout). One per agent, called on its loop.
 */
final class ControlFrames {
    private final int reorderWindow;
    private int stream;

    ControlFrames(int reorderWindow) {
        this.reorderWindow = reorderWindow;
    }

    /** A new stream for this start of the agent. */
    void init(LayerContext ctx) {
        // Unique per start of the agent, yet reproducible in a simulation (no hidden randomness).
        long mix = Frames.id(ctx.host().nodeName()) ^ (ctx.host().clock().epochMillis() * 0x9E3779B97F4A7C15L)
                ^ ctx.host().clock().nanoTime();
        stream = (int) (mix ^ (mix >>> 32));
        if (stream == 0) {
            stream = 1;
        }
    }

    /** This agent's stream: the stream of the frames it numbers, and its session as a receiver. */
    int stream() {
        return stream;
    }

    void send(LayerContext ctx, long peer, Address to, int kind, int streamId, long seq, long[] list, int n) {
        send(ctx, peer, to, kind, streamId, seq, list, n, 0);
    }

    void send(LayerContext ctx, long peer, Address to, int kind, int streamId, long seq, long[] list, int n, long since) {
        send(ctx, peer, to, kind, streamId, seq, list, n, since, reorderWindow);
    }

    void send(LayerContext ctx, long peer, Address to, int kind, int streamId, long seq, long[] list, int n, long since,
                             int credit) {
        boolean acknowledging = kind == ACK || kind == NAK;
        int len = HEADER_BYTES + (kind == NAK ? 2 + 8 * n : 0) + (acknowledging ? 12 : 0) + (kind == ACK ? 4 : 0);
        byte[] b = new byte[Frames.HEADROOM + len + 40];
        int o = Frames.HEADROOM;
        b[o] = (byte) kind;
        Frames.putInt(b, o + 1, streamId);
        Frames.putLong(b, o + 5, seq);
        if (kind == NAK) {
            Frames.putShort(b, o + 13, n);
            for (int i = 0; i < n; i++) {
                Frames.putLong(b, o + 15 + 8 * i, list[i]);
            }
        }
        if (kind == ACK) {
            Frames.putInt(b, o + len - 16, stream);
            Frames.putLong(b, o + len - 12, since);
            Frames.putInt(b, o + len - 4, credit);
        } else if (acknowledging) {
            Frames.putInt(b, o + len - 12, stream);
            Frames.putLong(b, o + len - 8, since);
        }
        ctx.passDown(Envelope.control(peer, to, b, o, len));
    }
}
