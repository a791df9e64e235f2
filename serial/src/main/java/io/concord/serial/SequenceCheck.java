package io.concord.serial;

/**
 * One receiver's check of its sender's sequence numbers and clock (EN 50159: repetition,
 * re-sequencing, delay). A frame is taken if its number is ahead of the last taken by 1 to 32,768
 * (modulo 65,536), and its age is within the limit: the age is how much later, on the receiver's
 * clock, it arrives than the least delayed frame so far did relative to the sender's clock. The
 * first frame, and a host's SYNC, start the count again.
 */
public final class SequenceCheck {
    private final long maxAgeMs;
    private int last = -1;
    /** The least (receiver's clock - sender's clock) seen, as a 32-bit difference (both clocks wrap at 2^32 ms). */
    private int minOffset;

    /** @param maxAgeMs frames older than this are stale */
    public SequenceCheck(long maxAgeMs) {
        this.maxAgeMs = maxAgeMs;
    }

    /**
     * Null if the frame is taken (and becomes the last), else the reason: repeated,
     * out-of-order, stale.
     */
    public String check(Frame f, long localMs) {
        int offset = (int) (localMs - f.timeMs());
        if ((f.flags() & Frame.SYNC) != 0 || last < 0) {
            last = f.seq();
            minOffset = offset;
            return null;
        }
        int ahead = (f.seq() - last) & 0xFFFF;
        if (ahead == 0) {
            return "repeated";
        }
        if (ahead > 32_768) {
            return "out-of-order";
        }
        if (offset - minOffset < 0) {
            minOffset = offset;
        }
        if (offset - minOffset > maxAgeMs) {
            return "stale";
        }
        last = f.seq();
        return null;
    }

    /** Starts the count again (the link was reopened). */
    public void reset() {
        last = -1;
        minOffset = 0;
    }
}
