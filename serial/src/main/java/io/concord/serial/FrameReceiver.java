package io.concord.serial;

import java.util.function.Consumer;

/**
 * One end's receiving side of the board protocol: cuts the byte stream into frames, opens them,
 * and checks their direction, sequence and age; every frame it drops is counted by its reason
 * ({@link #drops()}), the rest go to the consumer. The host's driver and the board both read
 * through one. At the host, a STATE or HELLO with a newer boot number starts the sequence count
 * again (the board restarted: its numbers start from 0), and one with an older boot number is
 * dropped ({@code old-boot}: a frame of the board's previous life, replayed or late); a host's
 * SYNC starts the count again at the board ({@link SequenceCheck}). Single-threaded.
 */
final class FrameReceiver {
    /** Board frames older than this are stale at the host. */
    static final long BOARD_FRAME_MAX_AGE_MS = 500;
    private final FrameCodec codec;
    private final boolean fromBoard;
    private final SequenceCheck check;
    private final Drops drops;
    private final Deframer deframer;
    private final Consumer<Frame> onFrame;
    private long nowMs;
    private long boot = -1;

    /**
     * @param codec     opens frames (with the pairing key, if any)
     * @param fromBoard true at the host (it takes board frames, types from 0x80), false at the board
     * @param maxAgeMs  frames older than this are stale
     * @param onFrame   told of each frame taken
     */
    public FrameReceiver(FrameCodec codec, boolean fromBoard, long maxAgeMs, Consumer<Frame> onFrame) {
        this(codec, fromBoard, maxAgeMs, onFrame, new Drops());
    }

    /** A receiver that counts its drops on {@code drops} (a board that restarts keeps counting). */
    public FrameReceiver(FrameCodec codec, boolean fromBoard, long maxAgeMs, Consumer<Frame> onFrame, Drops drops) {
        this(codec, fromBoard, new SequenceCheck(maxAgeMs), onFrame, drops);
    }

    /**
     * A receiver with its own sequence and delay check: a test's (a check that tolerates no clock
     * drift shows what the drift tolerance stands against).
     */
    public FrameReceiver(FrameCodec codec, boolean fromBoard, SequenceCheck check, Consumer<Frame> onFrame, Drops drops) {
        this.drops = drops;
        this.codec = codec;
        this.fromBoard = fromBoard;
        this.check = check;
        this.onFrame = onFrame;
        this.deframer = new Deframer(FrameCodec.MAX_FRAME * 2, this::onStuffed, () -> drops.count("oversized"));
    }

    /** The next bytes of the stream, in any chunks, arrived at {@code nowMs} on this end's clock. */
    public void feed(byte[] b, int off, int len, long nowMs) {
        this.nowMs = nowMs;
        deframer.feed(b, off, len);
    }

    /** Forgets a partial frame and the sequence count (the port was opened again). */
    public void reset() {
        deframer.reset();
        check.reset();
    }

    /** The sender's clock drift as measured since the count started again ({@link SequenceCheck#drift()}). Any thread. */
    public double drift() {
        return check.drift();
    }

    /** The time the drift was measured over, in ms of this end's clock. Any thread. */
    public long driftSpanMs() {
        return check.driftSpanMs();
    }

    /** The board's boot number of the last STATE or HELLO taken, or -1 (at the host). */
    public long boot() {
        return boot;
    }

    /** Frames dropped, by reason; the consumer may count its own (malformed, unknown-type) here too. */
    public Drops drops() {
        return drops;
    }

    private void onStuffed(byte[] stuffed) {
        Frame f;
        try {
            f = codec.decode(stuffed, 0, stuffed.length);
        } catch (FrameException e) {
            drops.count(e.reason());
            return;
        }
        if ((f.type() >= 0x80) != fromBoard) {
            drops.count("wrong-direction");
            return;
        }
        if ((f.flags() & Frame.SYNC) != 0 && (fromBoard || f.type() != Frame.Type.PING)) {
            // Only the host starts sessions, and only with a PING (which disarms): a SYNC skips the
            // sequence and delay checks, so it never comes on a command.
            drops.count("malformed");
            return;
        }
        if (fromBoard) {
            long b = f.type() == Frame.Type.HELLO && BoardProtocol.version(f) != BoardProtocol.VERSION ? -1 : BoardProtocol.boot(f);
            if (b >= 0 && b != boot) {
                if (boot >= 0 && (int) (b - boot) < 0) {
                    drops.count("old-boot");
                    return;
                }
                boot = b;
                check.reset();
            }
        }
        String bad = check.check(f, nowMs);
        if (bad != null) {
            drops.count(bad);
            return;
        }
        onFrame.accept(f);
    }
}
