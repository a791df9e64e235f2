package io.concord.serial;

/**
 * One frame of the board protocol (docs/chair-protocol.md), before stuffing: a type, a sequence
 * number of its sender's stream, the sender's clock in milliseconds, and a body whose layout the
 * type gives. {@code flags} has bit 0 set when a MAC follows the body, bit 1 on a host's SYNC.
 *
 * @param type   the frame type ({@link Type})
 * @param flags  bit 0: MAC present; bit 1: SYNC (a new host session: the board restarts its count)
 * @param seq    0 to 65535, one more than the sender's previous frame, wrapping
 * @param timeMs the sender's clock, milliseconds since it started, modulo 2^32
 * @param body   the type's fields
 */
public record Frame(int type, int flags, int seq, long timeMs, byte[] body) {
    /** Flag: a MAC follows the body. */
    public static final int MAC = 1;
    /** Flag: a host's first frame of a session; the board starts counting its sequence again. */
    public static final int SYNC = 2;

    /** The frame types. */
    public static final class Type {
        /** Host to board: left and right motor power, per mille. */
        public static final int DRIVE = 0x01;
        /** Host to board: both motors to zero. */
        public static final int STOP = 0x02;
        /** Host to board: the state rate. */
        public static final int CONFIGURE = 0x03;
        /** Host to board: are you there (a nonce, echoed in the ACK); with SYNC, a new session, which disarms the board. */
        public static final int PING = 0x04;
        /**
         * Host to board (version 3): arm, for the board's boot number and the reason it is not armed, as the host's
         * last STATE showed them; sent only when the host's supervisor resumes, never by the heartbeat.
         */
        public static final int ARM = 0x05;
        /** Board to host: boot number, encoders, ranges, bumper, e-stop, armed (and why not), battery, faults, and a marker fix. */
        public static final int STATE = 0x81;
        /**
         * Board to host, versions 1 and 2 only: their HELLO, whose first byte was ambiguous (a version-2 board's
         * version, a version-1 board's firmware name's length). A host of version 3 refuses such a board.
         */
        public static final int OLD_HELLO = 0x82;
        /** Board to host, from version 3: the protocol's version, the boot number, the firmware's version and the chair's layout. */
        public static final int HELLO = 0x85;
        /** Board to host: a host frame taken. */
        public static final int ACK = 0x83;
        /** Board to host: a host frame refused, with the reason and why the board is not armed. */
        public static final int NAK = 0x84;

        private Type() {
        }

        /** The type's name, for logs and drop counters. */
        public static String name(int type) {
            return switch (type) {
                case DRIVE -> "DRIVE";
                case STOP -> "STOP";
                case CONFIGURE -> "CONFIGURE";
                case PING -> "PING";
                case ARM -> "ARM";
                case OLD_HELLO -> "HELLO (version 1 or 2)";
                case STATE -> "STATE";
                case HELLO -> "HELLO";
                case ACK -> "ACK";
                case NAK -> "NAK";
                default -> String.format("0x%02X", type);
            };
        }
    }

    /** Copies the body. */
    public Frame {
        body = body.clone();
    }

    @Override
    public byte[] body() {
        return body.clone();
    }

    /** A reader of the body's fields. */
    public Fields fields() {
        return new Fields(body);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Frame f && f.type == type && f.flags == flags && f.seq == seq && f.timeMs == timeMs
                && java.util.Arrays.equals(f.body, body);
    }

    @Override
    public int hashCode() {
        return java.util.Objects.hash(type, flags, seq, timeMs, java.util.Arrays.hashCode(body));
    }

    @Override
    public String toString() {
        return Type.name(type) + "[seq " + seq + ", t " + timeMs + " ms, " + body.length + " bytes" + ((flags & SYNC) != 0 ? ", sync" : "") + "]";
    }

    /** Big-endian fields, read in order; a body too short throws {@link FrameException} ("malformed"). */
    public static final class Fields {
        private final byte[] b;
        private int at;

        Fields(byte[] b) {
            this.b = b;
        }

        private void need(int n) {
            if (at + n > b.length) {
                throw new FrameException("malformed", "the body ends at byte " + b.length + ", a field needs " + n + " more from byte " + at);
            }
        }

        public int u8() {
            need(1);
            return b[at++] & 0xFF;
        }

        public int u16() {
            need(2);
            int v = ((b[at] & 0xFF) << 8) | (b[at + 1] & 0xFF);
            at += 2;
            return v;
        }

        public int i16() {
            return (short) u16();
        }

        public int i32() {
            need(4);
            int v = ((b[at] & 0xFF) << 24) | ((b[at + 1] & 0xFF) << 16) | ((b[at + 2] & 0xFF) << 8) | (b[at + 3] & 0xFF);
            at += 4;
            return v;
        }

        public long u32() {
            return i32() & 0xFFFFFFFFL;
        }

        public String text() {
            int n = u8();
            need(n);
            String s = new String(b, at, n, java.nio.charset.StandardCharsets.UTF_8);
            at += n;
            return s;
        }

        /** Throws if bytes are left over. */
        public void end() {
            if (at != b.length) {
                throw new FrameException("malformed", (b.length - at) + " bytes left over after the last field");
            }
        }
    }

    /** Writes big-endian fields. */
    public static final class Builder {
        private final java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();

        public Builder u8(int v) {
            out.write(v);
            return this;
        }

        public Builder u16(int v) {
            out.write(v >>> 8);
            out.write(v);
            return this;
        }

        public Builder i32(long v) {
            out.write((int) (v >>> 24));
            out.write((int) (v >>> 16));
            out.write((int) (v >>> 8));
            out.write((int) v);
            return this;
        }

        public Builder text(String s) {
            byte[] t = s.getBytes(java.nio.charset.StandardCharsets.UTF_8);
            if (t.length > 255) {
                throw new IllegalArgumentException("text longer than 255 bytes: " + s);
            }
            out.write(t.length);
            out.write(t, 0, t.length);
            return this;
        }

        public byte[] bytes() {
            return out.toByteArray();
        }
    }
}
