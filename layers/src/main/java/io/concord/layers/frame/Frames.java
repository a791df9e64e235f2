package io.concord.layers.frame;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Locale;

/**
 * The constants of the Concord frame (see {@code docs/wire-format.md}) and the byte helpers the
 * layers share. All integers are big-endian.
 *
 * <pre>
 * frame   = header(28) body trailer
 * header  = magic u16 (0xC07D) | version u8 (1) | flags u8 | source id u64 | destination id u64 | counter u64
 * body    = temporal(9) sequence(13) acl          (encrypted with the crc under AES-GCM)
 * trailer = crc32c u32 [| tag 16 bytes]
 * </pre>
 */
public final class Frames {
    public static final int MAGIC = 0xC07D;
    public static final int VERSION = 1;
    public static final int HEADER_BYTES = 28;
    public static final int CRC_BYTES = 4;
    public static final int TAG_BYTES = 16;
    /** Headroom the parser leaves in front of the ACL bytes so lower layers prepend in place. */
    public static final int HEADROOM = 64;

    /** Protection, bits 0-1 of the flags. */
    public static final int PROTECTION_CRC = 0;
    public static final int PROTECTION_HMAC = 1;
    public static final int PROTECTION_GCM_PLATFORM = 2;
    public static final int PROTECTION_GCM_PAIR = 3;
    public static final int PROTECTION_MASK = 3;
    /** Flag bit 2: a handshake frame of the security layer. */
    public static final int FLAG_HANDSHAKE = 4;
    /**
     * Flag bits 3-7: the platform key's id (5 bits of HKDF-SHA256 of the key, info
     * {@code concord key id v1}), 0 under CRC alone: a frame of another platform sharing the port
     * range is told from a forged one before any MAC is computed, most of the time (1 in 32 keys
     * share an id; their frames are then told apart by the tag, as {@code bad-tag}).
     */
    public static final int KEY_ID_MASK = 0xF8;

    /**
     * The destination id of a frame for whichever agent holds the port it is sent to: the
     * port-binding discovery asks a port before it knows the name behind it. Such frames are sealed
     * with the platform key, are not sequenced, and may carry only platform messages.
     */
    public static final long ANY = 0;
    /** Envelope header id the security layer sets on a frame that came addressed to {@link #ANY}. */
    public static final int ENVELOPE_ANY = 9;
    /**
     * Envelope header id the container layer sets going down when the copy for a receiver goes to
     * another agent's node, which serves it (the container, for {@code df@platform} or a foreign
     * agent): the {@code AID} of that node. The frame's destination id is its.
     */
    public static final int ENVELOPE_VIA = 10;
    /** The local name of the receiver that stands for {@link #ANY}: {@code *@platform}. */
    public static final String ANY_LOCAL_NAME = "*";

    private static final VarHandle LONG = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle INT = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle SHORT = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.BIG_ENDIAN);

    private Frames() {
    }

    /**
     * An agent's frame id: the first 8 bytes of SHA-256 of its lower-case name, never 0. Both ends
     * compute it from the name, so it needs no registry.
     */
    public static long id(String agentName) {
        try {
            byte[] h = MessageDigest.getInstance("SHA-256").digest(agentName.toLowerCase(Locale.ROOT)
                    .getBytes(StandardCharsets.UTF_8));
            long id = getLong(h, 0);
            return id == 0 ? 1 : id;
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("the JDK has no SHA-256", e);
        }
    }

    public static long getLong(byte[] b, int at) {
        return (long) LONG.get(b, at);
    }

    public static void putLong(byte[] b, int at, long v) {
        LONG.set(b, at, v);
    }

    public static int getInt(byte[] b, int at) {
        return (int) INT.get(b, at);
    }

    public static void putInt(byte[] b, int at, int v) {
        INT.set(b, at, v);
    }

    public static int getShort(byte[] b, int at) {
        return ((short) SHORT.get(b, at)) & 0xFFFF;
    }

    public static void putShort(byte[] b, int at, int v) {
        SHORT.set(b, at, (short) v);
    }
}
