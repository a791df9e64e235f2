package io.concord.serial;

/**
 * One receiver's check of its sender's sequence numbers and clock (EN 50159: repetition,
 * re-sequencing, delay). A frame is taken if its number is ahead of the last taken by 1 to 32,768
 * (modulo 65,536), and its delay is within the limit.
 *
 * <p>The delay is read against a synchronised offset: the offset of a frame is the receiver's
 * clock minus the sender's at the frame; the reference is the least offset seen, allowed to
 * grow by the stated drift tolerance ({@link #DRIFT}, 2 %) of the time since, so that a sender's
 * clock that runs slow (a 1 % slow crystal adds 10 ms of offset a second) is not taken for a
 * growing delay; a sender's clock that runs fast lowers the offset, which becomes the new
 * reference. A frame whose offset is more than the limit above the reference is stale. The
 * first frame, and a host's SYNC, start the count again.
 */
final class SequenceCheck {
    /** The clock drift tolerated between the two ends: 2 % (20,000 ppm), a resonator's or an RC oscillator's worst. */
    public static final double DRIFT = 0.02;

    private final long maxAgeMs;
    private final double drift;
    private int last = -1;
    /** The reference offset (receiver's clock - sender's clock), as a 32-bit difference (both clocks wrap at 2^32 ms). */
    private int refOffset;
    /** Milliseconds the reference may have grown by since it was set, at the drift tolerance. */
    private double slack;
    private long lastLocalMs;
    /**
     * The measured drift, from the lower envelope of the offsets (the frames least delayed on the
     * wire): the least offset of the first second since the reset, and the least of the latest
     * second's window, each with its local time. A frame held up on the wire (bytes waiting in a
     * port's buffer when it opens) raises its offset, never the envelope.
     */
    private long firstLocalMs;
    private volatile int earlyMin;
    private volatile long earlyAt;
    private long windowStart;
    private volatile int windowMin;
    private volatile long windowMinAt;

    /** @param maxAgeMs frames delayed more than this are stale; the drift tolerance is {@link #DRIFT} */
    public SequenceCheck(long maxAgeMs) {
        this(maxAgeMs, DRIFT);
    }

    /**
     * @param maxAgeMs frames delayed more than this are stale
     * @param drift    the tolerated drift between the clocks, as a fraction (0.02: 2 %)
     */
    public SequenceCheck(long maxAgeMs, double drift) {
        this.maxAgeMs = maxAgeMs;
        this.drift = drift;
    }

    /**
     * Null if the frame is taken (and becomes the last), else the reason: repeated,
     * out-of-order, stale.
     */
    public String check(Frame f, long localMs) {
        int offset = (int) (localMs - f.timeMs());
        if ((f.flags() & Frame.SYNC) != 0 || last < 0) {
            last = f.seq();
            refOffset = offset;
            slack = 0;
            lastLocalMs = localMs;
            firstLocalMs = localMs;
            earlyMin = offset;
            earlyAt = localMs;
            windowStart = localMs;
            windowMin = offset;
            windowMinAt = localMs;
            return null;
        }
        int ahead = (f.seq() - last) & 0xFFFF;
        if (ahead == 0) {
            return "repeated";
        }
        if (ahead > 32_768) {
            return "out-of-order";
        }
        measure(offset, localMs);
        long dt = localMs - lastLocalMs;
        if (dt > 0) {
            slack += drift * dt;
            lastLocalMs = localMs;
        }
        double delay = (offset - refOffset) - slack;
        if (delay < 0) {
            refOffset = offset;
            slack = 0;
            delay = 0;
        }
        if (delay > maxAgeMs) {
            return "stale";
        }
        last = f.seq();
        return null;
    }

    /** Starts the count again (the link was reopened, or the board restarted). */
    public void reset() {
        last = -1;
        refOffset = 0;
        slack = 0;
        earlyAt = 0;
        windowMinAt = 0;
    }

    /** Keeps the offsets' lower envelope: the first second's least, and the latest window's least (stale or not). */
    private void measure(int offset, long localMs) {
        if (localMs - firstLocalMs < 1_000) {
            if (offset - earlyMin < 0) {
                earlyMin = offset;
                earlyAt = localMs;
                }
        }
        if (localMs - windowStart >= 1_000) {
            windowStart = localMs;
            windowMin = offset;
            windowMinAt = localMs;
        } else if (offset - windowMin < 0) {
            windowMin = offset;
            windowMinAt = localMs;
        }
    }

    /**
     * The sender's clock drift against this end's, measured since the reset on the offsets' lower
     * envelope: the growth from the least offset of the first second to the least of the latest
     * second (frames in order, stale or not), over the time between them. 0.03 is a sender's clock
     * 3 % slow, -0.01 one 1 % fast; NaN before a second separates them. The wire's jitter blurs it
     * by its least delay only. Any thread.
     */
    public double drift() {
        long span = driftSpanMs();
        if (span < 1_000) {
            return Double.NaN;
        }
        return (windowMin - earlyMin) / (double) span;
    }

    /** The time the drift is measured over, in ms of this end's clock. */
    public long driftSpanMs() {
        return windowMinAt - earlyAt;
    }
}
