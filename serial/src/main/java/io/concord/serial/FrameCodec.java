package io.concord.serial;

import java.security.GeneralSecurityException;
import java.util.Arrays;
import java.util.zip.CRC32C;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * Frames to bytes on the wire and back (docs/chair-protocol.md): an 8-byte header (type, flags,
 * sequence, time), the body, an optional 8-byte MAC (HMAC-SHA256 with the pairing key, first 8
 * bytes, over header and body), and a CRC-32C of all of it; stuffed with COBS and closed by a zero
 * byte. With a key, every frame must carry a valid MAC; without one, a frame carrying a MAC is
 * refused (the two ends are not paired alike).
 */
public final class FrameCodec {
    /** Header bytes: type, flags, sequence (2), time (4). */
    public static final int HEADER = 8;
    /** MAC bytes. */
    public static final int MAC_BYTES = 8;
    /** Largest frame before stuffing, header to CRC. */
    public static final int MAX_FRAME = 512;

    private final byte[] key;
    private final Mac mac;

    /** A codec without a MAC. */
    public FrameCodec() {
        this(null);
    }

    /** A codec that signs and checks every frame with the pairing key (16 bytes or more), or none if null. */
    public FrameCodec(byte[] key) {
        if (key != null && key.length < 16) {
            throw new IllegalArgumentException("a pairing key needs at least 16 bytes, got " + key.length);
        }
        this.key = key == null ? null : key.clone();
        try {
            this.mac = key == null ? null : Mac.getInstance("HmacSHA256");
            if (mac != null) {
                mac.init(new SecretKeySpec(this.key, "HmacSHA256"));
            }
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("HmacSHA256 is missing from this JDK", e);
        }
    }

    /** True if frames carry a MAC. */
    public boolean paired() {
        return key != null;
    }

    /** The frame's bytes before stuffing: header, body, MAC if paired, CRC. */
    public byte[] raw(Frame f) {
        int flags = (f.flags() & ~Frame.MAC) | (paired() ? Frame.MAC : 0);
        byte[] body = f.body();
        int n = HEADER + body.length + (paired() ? MAC_BYTES : 0) + 4;
        if (n > MAX_FRAME) {
            throw new IllegalArgumentException("a frame of " + n + " bytes is over the " + MAX_FRAME + "-byte limit");
        }
        byte[] out = new byte[n];
        out[0] = (byte) f.type();
        out[1] = (byte) flags;
        out[2] = (byte) (f.seq() >>> 8);
        out[3] = (byte) f.seq();
        long t = f.timeMs();
        out[4] = (byte) (t >>> 24);
        out[5] = (byte) (t >>> 16);
        out[6] = (byte) (t >>> 8);
        out[7] = (byte) t;
        System.arraycopy(body, 0, out, HEADER, body.length);
        int at = HEADER + body.length;
        if (paired()) {
            byte[] m = mac(out, 0, at);
            System.arraycopy(m, 0, out, at, MAC_BYTES);
            at += MAC_BYTES;
        }
        CRC32C crc = new CRC32C();
        crc.update(out, 0, at);
        long c = crc.getValue();
        out[at] = (byte) (c >>> 24);
        out[at + 1] = (byte) (c >>> 16);
        out[at + 2] = (byte) (c >>> 8);
        out[at + 3] = (byte) c;
        return out;
    }

    /** The frame's bytes on the wire: stuffed, then a zero. */
    public byte[] encode(Frame f) {
        byte[] raw = raw(f);
        byte[] stuffed = Cobs.encode(raw, 0, raw.length);
        byte[] out = Arrays.copyOf(stuffed, stuffed.length + 1);
        out[stuffed.length] = 0;
        return out;
    }

    /**
     * A frame from its stuffed bytes (the zero that closed it removed).
     *
     * @throws FrameException corrupt (stuffing or CRC), oversized, mac (missing, unexpected or
     *                        wrong), malformed (shorter than a header)
     */
    public Frame decode(byte[] stuffed, int off, int len) {
        if (len > MAX_FRAME + MAX_FRAME / 254 + 1) {
            throw new FrameException("oversized", len + " stuffed bytes; a frame has at most " + MAX_FRAME);
        }
        byte[] raw;
        try {
            raw = Cobs.decode(stuffed, off, len);
        } catch (IllegalArgumentException e) {
            throw new FrameException("corrupt", e.getMessage());
        }
        if (raw.length < HEADER + 4) {
            throw new FrameException("corrupt", raw.length + " bytes, shorter than a header and a CRC");
        }
        int end = raw.length - 4;
        CRC32C crc = new CRC32C();
        crc.update(raw, 0, end);
        long want = ((raw[end] & 0xFFL) << 24) | ((raw[end + 1] & 0xFFL) << 16) | ((raw[end + 2] & 0xFFL) << 8) | (raw[end + 3] & 0xFFL);
        if (crc.getValue() != want) {
            throw new FrameException("corrupt", String.format("CRC-32C %08X, the frame says %08X", crc.getValue(), want));
        }
        int flags = raw[1] & 0xFF;
        if ((flags & ~(Frame.MAC | Frame.SYNC)) != 0) {
            throw new FrameException("malformed", String.format("flags %02X: only bits 0 (MAC) and 1 (SYNC) are defined", flags));
        }
        boolean hasMac = (flags & Frame.MAC) != 0;
        if (hasMac != paired()) {
            throw new FrameException("mac", hasMac ? "the frame carries a MAC and this end has no pairing key"
                    : "the frame carries no MAC and this end is paired");
        }
        int bodyEnd = end;
        if (hasMac) {
            bodyEnd = end - MAC_BYTES;
            if (bodyEnd < HEADER) {
                throw new FrameException("malformed", "too short for its MAC");
            }
            byte[] m = mac(raw, 0, bodyEnd);
            if (!java.security.MessageDigest.isEqual(Arrays.copyOf(m, MAC_BYTES), Arrays.copyOfRange(raw, bodyEnd, end))) {
                throw new FrameException("mac", "the MAC does not match (another key, or the frame was altered)");
            }
        }
        int seq = ((raw[2] & 0xFF) << 8) | (raw[3] & 0xFF);
        long t = ((raw[4] & 0xFFL) << 24) | ((raw[5] & 0xFFL) << 16) | ((raw[6] & 0xFFL) << 8) | (raw[7] & 0xFFL);
        return new Frame(raw[0] & 0xFF, flags, seq, t, Arrays.copyOfRange(raw, HEADER, bodyEnd));
    }

    private byte[] mac(byte[] b, int off, int len) {
        mac.update(b, off, len);
        return Arrays.copyOf(mac.doFinal(), MAC_BYTES);
    }
}
