package io.concord.serial;

/**
 * Consistent Overhead Byte Stuffing (Cheshire and Baker, 1999): a frame's bytes with no zero in
 * them, so that a zero byte can end each frame on the wire and a receiver finds the next frame
 * after any garbage. Costs at most one byte in 254, plus one.
 */
final class Cobs {
    private Cobs() {
    }

    /** The stuffed form of {@code data} (without the closing zero). */
    public static byte[] encode(byte[] data, int off, int len) {
        int codeAt = 0;
        byte[] buf = new byte[len + len / 254 + 2];
        int w = 1;
        int code = 1;
        for (int i = off; i < off + len; i++) {
            if (data[i] == 0) {
                buf[codeAt] = (byte) code;
                codeAt = w++;
                code = 1;
            } else {
                buf[w++] = data[i];
                code++;
                if (code == 0xFF && i + 1 < off + len) {
                    buf[codeAt] = (byte) code;
                    codeAt = w++;
                    code = 1;
                }
            }
        }
        buf[codeAt] = (byte) code;
        return java.util.Arrays.copyOf(buf, w);
    }

    /**
     * The original bytes of a stuffed frame (without its closing zero).
     *
     * @throws IllegalArgumentException if it holds a zero or a code points past its end
     */
    public static byte[] decode(byte[] data, int off, int len) {
        byte[] out = new byte[len];
        int w = 0;
        int i = off;
        int end = off + len;
        while (i < end) {
            int code = data[i] & 0xFF;
            if (code == 0) {
                throw new IllegalArgumentException("a zero inside a stuffed frame at byte " + (i - off));
            }
            if (i + code > end) {
                throw new IllegalArgumentException("code " + code + " at byte " + (i - off) + " points past the frame's end");
            }
            for (int k = 1; k < code; k++) {
                byte b = data[i + k];
                if (b == 0) {
                    throw new IllegalArgumentException("a zero inside a stuffed frame at byte " + (i + k - off));
                }
                out[w++] = b;
            }
            i += code;
            if (code < 0xFF && i < end) {
                out[w++] = 0;
            }
        }
        byte[] r = new byte[w];
        System.arraycopy(out, 0, r, 0, w);
        return r;
    }
}
