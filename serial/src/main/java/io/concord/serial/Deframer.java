package io.concord.serial;

import java.util.Arrays;
import java.util.function.Consumer;

/**
 * Cuts a byte stream into stuffed frames at each zero byte, whatever the chunks it arrives in.
 * Bytes beyond a frame's largest size are thrown away up to the next zero, counted once as
 * oversized; empty frames (two zeros in a row, a sender's way to resynchronise) are skipped.
 */
final class Deframer {
    private final byte[] buf;
    private int n;
    private boolean overflow;
    private final Consumer<byte[]> onFrame;
    private final Runnable onOversized;

    /**
     * @param maxStuffed  the largest stuffed frame
     * @param onFrame     told of each frame's stuffed bytes (without the zero)
     * @param onOversized told of each run of bytes too long to be a frame
     */
    public Deframer(int maxStuffed, Consumer<byte[]> onFrame, Runnable onOversized) {
        this.buf = new byte[maxStuffed];
        this.onFrame = onFrame;
        this.onOversized = onOversized;
    }

    /** Takes the next bytes of the stream. */
    public void feed(byte[] data, int off, int len) {
        for (int i = off; i < off + len; i++) {
            byte b = data[i];
            if (b == 0) {
                if (overflow) {
                    overflow = false;
                    onOversized.run();
                } else if (n > 0) {
                    onFrame.accept(Arrays.copyOf(buf, n));
                }
                n = 0;
            } else if (!overflow) {
                if (n == buf.length) {
                    overflow = true;
                } else {
                    buf[n++] = b;
                }
            }
        }
    }

    /** Forgets a partial frame (the port was reopened). */
    public void reset() {
        n = 0;
        overflow = false;
    }
}
