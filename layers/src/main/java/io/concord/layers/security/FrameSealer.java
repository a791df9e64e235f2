package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.layers.frame.Frames;
import io.concord.layers.security.SecurityLayer.Protection;

import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.util.Arrays;
import java.util.zip.CRC32C;
import javax.crypto.Cipher;
import javax.crypto.Mac;
import javax.crypto.spec.GCMParameterSpec;
import javax.crypto.spec.SecretKeySpec;

/**
 * The security layer's frame sealer: it writes and checks the Concord header (source and
 * destination ids, a counter), the CRC-32C safety code over header and body, and the HMAC or
 * AES-GCM tag of the protection, and remembers the tags of the frames it accepted, so that a copy
 * is refused before it is opened. It holds the platform key's ciphers; a pair key and its cipher
 * are the handshake's, and come with each call. It knows no peer, no handshake and no timer: each
 * call works on the bytes it is given (JGroups keeps the same seam between {@code EncryptBase} and
 * its key exchanges). One per agent, called on its loop.
 */
final class FrameSealer {
    private static final int RECENT_TAGS = 64;

    private final long ownId;
    private final boolean hmacTag;
    private final boolean safetyCode;
    private final CRC32C crc = new CRC32C();
    private final long[] recentTags = new long[RECENT_TAGS];
    private final byte[] nonce = new byte[12];
    private int recentIndex;
    private long counter;
    private byte[] platformKeyBytes;
    private SecretKeySpec platformAead;
    private Cipher platformEncrypt;
    private Cipher platformDecrypt;
    private Mac mac;

    /**
     * @param protection   the data frames' protection: which platform-key ciphers are made
     * @param platformKey  the platform key ({@code null} under {@link Protection#CRC})
     * @param ownId        this agent's frame id, the source of what it seals
     * @param firstCounter the counter of the first frame sealed
     * @param hmacTag      false only in threat tests: an HMAC tag is not checked
     * @param safetyCode   false only in threat tests: the CRC-32C is not checked
     * @throws IllegalStateException if the JVM lacks AES-GCM or HMAC-SHA256
     */
    FrameSealer(Protection protection, PlatformKey platformKey, long ownId, long firstCounter, boolean hmacTag,
                boolean safetyCode) {
        this.ownId = ownId;
        this.counter = firstCounter;
        this.hmacTag = hmacTag;
        this.safetyCode = safetyCode;
        try {
            if (protection != Protection.CRC) {
                platformKeyBytes = platformKey.bytes();
                keyBits = keyBitsOf(platformKeyBytes);
                platformAead = new SecretKeySpec(Crypto.hkdf(platformKeyBytes, null, "concord platform aead v1", 16), "AES");
                platformEncrypt = Cipher.getInstance("AES/GCM/NoPadding");
                platformDecrypt = Cipher.getInstance("AES/GCM/NoPadding");
            }
            if (protection == Protection.HMAC) {
                mac = Mac.getInstance("HmacSHA256");
                mac.init(new SecretKeySpec(Crypto.hkdf(platformKeyBytes, null, "concord platform mac v1", 32), "HmacSHA256"));
            }
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("this JVM lacks AES-GCM or HMAC-SHA256: " + e.getMessage(), e);
        }
    }

    /** The platform key's id in the flags' bits 3-7 (0 under CRC alone). */
    private int keyBits;

    int keyBits() {
        return keyBits;
    }

    /** A platform key's id, where the flags carry it (bits 3-7): 5 bits of HKDF-SHA256 of the key, info {@code concord key id v1}. */
    static int keyBitsOf(byte[] platformKey) {
        return (Crypto.hkdf(platformKey, null, "concord key id v1", 1)[0] << 3) & Frames.KEY_ID_MASK;
    }

    /** The counter of the next frame (see {@link SecurityLayer#setNextCounter}). */
    void setNextCounter(long next) {
        counter = next;
    }

    /** The platform key's bytes, the salt of every pair key; {@code null} under CRC alone. */
    byte[] platformKeyBytes() {
        return platformKeyBytes;
    }

    /** Seals a frame with the platform key (HMAC or AES-GCM by {@code protection}; CRC alone for CRC). */
    void sealWithPlatformKey(Envelope env, int protection, int flags) {
        seal(env, protection, flags, platformAead, platformEncrypt);
    }

    /**
     * Prepends the header, appends the safety code and, by protection, the HMAC tag or the AES-GCM
     * encryption under {@code key} with {@code gcm} (a cipher of that key only).
     */
    void seal(Envelope env, int protection, int flags, SecretKeySpec key, Cipher gcm) {
        int h = env.prepend(Frames.HEADER_BYTES);
        byte[] d = env.data();
        Frames.putShort(d, h, Frames.MAGIC);
        d[h + 2] = (byte) Frames.VERSION;
        d[h + 3] = (byte) (protection | flags | (protection == Frames.PROTECTION_CRC ? 0 : keyBits));
        Frames.putLong(d, h + 4, ownId);
        Frames.putLong(d, h + 12, env.peerId());
        long ctr = counter++;
        Frames.putLong(d, h + 20, ctr);
        crc.reset();
        crc.update(d, h, env.length());
        int code = (int) crc.getValue();
        int at = env.append(Frames.CRC_BYTES);
        d = env.data();
        h = env.offset();
        Frames.putInt(d, at, code);
        if (protection == Frames.PROTECTION_HMAC) {
            mac.update(d, h, env.length());
            byte[] tag = mac.doFinal();
            int t = env.append(Frames.TAG_BYTES);
            System.arraycopy(tag, 0, env.data(), t, Frames.TAG_BYTES);
        } else if (protection >= Frames.PROTECTION_GCM_PLATFORM) {
            try {
                nonceFor(ownId, ctr);
                gcm.init(Cipher.ENCRYPT_MODE, key, new GCMParameterSpec(128, nonce));
                gcm.updateAAD(d, h, Frames.HEADER_BYTES);
                int bodyLen = env.length() - Frames.HEADER_BYTES;
                byte[] out = new byte[Frames.HEADER_BYTES + bodyLen + Frames.TAG_BYTES];
                System.arraycopy(d, h, out, 0, Frames.HEADER_BYTES);
                gcm.doFinal(d, h + Frames.HEADER_BYTES, bodyLen, out, Frames.HEADER_BYTES);
                env.setData(out, 0, out.length);
            } catch (GeneralSecurityException e) {
                throw new IllegalStateException("AES-GCM failed to encrypt: " + e.getMessage(), e);
            }
        }
    }

    /** Nonce: the sender's id prefix and its frame counter, unique per key as long as ids differ. */
    private void nonceFor(long senderId, long ctr) {
        Frames.putInt(nonce, 0, (int) (senderId >>> 32));
        Frames.putLong(nonce, 4, ctr);
    }

    /** Opens an AES-GCM frame with the platform key, or returns null if the tag does not match. */
    byte[] openWithPlatformKey(long src, long ctr, byte[] d, int h, int len) {
        return open(platformDecrypt, platformAead, src, ctr, d, h, len);
    }

    /** Opens an AES-GCM frame, or returns null if the tag does not match. */
    byte[] open(Cipher gcm, SecretKeySpec key, long src, long ctr, byte[] d, int h, int len) {
        try {
            nonceFor(src, ctr);
            gcm.init(Cipher.DECRYPT_MODE, key, new GCMParameterSpec(128, nonce));
            gcm.updateAAD(d, h, Frames.HEADER_BYTES);
            return gcm.doFinal(d, h + Frames.HEADER_BYTES, len - Frames.HEADER_BYTES);
        } catch (GeneralSecurityException e) {
            return null; // a bad tag (AEADBadTagException), or a frame the cipher refuses
        }
    }

    /**
     * True if the frame's HMAC tag (its last {@link Frames#TAG_BYTES}) is right, or if the threat
     * tests switched the check off.
     */
    boolean hmacMatches(byte[] d, int h, int len) {
        mac.update(d, h, len - Frames.TAG_BYTES);
        byte[] expected = mac.doFinal();
        return !hmacTag || MessageDigest.isEqual(Arrays.copyOf(expected, Frames.TAG_BYTES),
                Arrays.copyOfRange(d, h + len - Frames.TAG_BYTES, h + len));
    }

    /**
     * True if the safety code after the body matches the header at {@code h} and the body, or if
     * the threat tests switched the check off.
     */
    boolean safetyCodeMatches(byte[] d, int h, byte[] body, int bodyOff, int bodyLen) {
        crc.reset();
        crc.update(d, h, Frames.HEADER_BYTES);
        crc.update(body, bodyOff, bodyLen);
        return !safetyCode || (int) crc.getValue() == Frames.getInt(body, bodyOff + bodyLen);
    }

    /** True if a frame with this tag (its first 8 bytes) was accepted lately: a copy. */
    boolean seenTag(long tag) {
        for (long t : recentTags) {
            if (t == tag) {
                return true;
            }
        }
        return false;
    }

    /** Remembers the tag of a frame accepted (the last {@value #RECENT_TAGS}). */
    void rememberTag(long tag) {
        recentTags[recentIndex] = tag;
        recentIndex = (recentIndex + 1) % RECENT_TAGS;
    }

    /** A cipher for one AES-GCM key and direction. */
    static Cipher newGcm() {
        try {
            return Cipher.getInstance("AES/GCM/NoPadding");
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("this JVM lacks AES-GCM: " + e.getMessage(), e);
        }
    }
}
