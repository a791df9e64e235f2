package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.net.Address;
import io.concord.testkit.LayerHarness;
import io.concord.core.time.ManualClock;
import io.concord.layers.frame.Frames;

import java.nio.charset.StandardCharsets;

/**
 * One agent's parts of the sequence layer, driven alone: a {@link LayerHarness} around a probe
 * layer gives them their context (time, timers, drops, the way down and up).
 */
final class Parts {
    static final Address PEER_AT = new Address("h", 2);
    static final long PEER = 22;

    /** Hands the layer's context to the test. */
    private static final class Probe extends Layer {
        LayerContext ctx;

        @Override
        public void init(LayerContext c) {
            ctx = c;
        }
    }

    final SequenceLayer.Config config;
    final LayerHarness harness;
    final ControlFrames control;
    final FlowWindow flow;
    final Retransmission sending;
    final Delivery receiving;
    private final Probe probe = new Probe();

    Parts(SequenceLayer.Config config, boolean flowControl) {
        this.config = config;
        this.harness = LayerHarness.builder().name("a@p").clock(new ManualClock()).build(probe);
        this.control = new ControlFrames(config.reorderWindow());
        control.init(probe.ctx);
        this.flow = new FlowWindow(config.reorderWindow(), flowControl);
        this.sending = new Retransmission(config, true, flow, control);
        this.receiving = new Delivery(config, true, true, flow, control, false);
    }

    LayerContext ctx() {
        return probe.ctx;
    }

    /** A payload the agent itself sent. */
    static Envelope payload(String text) {
        byte[] b = text.getBytes(StandardCharsets.UTF_8);
        byte[] buf = new byte[Frames.HEADROOM + b.length];
        System.arraycopy(b, 0, buf, Frames.HEADROOM, b.length);
        return Envelope.control(PEER, PEER_AT, buf, Frames.HEADROOM, b.length).markSentByAgent();
    }

    /** The same as a frame a layer sends on its own (the platform's lists, a heartbeat). */
    static Envelope platformFrame(String text) {
        byte[] b = text.getBytes(StandardCharsets.UTF_8);
        byte[] buf = new byte[Frames.HEADROOM + b.length];
        System.arraycopy(b, 0, buf, Frames.HEADROOM, b.length);
        return Envelope.control(PEER, PEER_AT, buf, Frames.HEADROOM, b.length);
    }

    /** A frame of {@code kind} from the peer's stream 5 with sequence number {@code seq} and a payload. */
    static Envelope fromPeer(int kind, long seq, String text) {
        byte[] t = text.getBytes(StandardCharsets.UTF_8);
        byte[] b = new byte[SequenceLayer.HEADER_BYTES + t.length];
        b[0] = (byte) kind;
        Frames.putInt(b, 1, 5);
        Frames.putLong(b, 5, seq);
        System.arraycopy(t, 0, b, SequenceLayer.HEADER_BYTES, t.length);
        Envelope e = Envelope.incoming(PEER_AT, b, 0, b.length, 0);
        e.setPeerId(PEER);
        return e;
    }

    static String text(Envelope e) {
        return new String(e.data(), e.offset(), e.length(), StandardCharsets.UTF_8);
    }

    static int kind(Envelope e) {
        return e.data()[e.offset()];
    }

    static long seq(Envelope e) {
        return Frames.getLong(e.data(), e.offset() + 5);
    }
}
