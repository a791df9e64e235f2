package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.LayerContext;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Predicate;

import static io.concord.layers.sequence.SequenceLayer.ACK;
import static io.concord.layers.sequence.SequenceLayer.ENVELOPE_HEADER;
import static io.concord.layers.sequence.SequenceLayer.HEADER_BYTES;
import static io.concord.layers.sequence.SequenceLayer.NAK;

/**
 * The receiving side of the sequence layer's reliability: delivery in order through the reorder
 * buffer (also the repetition window), NAKs for gaps repeated with back-off, delayed and batched
 * ACKs that carry the window the {@link FlowWindow} announces, SKIPs past what a sender no longer
 * has, the sessions of a sender that restarted, and frames a layer above refused, asked for again.
 * One per agent, called on its loop.
 */
final class Delivery {
    static final int MAX_NAK_ENTRIES = 64;
    static final int OLD_STREAMS = 4;

    private final SequenceLayer.Config config;
    private final boolean sequenceWindow;
    private final boolean reorderBuffer;
    private final FlowWindow flow;
    private final ControlFrames control;
    private final Map<Long, ReceiverState> ins;

    /** The switches are off only in threat tests ({@code Defence.SEQUENCE_WINDOW}, {@code REORDER_BUFFER}). */
    /** The stack below sends copies and remembers no tags: a recent repetition is a copy (see SequenceLayer). */
    private final boolean copiesReachIt;

    Delivery(SequenceLayer.Config config, boolean sequenceWindow, boolean reorderBuffer, FlowWindow flow, ControlFrames control,
             boolean copiesReachIt) {
        this.copiesReachIt = copiesReachIt;
        this.config = config;
        this.sequenceWindow = sequenceWindow;
        this.reorderBuffer = reorderBuffer;
        this.flow = flow;
        this.control = control;
        this.ins = lru(config.maxPeers(), in -> true);
    }

    /** A map of peers that forgets the least recently used past {@code max}, if it may. */
    static <V> Map<Long, V> lru(int max, Predicate<V> forgettable) {
        return new LinkedHashMap<>(64, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<Long, V> eldest) {
                return size() > max && forgettable.test(eldest.getValue());
            }
        };
    }

    /** Senders known, frames they sent waiting in the reorder buffers, and ended streams: for tests of flat memory. */
    int stateSize() {
        int n = ins.size();
        for (ReceiverState i : ins.values()) {
            n += i.buffered + i.oldStreams.size();
        }
        return n;
    }

    /** A probe: the sender has frames unacknowledged; answered with a NAK for a gap, and an ACK. */
    void onProbe(LayerContext ctx, Envelope env, long peer, int streamId, long seq) {
        ReceiverState in = receiverFor(ctx, env, peer, streamId);
        if (in == null) {
            return;
        }
        in.highest = Math.max(in.highest, seq);
        if (seq >= in.expected) {
            sendNak(ctx, peer, in);
        }
        sendAck(ctx, peer, in);
    }

    /** A SKIP: the sender no longer has the frames before {@code seq}. */
    void onSkip(LayerContext ctx, Envelope env, long peer, int streamId, long seq) {
        ReceiverState in = ins.get(peer);
        if (in != null && in.stream == streamId && seq > in.expected) {
            skipTo(ctx, env, peer, in, seq);
        }
    }

    /** The receiver state for a peer's stream; a new stream means the peer restarted. */
    private ReceiverState receiverFor(LayerContext ctx, Envelope env, long peer, int streamId) {
        ReceiverState in = ins.get(peer);
        if (in == null) {
            in = new ReceiverState(config.reorderWindow());
            in.stream = streamId;
            ins.put(peer, in);
        } else if (in.stream != streamId) {
            if (in.oldStreams.containsKey(streamId)) {
                ctx.drop(env, "repeated", "a frame of an earlier session of this peer");
                return null;
            }
            in.oldStreams.put(in.stream, in.expected);
            if (in.oldStreams.size() > OLD_STREAMS) {
                Integer eldest = in.oldStreams.keySet().iterator().next();
                in.oldStreams.remove(eldest);
            }
            reset(ctx, in, streamId);
        }
        in.address = env.source();
        return in;
    }

    private void reset(LayerContext ctx, ReceiverState in, int streamId) {
        in.stream = streamId;
        in.since = 0;
        in.expected = 1;
        in.highest = 0;
        Arrays.fill(in.buffer, null);
        in.buffered = 0;
        in.nakRetries = 0;
        in.sinceAck = 0;
        if (in.nakTimer >= 0) {
            ctx.host().cancel(in.nakTimer);
            in.nakTimer = -1;
        }
    }

    void onData(LayerContext ctx, Envelope env, long peer, int streamId, long seq) {
        ReceiverState in = receiverFor(ctx, env, peer, streamId);
        if (in == null) {
            return;
        }
        if (seq <= 0) {
            ctx.drop(env, "malformed-frame", "sequence number " + seq);
            return;
        }
        long before = in.highest;
        in.highest = Math.max(in.highest, seq);
        if (in.since == 0) {
            in.since = seq;
        }
        if (!sequenceWindow || !reorderBuffer && seq >= in.expected) {
            // Switched off for a threat test: whatever comes is delivered as it comes.
            deliver(ctx, env, peer, in, seq);
            in.expected = Math.max(in.expected, seq + 1);
            scheduleAck(ctx, peer, in);
            return;
        }
        if (seq < in.expected) {
            if (takeResendAllowance(in, seq)) {
                deliver(ctx, env, peer, in, seq);
                return;
            }
            if (copiesReachIt && in.expected - seq <= SequenceLayer.COPY_SPAN) {
                ctx.drop(env, "copy", "a copy of sequence " + seq + ", delivered already");
            } else {
                ctx.drop(env, "repeated", "sequence " + seq + " was delivered already");
            }
            scheduleAck(ctx, peer, in);
            return;
        }
        if (seq >= in.expected + config.reorderWindow()) {
            ctx.drop(env, "reorder-overflow", "sequence " + seq + " is beyond the reorder window ("
                    + in.expected + " + " + config.reorderWindow() + "); it will be asked for again");
            sendNak(ctx, peer, in);
            return;
        }
        int slot = (int) (seq % config.reorderWindow());
        if (seq == in.expected) {
            deliver(ctx, env, peer, in, seq);
            in.expected++;
            drain(ctx, peer, in);
        } else if (in.buffer[slot] != null) {
            ctx.drop(env, "repeated", "sequence " + seq + " is already waiting to be delivered");
            return;
        } else {
            env.detachData();
            in.buffer[slot] = env;
            in.bufferSeq[slot] = seq;
            in.buffered++;
            // Asked for at once only when a new gap opens (the numbers between the highest seen
            // and this one); a frame that arrives while an older gap is open asks for nothing
            // again: the NAK timer repeats the question. Asking for every gap at every arrival
            // had the sender repeat a window's frames once per frame of it.
            if (seq > before + 1) {
                sendNak(ctx, peer, in, Math.max(before + 1, in.expected), seq - 1);
            }
        }
        if (in.buffered > 0) {
            scheduleNak(ctx, peer, in);
        }
        scheduleAck(ctx, peer, in);
    }

    private void deliver(LayerContext ctx, Envelope env, long peer, ReceiverState in, long seq) {
        env.skip(HEADER_BYTES);
        env.putHeader(ENVELOPE_HEADER, new long[]{peer, in.stream, seq});
        in.sinceAck++;
        ctx.passUp(env);
    }

    private void drain(LayerContext ctx, long peer, ReceiverState in) {
        while (in.buffered > 0) {
            int slot = (int) (in.expected % config.reorderWindow());
            Envelope next = in.buffer[slot];
            if (next == null || in.bufferSeq[slot] != in.expected) {
                return;
            }
            in.buffer[slot] = null;
            in.buffered--;
            deliver(ctx, next, peer, in, in.expected);
            in.expected++;
        }
        in.nakRetries = 0;
    }

    private void skipTo(LayerContext ctx, Envelope env, long peer, ReceiverState in, long seq) {
        ctx.drop(env, "lost", (seq - in.expected) + " frames from " + in.address + " are no longer available "
                + "at the sender (sequence " + in.expected + " to " + (seq - 1) + ")");
        // Over the window's slots, never over the numbers skipped: a SKIP to a far sequence number
        // must cost no more than a near one (counting up to it once hung the loop).
        for (int slot = 0; slot < in.buffer.length; slot++) {
            if (in.buffer[slot] != null && in.bufferSeq[slot] < seq) {
                in.buffer[slot] = null;
                in.buffered--;
            }
        }
        in.expected = seq;
        drain(ctx, peer, in);
    }

    private void sendNak(LayerContext ctx, long peer, ReceiverState in) {
        sendNak(ctx, peer, in, in.expected, in.highest);
    }

    /** Asks for the frames missing between two sequence numbers (within the window; at most 64). */
    private void sendNak(LayerContext ctx, long peer, ReceiverState in, long from, long to) {
        long[] missing = new long[MAX_NAK_ENTRIES];
        int n = 0;
        long upTo = Math.min(to, in.expected + config.reorderWindow() - 1);
        for (long s = Math.max(from, in.expected); s <= upTo && n < MAX_NAK_ENTRIES; s++) {
            int slot = (int) (s % config.reorderWindow());
            if (in.buffer[slot] == null || in.bufferSeq[slot] != s) {
                missing[n++] = s;
            }
        }
        if (n > 0) {
            control.send(ctx, peer, in.address, NAK, in.stream, in.expected, missing, n, in.since);
        }
    }

    private void scheduleNak(LayerContext ctx, long peer, ReceiverState in) {
        if (in.nakTimer >= 0) {
            return;
        }
        long delay = config.nakRetryMs() << Math.min(in.nakRetries, 4);
        in.nakTimer = ctx.host().schedule(ctx.nowNs() + delay * 1_000_000L, () -> {
            in.nakTimer = -1;
            if (in.buffered == 0 && in.highest < in.expected) {
                return;
            }
            if (++in.nakRetries > config.maxNakRetries()) {
                long first = Long.MAX_VALUE;
                for (int i = 0; i < in.buffer.length; i++) {
                    if (in.buffer[i] != null) {
                        first = Math.min(first, in.bufferSeq[i]);
                    }
                }
                if (first != Long.MAX_VALUE) {
                    skipTo(ctx, Envelope.control(peer, in.address, new byte[0], 0, 0), peer, in, first);
                }
                in.nakRetries = 0;
                return;
            }
            sendNak(ctx, peer, in);
            scheduleNak(ctx, peer, in);
        });
    }

    private void scheduleAck(LayerContext ctx, long peer, ReceiverState in) {
        if (in.sinceAck >= config.ackEvery()) {
            sendAck(ctx, peer, in);
        } else if (in.ackTimer < 0) {
            in.ackTimer = ctx.host().schedule(ctx.nowNs() + config.ackDelayMs() * 1_000_000L, () -> {
                in.ackTimer = -1;
                sendAck(ctx, peer, in);
            });
        }
    }

    void sendAck(LayerContext ctx, long peer, ReceiverState in) {
        in.sinceAck = 0;
        if (in.ackTimer >= 0) {
            ctx.host().cancel(in.ackTimer);
            in.ackTimer = -1;
        }
        // The window: the reorder window while the agent keeps up with its mailbox, shut while
        // the mailbox is full; announced again when the agent has taken it down.
        int window = flow.windowToAnnounce(ctx, in);
        control.send(ctx, peer, in.address, ACK, in.stream, in.expected - 1, null, 0, in.since, window);
    }

    /** A layer above refused a delivered frame: the sender is asked for it again, and it is let through once. */
    void resend(LayerContext ctx, Envelope refused) {
        long[] id = refused.header(ENVELOPE_HEADER);
        ReceiverState in = id == null ? null : ins.get(id[0]);
        if (in != null && in.stream == (int) id[1]) {
            allowResend(in, id[2]);
            control.send(ctx, id[0], in.address, NAK, in.stream, in.expected, new long[]{id[2]}, 1);
        }
    }

    /** The agent took its mailbox down: a window the last acknowledgement shut is announced open. */
    void inboxDrained(LayerContext ctx) {
        for (Map.Entry<Long, ReceiverState> e : ins.entrySet()) {
            if (e.getValue().closed) {
                sendAck(ctx, e.getKey(), e.getValue());
            }
        }
    }

    private static void allowResend(ReceiverState in, long seq) {
        for (int i = 0; i < in.resendAllowed.length; i++) {
            if (in.resendAllowed[i] == 0) {
                in.resendAllowed[i] = seq;
                return;
            }
        }
        in.resendAllowed[0] = seq;
    }

    private static boolean takeResendAllowance(ReceiverState in, long seq) {
        for (int i = 0; i < in.resendAllowed.length; i++) {
            if (in.resendAllowed[i] == seq) {
                in.resendAllowed[i] = 0;
                return true;
            }
        }
        return false;
    }
}
