package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.layer.SendRejectedException;
import io.concord.core.layer.StackEvent;
import io.concord.core.layer.StackHost;
import io.concord.core.net.Address;
import io.concord.layers.defence.Defence;
import io.concord.layers.frame.Frames;

import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;

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
 */
public final class SequenceLayer extends Layer {
    public static final int HEADER_BYTES = 13;
    /** Envelope header id under which delivered data frames carry {@code long[]{peer, stream, seq}}. */
    public static final int ENVELOPE_HEADER = 2;
    /** The event a layer above fires (down) to have a refused frame sent again. */
    public static final String RESEND_REQUEST = "resend-request";

    private static final int DATA = 0;
    private static final int ACK = 1;
    private static final int NAK = 2;
    private static final int PROBE = 3;
    private static final int SKIP = 4;
    /** A frame for any agent at a port (discovery): not sequenced, not acknowledged. */
    private static final int DATAGRAM = 5;
    private static final int MAX_NAK_ENTRIES = 64;
    private static final int OLD_STREAMS = 4;

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

    private static final class Out {
        long nextSeq = 1;
        long acked;
        /** The receiver's session, from its acknowledgements; 0 until the first. */
        int peerSession;
        final Set<Integer> endedSessions = new LinkedHashSet<>();
        Address address;
        final byte[][] ring;
        final long[] ringSeq;
        final int[] ringLen;
        long probeTimer = -1;
        int probes;
        /** Frames past the acknowledged ones the receiver takes (its window); -1 until it says. */
        int credit = -1;
        /** Frames the agent sent that wait for the receiver's window to open, in order. */
        final ArrayDeque<Envelope> held = new ArrayDeque<>();
        /** Counted among the receivers that hold the agent back. */
        boolean holding;

        Out(int size) {
            ring = new byte[size][];
            ringSeq = new long[size];
            ringLen = new int[size];
        }
    }

    private static final class In {
        int stream;
        /** The first sequence number of the stream this session got, or 0. */
        long since;
        long expected = 1;
        long highest;
        final Envelope[] buffer;
        final long[] bufferSeq;
        int buffered;
        Address address;
        long nakTimer = -1;
        int nakRetries;
        int sinceAck;
        long ackTimer = -1;
        /** The last acknowledgement told the sender that this agent's mailbox was full (window 0). */
        boolean closed;
        final Map<Integer, Long> oldStreams = new LinkedHashMap<>();
        final long[] resendAllowed = new long[8];

        In(int window) {
            buffer = new Envelope[window];
            bufferSeq = new long[window];
        }
    }

    /**
     * Frames held per receiver while its window is shut; one more is refused to the sending agent
     * ({@code flow-control}). The agent is paused as soon as any is held, so only an agent that
     * sends this many in one action of a behaviour meets the limit.
     */
    public static final int MAX_HELD = 4096;

    private final Config config;
    private final boolean sequenceWindow;
    private final boolean retransmission;
    private final boolean reorderBuffer;
    private final boolean flowControl;
    private final boolean sessionProof;
    private final Map<Long, Out> outs;
    /** Receivers with frames held for them: while any, the agent is paused. */
    private int congested;
    private final Map<Long, In> ins;
    private int stream;

    public SequenceLayer(Config config) {
        this(config, Set.of());
    }

    /**
     * A sequence layer with some defences off: only for the threat tests, through
     * {@code SafetyStack.Builder.withoutDefences}, above the layers.
     */
    public SequenceLayer(Config config, Set<Defence> off) {
        this.sequenceWindow = !off.contains(Defence.SEQUENCE_WINDOW);
        this.retransmission = !off.contains(Defence.RETRANSMISSION);
        this.reorderBuffer = !off.contains(Defence.REORDER_BUFFER);
        this.flowControl = !off.contains(Defence.FLOW_CONTROL);
        this.sessionProof = !off.contains(Defence.SESSION_PROOF);
        this.config = config;
        // A receiver with frames held for it is never forgotten: they would be lost, and the agent
        // stay paused.
        this.outs = lru(config.maxPeers(), out -> !out.holding);
        this.ins = lru(config.maxPeers(), in -> true);
    }

    private static <V> Map<Long, V> lru(int max, Predicate<V> forgettable) {
        return new LinkedHashMap<>(64, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<Long, V> eldest) {
                return size() > max && forgettable.test(eldest.getValue());
            }
        };
    }

    @Override
    public String name() {
        return "sequence";
    }

    @Override
    public void init(LayerContext ctx) {
        // Unique per start of the agent, yet reproducible in a simulation (no hidden randomness).
        long mix = Frames.id(ctx.host().nodeName()) ^ (ctx.host().clock().epochMillis() * 0x9E3779B97F4A7C15L)
                ^ ctx.host().clock().nanoTime();
        stream = (int) (mix ^ (mix >>> 32));
        if (stream == 0) {
            stream = 1;
        }
    }

    /** Frames and sequence numbers held in memory, for tests of flat memory. */
    public int stateSize() {
        int n = outs.size() + ins.size();
        for (Out o : outs.values()) {
            for (byte[] f : o.ring) {
                if (f != null) {
                    n++;
                }
            }
        }
        for (In i : ins.values()) {
            n += i.buffered + i.oldStreams.size();
        }
        return n;
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
        Out o = outs.computeIfAbsent(env.peerId(), k -> new Out(config.retransmitBuffer()));
        o.address = env.destination();
        if (flowControl && (!o.held.isEmpty() || !windowOpen(o))) {
            hold(ctx, env, o);
            return;
        }
        transmit(ctx, env, o);
    }

    /**
     * Acknowledged frames are kept for their slot's reuse, but not large ones: a container that
     * sent a list of many pages to a hundred members held them all (at 5,000 agents over 50
     * simulated hosts, gigabytes).
     */
    private void forgetLarge(Out o, long from, long to) {
        for (long s = Math.max(from + 1, to - config.retransmitBuffer() + 1); s <= to; s++) {
            int slot = (int) (s % config.retransmitBuffer());
            byte[] kept = o.ring[slot];
            if (kept != null && kept.length > LARGE_FRAME && o.ringSeq[slot] == s) {
                o.ring[slot] = null;
            }
        }
    }

    /** Frames above this size are not kept once acknowledged. */
    private static final int LARGE_FRAME = 1_536;

    /** Frames this sender may have unacknowledged: the receiver's window, at most its reorder window. */
    private boolean windowOpen(Out o) {
        int window = o.credit < 0 ? config.reorderWindow() : Math.min(config.reorderWindow(), o.credit);
        return o.nextSeq - 1 - o.acked < window;
    }

    private void hold(LayerContext ctx, Envelope env, Out o) {
        if (o.held.size() >= MAX_HELD) {
            throw new SendRejectedException("flow-control", MAX_HELD + " messages to " + o.address
                    + " wait already for it to take the ones before (it is slower than this sender, or gone); "
                    + "send fewer in one action of a behaviour: the agent is paused until the receiver catches up");
        }
        env.detachData();
        o.held.add(env);
        if (!o.holding) {
            o.holding = true;
            if (congested++ == 0) {
                ctx.host().backpressure(true);
            }
        }
        if (o.probeTimer < 0) {
            // A window that opens again is announced; if that announcement is lost, a probe asks.
            long peer = env.peerId();
            o.probeTimer = ctx.host().schedule(ctx.nowNs() + config.probeTimeoutMs() * 1_000_000L, () -> probe(ctx, peer, o));
        }
    }

    /** Sends what is held for a receiver as far as its window allows. */
    private void release(LayerContext ctx, Out o) {
        while (!o.held.isEmpty() && (windowOpen(o) || !flowControl)) {
            transmit(ctx, o.held.poll(), o);
        }
        if (o.held.isEmpty() && o.holding) {
            o.holding = false;
            if (--congested == 0) {
                ctx.host().backpressure(false);
            }
        }
    }

    private void transmit(LayerContext ctx, Envelope env, Out o) {
        long seq = o.nextSeq++;
        int at = env.prepend(HEADER_BYTES);
        byte[] d = env.data();
        d[at] = DATA;
        Frames.putInt(d, at + 1, stream);
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
        if (o.probeTimer < 0) {
            long peer = env.peerId();
            o.probeTimer = ctx.host().schedule(ctx.nowNs() + config.probeTimeoutMs() * 1_000_000L, () -> probe(ctx, peer, o));
        }
    }

    private void probe(LayerContext ctx, long peer, Out o) {
        o.probeTimer = -1;
        boolean shut = o.acked >= o.nextSeq - 1 && !o.held.isEmpty(); // all taken, the window shut
        if (o.acked >= o.nextSeq - 1 && !shut) {
            o.probes = 0;
            return;
        }
        if (shut) {
            // A receiver that keeps its window shut is slow, not gone: it answers each probe.
            o.probes = Math.min(o.probes + 1, 4);
        } else if (++o.probes > config.maxProbes()) {
            ctx.drop(Envelope.control(peer, o.address, new byte[0], 0, 0), "unacknowledged",
                    (o.nextSeq - 1 - o.acked) + " frames to " + o.address + " were never acknowledged; is the peer gone?");
            o.probes = 0;
            return;
        }
        sendControl(ctx, peer, o.address, PROBE, stream, o.nextSeq - 1, null, 0);
        long backoff = config.probeTimeoutMs() << Math.min(o.probes, 4);
        o.probeTimer = ctx.host().schedule(ctx.nowNs() + backoff * 1_000_000L, () -> probe(ctx, peer, o));
    }

    /**
     * False if an acknowledgement is not to be acted on: it names a session of the receiver that
     * has ended, or a new one (the receiver restarted), which is handled here.
     */
    private boolean sameSession(LayerContext ctx, long peer, Out out, int session, long since) {
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
            sendControl(ctx, peer, out.address, SKIP, stream, from, null, 0);
        }
        return false;
    }

    private void retransmit(LayerContext ctx, long peer, Out o, long seq) {
        if (!retransmission) {
            return;
        }
        int slot = (int) (seq % config.retransmitBuffer());
        if (seq < o.nextSeq && o.ring[slot] != null && o.ringSeq[slot] == seq) {
            ctx.passDown(Envelope.control(peer, o.address, o.ring[slot], Frames.HEADROOM, o.ringLen[slot]));
        } else if (seq < o.nextSeq) {
            long lowest = Math.max(1, o.nextSeq - config.retransmitBuffer());
            sendControl(ctx, peer, o.address, SKIP, stream, lowest, null, 0);
        }
    }

    private void sendControl(LayerContext ctx, long peer, Address to, int kind, int streamId, long seq, long[] list, int n) {
        sendControl(ctx, peer, to, kind, streamId, seq, list, n, 0);
    }

    private void sendControl(LayerContext ctx, long peer, Address to, int kind, int streamId, long seq, long[] list, int n, long since) {
        sendControl(ctx, peer, to, kind, streamId, seq, list, n, since, config.reorderWindow());
    }

    private void sendControl(LayerContext ctx, long peer, Address to, int kind, int streamId, long seq, long[] list, int n, long since,
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
            case DATA -> onData(ctx, env, peer, streamId, seq);
            case DATAGRAM -> {
                if (env.header(Frames.ENVELOPE_ANY) == null) {
                    ctx.drop(env, "malformed-frame", "an unsequenced frame that was not addressed to any agent");
                    return;
                }
                env.skip(HEADER_BYTES);
                ctx.passUp(env);
            }
            case ACK -> {
                Out out = outs.get(peer);
                if (out != null && streamId == stream && env.length() >= HEADER_BYTES + 12
                        && !sameSession(ctx, peer, out, Frames.getInt(d, o + HEADER_BYTES), Frames.getLong(d, o + HEADER_BYTES + 4))) {
                    return;
                }
                if (out != null && streamId == stream) {
                    if (seq > out.acked) {
                        long was = out.acked;
                        out.acked = Math.min(seq, out.nextSeq - 1);
                        forgetLarge(out, was, out.acked);
                    }
                    // The window of the latest acknowledgement only: one overtaken by a later one
                    // (reordered, or a late copy) must not open a window the receiver shut since.
                    if (env.length() >= HEADER_BYTES + 16 && seq >= out.acked) {
                        out.credit = Math.max(0, Frames.getInt(d, o + HEADER_BYTES + 12));
                    }
                    release(ctx, out);
                    if (out.acked >= out.nextSeq - 1 && out.held.isEmpty() && out.probeTimer >= 0) {
                        ctx.host().cancel(out.probeTimer);
                        out.probeTimer = -1;
                        out.probes = 0;
                    }
                }
            }
            case NAK -> {
                Out out = outs.get(peer);
                if (out == null || streamId != stream || env.length() < HEADER_BYTES + 2) {
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
            case PROBE -> {
                In in = receiverFor(ctx, env, peer, streamId);
                if (in == null) {
                    return;
                }
                in.highest = Math.max(in.highest, seq);
                if (seq >= in.expected) {
                    sendNak(ctx, peer, in);
                }
                sendAck(ctx, peer, in);
            }
            case SKIP -> {
                In in = ins.get(peer);
                if (in != null && in.stream == streamId && seq > in.expected) {
                    skipTo(ctx, env, peer, in, seq);
                }
            }
            default -> ctx.drop(env, "malformed-frame", "unknown sequence kind " + kind);
        }
    }

    /** The receiver state for a peer's stream; a new stream means the peer restarted. */
    private In receiverFor(LayerContext ctx, Envelope env, long peer, int streamId) {
        In in = ins.get(peer);
        if (in == null) {
            in = new In(config.reorderWindow());
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

    private void reset(LayerContext ctx, In in, int streamId) {
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

    private void onData(LayerContext ctx, Envelope env, long peer, int streamId, long seq) {
        In in = receiverFor(ctx, env, peer, streamId);
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
            ctx.drop(env, "repeated", "sequence " + seq + " was delivered already");
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

    private void deliver(LayerContext ctx, Envelope env, long peer, In in, long seq) {
        env.skip(HEADER_BYTES);
        env.putHeader(ENVELOPE_HEADER, new long[]{peer, in.stream, seq});
        in.sinceAck++;
        ctx.passUp(env);
    }

    private void drain(LayerContext ctx, long peer, In in) {
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

    private void skipTo(LayerContext ctx, Envelope env, long peer, In in, long seq) {
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

    private void sendNak(LayerContext ctx, long peer, In in) {
        sendNak(ctx, peer, in, in.expected, in.highest);
    }

    /** Asks for the frames missing between two sequence numbers (within the window; at most 64). */
    private void sendNak(LayerContext ctx, long peer, In in, long from, long to) {
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
            sendControl(ctx, peer, in.address, NAK, in.stream, in.expected, missing, n, in.since);
        }
    }

    private void scheduleNak(LayerContext ctx, long peer, In in) {
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

    private void scheduleAck(LayerContext ctx, long peer, In in) {
        if (in.sinceAck >= config.ackEvery()) {
            sendAck(ctx, peer, in);
        } else if (in.ackTimer < 0) {
            in.ackTimer = ctx.host().schedule(ctx.nowNs() + config.ackDelayMs() * 1_000_000L, () -> {
                in.ackTimer = -1;
                sendAck(ctx, peer, in);
            });
        }
    }

    private void sendAck(LayerContext ctx, long peer, In in) {
        in.sinceAck = 0;
        if (in.ackTimer >= 0) {
            ctx.host().cancel(in.ackTimer);
            in.ackTimer = -1;
        }
        // The window: the reorder window while the agent keeps up with its mailbox, shut while
        // the mailbox is full; announced again when the agent has taken it down.
        in.closed = flowControl && ctx.host().inboxFull();
        sendControl(ctx, peer, in.address, ACK, in.stream, in.expected - 1, null, 0, in.since, in.closed ? 0 : config.reorderWindow());
    }

    // ---- resend requests from above ----------------------------------------------------------------

    @Override
    public void onEvent(LayerContext ctx, StackEvent event) {
        if (!event.up() && StackHost.INBOX_DRAINED.equals(event.type())) {
            for (Map.Entry<Long, In> e : ins.entrySet()) {
                if (e.getValue().closed) {
                    sendAck(ctx, e.getKey(), e.getValue());
                }
            }
            return;
        }
        if (!event.up() && RESEND_REQUEST.equals(event.type()) && event.payload() instanceof Envelope refused) {
            long[] id = refused.header(ENVELOPE_HEADER);
            In in = id == null ? null : ins.get(id[0]);
            if (in != null && in.stream == (int) id[1]) {
                allowResend(in, id[2]);
                sendControl(ctx, id[0], in.address, NAK, in.stream, in.expected, new long[]{id[2]}, 1);
            }
            return;
        }
        ctx.fireEvent(event);
    }

    private static void allowResend(In in, long seq) {
        for (int i = 0; i < in.resendAllowed.length; i++) {
            if (in.resendAllowed[i] == 0) {
                in.resendAllowed[i] = seq;
                return;
            }
        }
        in.resendAllowed[0] = seq;
    }

    private static boolean takeResendAllowance(In in, long seq) {
        for (int i = 0; i < in.resendAllowed.length; i++) {
            if (in.resendAllowed[i] == seq) {
                in.resendAllowed[i] = 0;
                return true;
            }
        }
        return false;
    }
}
