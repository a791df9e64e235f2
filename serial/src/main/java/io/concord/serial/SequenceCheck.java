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
    /** The measured drift: the offset and local time of the first frame since the reset, and of the last in order (stale or not). */
    private volatile int firstOffset;
    private volatile long firstLocalMs;
    private volatile int lastOffset;
    private volatile long lastSeenMs;

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
            firstOffset = offset;
            firstLocalMs = localMs;
            lastOffset = offset;
            lastSeenMs = localMs;
            return null;
        }
        int ahead = (f.seq() - last) & 0xFFFF;
        if (ahead == 0) {
            return "repeated";
        }
        if (ahead > 32_768) {
            return "out-of-order";
        }
        lastOffset = offset;
        lastSeenMs = localMs;
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
        firstLocalMs = 0;
        lastSeenMs = 0;
    }

    /**
     * The sender's clock drift against this end's, measured from the first frame since the reset
     * to the last one in order (stale or not): the growth of the offset over the time passed. 0.03
     * is a sender's clock 3 % slow, -0.01 one 1 % fast; NaN before a second has passed. The frames'
     * delays on the wire blur it by their jitter over the span. Any thread.
     */
    public double drift() {
        long span = driftSpanMs();
        if (span < 1_000) {
            return Double.NaN;
        }
        return (lastOffset - firstOffset) / (double) span;
    }

    /** The time the drift is measured over, in ms of this end's clock. */
    public long driftSpanMs() {
        return lastSeenMs - firstLocalMs;
    }
}
