package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.SendRejectedException;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.layer.StackEvent;
import io.concord.core.layer.StackHost;
import io.concord.layers.defence.Defence;
import io.concord.layers.frame.Frames;

import java.util.Set;

/**
 * Sequence numbers per sender and receiver: against repetition, deletion and resequencing.
 *
 * <p>Each agent numbers the data frames it sends to each peer 1, 2, 3... within a stream (a
 * random id per start of the agent). The receiver delivers them in order. A frame below the next
 * expected number, or already held, is a repetition and is dropped ({@code repeated}). A frame
 * ahead of it waits in a reorder buffer of fixed size, which is also the repetition window, so
 * memory stays flat however many frames pass, and the receiver asks at once for what is missing
 * (NAK). The sender keeps its last frames for retransmission; after a quiet spell with frames
 * unacknowledged it probes, so a lost last frame is noticed too. A frame the sender no longer has
 * is skipped (SKIP), counted as {@code lost}.
 *
 * <p>Header: kind u8 (0 data, 1 ack, 2 nak, 3 probe, 4 skip), stream u32, sequence u64. A NAK
 * carries a u16 count and that many u64 sequence numbers. An ACK and a NAK end with the
 * receiver's own session (its stream id, new at every start: u32) and the first sequence number
 * this session of the receiver got of the stream (u64, 0 if none yet).
 *
 * <p>A restarted receiver: its acknowledgements name a new session. The sender then sends again
 * nothing the previous session acknowledged or could have got, only what the new one asks for
 * from the first frame it got on: it skips (SKIP) to after both, counting what it gives up as
 * {@code receiver-restarted}, and ignores late acknowledgements of the session that ended. So a
 * receiver that restarts is never given again what it delivered before.
 *
 * <p>The layer is one layer of the stack, and its parts do the work, as JGroups splits UNICAST3
 * and UFC: reliability, in {@link Retransmission} on the sending side (numbers, the frames kept,
 * probes, the answers to ACK and NAK) and {@link Delivery} on the receiving side (the reorder
 * buffer, NAK, ACK, SKIP, sessions), with the {@link ControlFrames} both write; and the
 * {@link FlowWindow} (the receiver's window, the frames held, the agent paused). This class reads
 * the header and hands each kind to its part.
 */
public final class SequenceLayer extends Layer {
    public static final int HEADER_BYTES = 13;
    /** Envelope header id under which delivered data frames carry {@code long[]{peer, stream, seq}}. */
    public static final int ENVELOPE_HEADER = 2;
    /** The event a layer above fires (down) to have a refused frame sent again. */
    public static final String RESEND_REQUEST = "resend-request";

    static final int DATA = 0;
    static final int ACK = 1;
    static final int NAK = 2;
    static final int PROBE = 3;
    static final int SKIP = 4;
    /** A frame for any agent at a port (discovery): not sequenced, not acknowledged. */
    private static final int DATAGRAM = 5;

    /**
     * @param reorderWindow    frames held per peer ahead of the next expected one
     * @param retransmitBuffer frames kept per peer for retransmission
     * @param ackDelayMs       how long a receiver may wait before acknowledging
     * @param ackEvery         acknowledge at once after this many deliveries
     * @param probeTimeoutMs   quiet time before a sender probes for acknowledgement
     * @param maxProbes        probes before a sender gives up on a quiet peer
     * @param nakRetryMs       first interval between repeated NAKs for the same gap
     * @param maxNakRetries    NAKs for a gap before the receiver skips it
     * @param maxPeers         peers remembered on each side (least recently used forgotten)
     */
    public record Config(int reorderWindow, int retransmitBuffer, long ackDelayMs, int ackEvery, long probeTimeoutMs,
                         int maxProbes, long nakRetryMs, int maxNakRetries, int maxPeers) {
        public Config {
            if (reorderWindow < 2 || retransmitBuffer < reorderWindow || ackDelayMs < 0 || ackEvery < 1
                    || probeTimeoutMs <= 0 || maxProbes < 1 || nakRetryMs <= 0 || maxNakRetries < 1 || maxPeers < 1) {
                throw new IllegalArgumentException("sequence settings out of range: " + this
                        + " (the retransmit buffer must hold at least the reorder window)");
            }
        }

        /** The defaults: 256 frames of window, 1024 kept, ack within 5 ms, probe after 20 ms. */
        public static Config defaults() {
            return new Config(256, 1024, 5, 32, 20, 30, 10, 40, 4096);
        }
    }

    /**
     * Frames held per receiver while its window is shut; one more is refused to the sending agent
     * ({@code flow-control}). The agent is paused as soon as any is held, so only an agent that
     * sends this many in one action of a behaviour meets the limit.
     */
    public static final int MAX_HELD = 4096;
    /** How far behind the next expected number a copy of a frame may arrive (the security layer's tag memory is as long). */
    public static final int COPY_SPAN = 64;

    private final boolean sessionProof;
    private final ControlFrames control;
    private final FlowWindow flow;
    private final Retransmission sending;
    private final Delivery receiving;

    public SequenceLayer(Config config) {
        this(config, Set.of());
    }

    /**
     * A sequence layer with some defences off: only for the threat tests, through
     * {@code SafetyStack.Builder.withoutDefences}, above the layers.
     */
    public SequenceLayer(Config config, Set<Defence> off) {
        this(config, off, false);
    }

    /**
     * ... and {@code copiesReachIt}: the layers below send each frame more than once and keep no
     * memory of tags (the closed profile), so the second copy of a frame is first seen here; it is
     * then counted as a {@code copy}, as the security layer counts it where it can (a copy sent on
     * purpose is not news), and only a frame older than the last {@value #COPY_SPAN} as {@code repeated}.
     */
    public SequenceLayer(Config config, Set<Defence> off, boolean copiesReachIt) {
        this.sessionProof = !off.contains(Defence.SESSION_PROOF);
        this.control = new ControlFrames(config.reorderWindow());
        this.flow = new FlowWindow(config.reorderWindow(), !off.contains(Defence.FLOW_CONTROL));
        this.sending = new Retransmission(config, !off.contains(Defence.RETRANSMISSION), flow, control);
        this.receiving = new Delivery(config, !off.contains(Defence.SEQUENCE_WINDOW), !off.contains(Defence.REORDER_BUFFER), flow,
                control, copiesReachIt);
    }

    @Override
    public String name() {
        return "sequence";
    }

    @Override
    public void init(LayerContext ctx) {
        control.init(ctx);
    }

    /** Frames and sequence numbers held in memory, for tests of flat memory. */
    public int stateSize() {
        return sending.stateSize() + receiving.stateSize();
    }

    // ---- sending ---------------------------------------------------------------------------------

    @Override
    public void onDown(LayerContext ctx, Envelope env) {
        if (env.peerId() == Frames.ANY) {
            int at = env.prepend(HEADER_BYTES);
            byte[] d = env.data();
            d[at] = DATAGRAM;
            Frames.putInt(d, at + 1, 0);
            Frames.putLong(d, at + 5, 0);
            ctx.passDown(env);
            return;
        }
        SenderState o = sending.sender(env.peerId(), env.destination());
        if (flow.mustHold(o)) {
            if (env.isReport()) {
                // An observer behind on its events (slow, stopped, gone): refused, never held, so
                // that the observed agent's own conversations go on (the observer counts it missed).
                throw new SendRejectedException("receiver-behind", "an event for " + o.address
                        + ", which has not taken the ones before (its window is full): not sent");
            }
            flow.hold(ctx, env, o);
            // A window that opens again is announced; if that announcement is lost, a probe asks.
            sending.probeLater(ctx, env.peerId(), o);
            return;
        }
        sending.transmit(ctx, env, o);
    }

    // ---- receiving -------------------------------------------------------------------------------

    @Override
    public void onUp(LayerContext ctx, Envelope env) {
        if (env.length() < HEADER_BYTES) {
            ctx.drop(env, "malformed-frame", "no sequence header");
            return;
        }
        byte[] d = env.data();
        int o = env.offset();
        int kind = d[o];
        int streamId = Frames.getInt(d, o + 1);
        long seq = Frames.getLong(d, o + 5);
        long peer = env.peerId();
        if (sessionProof && kind != DATAGRAM && env.header(Frames.ENVELOPE_ANY) != null) {
            // Sealed with the platform key alone: any key holder can write it in any agent's name.
            // Only a frame sealed to this agent (under class 7, with the pair key of a signed
            // handshake) may start, continue or end a peer's stream: else one forged frame with a
            // new stream id would make the real frames of the peer look like an earlier session's.
            ctx.drop(env, "unauthenticated", "a sequenced frame (kind " + kind + ") addressed to any agent, in the name of "
                    + Long.toHexString(peer) + ": only frames sealed to this agent carry a peer's stream");
            return;
        }
        switch (kind) {
            case DATA -> receiving.onData(ctx, env, peer, streamId, seq);
            case DATAGRAM -> {
                if (env.header(Frames.ENVELOPE_ANY) == null) {
                    ctx.drop(env, "malformed-frame", "an unsequenced frame that was not addressed to any agent");
                    return;
                }
                env.skip(HEADER_BYTES);
                ctx.passUp(env);
            }
            case ACK -> sending.onAck(ctx, env, peer, streamId, seq, d, o);
            case NAK -> sending.onNak(ctx, env, peer, streamId, d, o);
            case PROBE -> receiving.onProbe(ctx, env, peer, streamId, seq);
            case SKIP -> receiving.onSkip(ctx, env, peer, streamId, seq);
            default -> ctx.drop(env, "malformed-frame", "unknown sequence kind " + kind);
        }
    }

    // ---- resend requests from above ----------------------------------------------------------------

    @Override
    public void onEvent(LayerContext ctx, StackEvent event) {
        if (!event.up() && StackHost.INBOX_DRAINED.equals(event.type())) {
            receiving.inboxDrained(ctx);
            return;
        }
        if (!event.up() && RESEND_REQUEST.equals(event.type()) && event.payload() instanceof Envelope refused) {
            receiving.resend(ctx, refused);
            return;
        }
        ctx.fireEvent(event);
    }
}
