package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.LayerContext;
import io.concord.core.net.Address;
import io.concord.layers.frame.Frames;

import java.util.Map;

import static io.concord.layers.sequence.SequenceLayer.DATA;
import static io.concord.layers.sequence.SequenceLayer.HEADER_BYTES;
import static io.concord.layers.sequence.SequenceLayer.PROBE;
import static io.concord.layers.sequence.SequenceLayer.SKIP;

/**
 * The sending side of the sequence layer's reliability (JGroups' UNICAST3 does both sides): the
 * numbering of the frames to each receiver and the ring of those kept for retransmission, the
 * probe after a quiet spell, the answers to ACKs and NAKs, and a receiver that restarted (its new
 * session). The {@link FlowWindow} decides when a frame may go; this part sends it and tells the
 * window what the receiver acknowledged. One per agent, called on its loop.
 */
final class Retransmission {
    private static final int MAX_NAK_ENTRIES = Delivery.MAX_NAK_ENTRIES;
    private static final int OLD_STREAMS = Delivery.OLD_STREAMS;
    /** Frames above this size are not kept once acknowledged. */
    private static final int LARGE_FRAME = 1_536;

    private final SequenceLayer.Config config;
    private final boolean retransmission;
    private final FlowWindow flow;
    private final ControlFrames control;
    private final Map<Long, SenderState> outs;

    /** {@code retransmission} is off only in threat tests ({@code Defence.RETRANSMISSION}). */
    Retransmission(SequenceLayer.Config config, boolean retransmission, FlowWindow flow, ControlFrames control) {
        this.config = config;
        this.retransmission = retransmission;
        this.flow = flow;
        this.control = control;
        // A receiver with frames held for it is never forgotten: they would be lost, and the agent
        // stay paused.
        this.outs = Delivery.lru(config.maxPeers(), out -> !out.holding);
    }

    /** Receivers known, and frames kept for them: for tests of flat memory. */
    int stateSize() {
        int n = outs.size();
        for (SenderState o : outs.values()) {
            for (byte[] f : o.ring) {
                if (f != null) {
                    n++;
                }
            }
        }
        return n;
    }

    /** The state for a receiver, made on the first frame to it; its address is the frame's destination. */
    SenderState sender(long peer, Address destination) {
        SenderState o = outs.computeIfAbsent(peer, k -> new SenderState(config.retransmitBuffer()));
        o.address = destination;
        return o;
    }

    /**
     * Acknowledged frames are kept for their slot's reuse, but not large ones: a container that
     * sent a list of many pages to a hundred members held them all (at 5,000 agents over 50
     * simulated hosts, gigabytes).
     */
    private void forgetLarge(SenderState o, long from, long to) {
        for (long s = Math.max(from + 1, to - config.retransmitBuffer() + 1); s <= to; s++) {
            int slot = (int) (s % config.retransmitBuffer());
            byte[] kept = o.ring[slot];
            if (kept != null && kept.length > LARGE_FRAME && o.ringSeq[slot] == s) {
                o.ring[slot] = null;
            }
        }
    }

    void transmit(LayerContext ctx, Envelope env, SenderState o) {
        if (o.acked >= o.nextSeq - 1) {
            o.progressNs = ctx.nowNs();   // all taken so far: the receiver's silence, if any, starts now
        }
        long seq = o.nextSeq++;
        int at = env.prepend(HEADER_BYTES);
        byte[] d = env.data();
        d[at] = DATA;
        Frames.putInt(d, at + 1, control.stream());
        Frames.putLong(d, at + 5, seq);
        int slot = (int) (seq % config.retransmitBuffer());
        byte[] keep = o.ring[slot];
        if (keep == null || keep.length < Frames.HEADROOM + env.length() + 40) {
            keep = new byte[Frames.HEADROOM + env.length() + 40];
            o.ring[slot] = keep;
        }
        System.arraycopy(d, at, keep, Frames.HEADROOM, env.length());
        o.ringSeq[slot] = seq;
        o.ringLen[slot] = env.length();
        ctx.passDown(env);
        probeLater(ctx, env.peerId(), o);
    }

    /** Probes the receiver after a quiet spell, unless a probe is due already. */
    void probeLater(LayerContext ctx, long peer, SenderState o) {
        if (o.probeTimer < 0) {
            o.probeTimer = ctx.host().schedule(ctx.nowNs() + config.probeTimeoutMs() * 1_000_000L, () -> probe(ctx, peer, o));
        }
    }

    private void probe(LayerContext ctx, long peer, SenderState o) {
        o.probeTimer = -1;
        boolean shut = o.acked >= o.nextSeq - 1 && !o.held.isEmpty(); // all taken, the window shut
        if (o.acked >= o.nextSeq - 1 && !shut) {
            o.probes = 0;
            return;
        }
        long now = ctx.nowNs();
        if (o.progressNs == Long.MIN_VALUE) {
            o.progressNs = now;
        }
        if (shut) {
            // A receiver that keeps its window shut is slow, not gone, while it answers each probe;
            // one that stops answering (its mailbox was full, then it closed or was stopped) holds
            // the agent back no longer (before, the agent stayed paused for good).
            o.probes = Math.min(o.probes + 1, 4);
            if (now - Math.max(o.progressNs, o.heardNs) >= FlowWindow.SILENT_MS * 1_000_000L) {
                flow.silent(ctx, o);
            }
        } else {
            if (!o.held.isEmpty() && now - o.progressNs >= FlowWindow.SILENT_MS * 1_000_000L) {
                // Stopped or gone: the frames for it wait, the agent's other conversations go on.
                flow.silent(ctx, o);
            }
            if (++o.probes > config.maxProbes()) {
                ctx.drop(Envelope.control(peer, o.address, new byte[0], 0, 0), "unacknowledged",
                        (o.nextSeq - 1 - o.acked) + " frames to " + o.address + " were never acknowledged; is the peer gone?");
                // Still asked now and then: a peer that was only stopped answers when it goes on.
                o.probes = 4;
            }
        }
        control.send(ctx, peer, o.address, PROBE, control.stream(), o.nextSeq - 1, null, 0);
        long backoff = config.probeTimeoutMs() << Math.min(o.probes, 4);
        o.probeTimer = ctx.host().schedule(ctx.nowNs() + backoff * 1_000_000L, () -> probe(ctx, peer, o));
    }

    /**
     * False if an acknowledgement is not to be acted on: it names a session of the receiver that
     * has ended, or a new one (the receiver restarted), which is handled here.
     */
    private boolean sameSession(LayerContext ctx, long peer, SenderState out, int session, long since) {
        if (session == 0 || session == out.peerSession) {
            return true;
        }
        if (out.peerSession == 0) {
            out.peerSession = session;
            return true;
        }
        if (out.endedSessions.contains(session)) {
            return false;
        }
        out.endedSessions.add(out.peerSession);
        if (out.endedSessions.size() > OLD_STREAMS) {
            out.endedSessions.remove(out.endedSessions.iterator().next());
        }
        out.peerSession = session;
        long from = Math.min(out.nextSeq, Math.max(out.acked + 1, since));
        if (from - 1 > out.acked) {
            ctx.drop(Envelope.control(peer, out.address, new byte[0], 0, 0), "receiver-restarted", (from - 1 - out.acked)
                    + " frames sent to " + out.address + " before it restarted are not sent again (it may have had them)");
        }
        out.acked = Math.max(out.acked, from - 1);
        if (from > 1) {
            control.send(ctx, peer, out.address, SKIP, control.stream(), from, null, 0);
        }
        return false;
    }

    private void retransmit(LayerContext ctx, long peer, SenderState o, long seq) {
        if (!retransmission) {
            return;
        }
        int slot = (int) (seq % config.retransmitBuffer());
        if (seq < o.nextSeq && o.ring[slot] != null && o.ringSeq[slot] == seq) {
            ctx.passDown(Envelope.control(peer, o.address, o.ring[slot], Frames.HEADROOM, o.ringLen[slot]));
        } else if (seq < o.nextSeq) {
            long lowest = Math.max(1, o.nextSeq - config.retransmitBuffer());
            control.send(ctx, peer, o.address, SKIP, control.stream(), lowest, null, 0);
        }
    }

    /** An acknowledgement: frames up to {@code seq} taken, the receiver's session and its window. */
    void onAck(LayerContext ctx, Envelope env, long peer, int streamId, long seq, byte[] d, int o) {
        SenderState out = outs.get(peer);
        if (out != null && streamId == control.stream() && env.length() >= HEADER_BYTES + 12
                && !sameSession(ctx, peer, out, Frames.getInt(d, o + HEADER_BYTES), Frames.getLong(d, o + HEADER_BYTES + 4))) {
            return;
        }
        if (out != null && streamId == control.stream()) {
            out.heardNs = ctx.nowNs();
            if (seq >= out.acked && out.acked >= out.nextSeq - 1) {
                flow.heard(ctx, out);   // it answers with all taken: there, if slow
            }
            if (seq > out.acked) {
                long was = out.acked;
                out.acked = Math.min(seq, out.nextSeq - 1);
                forgetLarge(out, was, out.acked);
                out.progressNs = ctx.nowNs();
                flow.heard(ctx, out);
            }
            // The window of the latest acknowledgement only: one overtaken by a later one
            // (reordered, or a late copy) must not open a window the receiver shut since.
            if (env.length() >= HEADER_BYTES + 16 && seq >= out.acked) {
                flow.credit(out, Frames.getInt(d, o + HEADER_BYTES + 12));
            }
            flow.release(ctx, out, this);
            if (out.acked >= out.nextSeq - 1 && out.held.isEmpty() && out.probeTimer >= 0) {
                ctx.host().cancel(out.probeTimer);
                out.probeTimer = -1;
                out.probes = 0;
            }
        }
    }

    /** A NAK: the frames the receiver asks for again, each at most once. */
    void onNak(LayerContext ctx, Envelope env, long peer, int streamId, byte[] d, int o) {
        SenderState out = outs.get(peer);
        if (out == null || streamId != control.stream() || env.length() < HEADER_BYTES + 2) {
            return;
        }
        int n = Math.min(Frames.getShort(d, o + 13), (env.length() - HEADER_BYTES - 2) / 8);
        int tail = o + HEADER_BYTES + 2 + 8 * n;
        if (tail + 12 <= o + env.length() && !sameSession(ctx, peer, out, Frames.getInt(d, tail), Frames.getLong(d, tail + 4))) {
            return;
        }
        // At most the 64 numbers a receiver ever asks for, each once: a NAK cannot make the
        // sender repeat one frame, or send more than 64, however it is written.
        int asked = Math.min(n, MAX_NAK_ENTRIES);
        long[] wanted = new long[asked];
        int distinct = 0;
        next:
        for (int i = 0; i < asked; i++) {
            long s = Frames.getLong(d, o + 15 + 8 * i);
            for (int j = 0; j < distinct; j++) {
                if (wanted[j] == s) {
                    continue next;
                }
            }
            wanted[distinct++] = s;
            retransmit(ctx, peer, out, s);
        }
        if (n > distinct) {
            ctx.drop(env, "nak-limit", "a NAK of " + n + " numbers, " + distinct + " distinct ones answered (at most "
                    + MAX_NAK_ENTRIES + ")");
        }
    }
}
