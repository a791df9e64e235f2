package io.concord.serial;

import java.util.function.Consumer;

/**
 * One end's receiving side of the board protocol: cuts the byte stream into frames, opens them,
 * and checks their direction, sequence and age; every frame it drops is counted by its reason
 * ({@link #drops()}), the rest go to the consumer. The host's driver and the board both read
 * through one. A HELLO from the board starts the sequence count again (the board restarted); a
 * host's SYNC does the same at the board ({@link SequenceCheck}). Single-threaded.
 */
public final class FrameReceiver {
    private final FrameCodec codec;
    private final boolean fromBoard;
    private final SequenceCheck check;
    private final Drops drops = new Drops();
    private final Deframer deframer;
    private final Consumer<Frame> onFrame;
    private long nowMs;

    /**
     * @param codec     opens frames (with the pairing key, if any)
     * @param fromBoard true at the host (it takes board frames, types from 0x80), false at the board
     * @param maxAgeMs  frames older than this are stale
     * @param onFrame   told of each frame taken
     */
    public FrameReceiver(FrameCodec codec, boolean fromBoard, long maxAgeMs, Consumer<Frame> onFrame) {
        this.codec = codec;
        this.fromBoard = fromBoard;
        this.check = new SequenceCheck(maxAgeMs);
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
        if (f.type() == Frame.Type.HELLO) {
            check.reset();
        }
        String bad = check.check(f, nowMs);
        if (bad != null) {
            drops.count(bad);
            return;
        }
        onFrame.accept(f);
    }
}
