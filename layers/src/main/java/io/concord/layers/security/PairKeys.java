package io.concord.layers.security;

import io.concord.layers.frame.Frames;

import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.util.Arrays;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/** The handshake's key derivation: a pair key from an X25519 secret, and the proof of holding one. */
final class PairKeys {
    /** The length of each challenge of a handshake. */
    static final int CHALLENGE_BYTES = 16;

    private PairKeys() {
    }

    /**
     * HKDF of the shared secret, salted with the platform key, bound to both ids and both
     * challenges: a replayed hello or reply gives a key nobody holds.
     */
    static byte[] derive(byte[] shared, byte[] platformKeyBytes, long ownId, long peerId, byte[] helloChallenge,
                         byte[] replyChallenge) {
        byte[] info = new byte[16 + 16 + 2 * CHALLENGE_BYTES];
        System.arraycopy("concord pair v2\0".getBytes(StandardCharsets.US_ASCII), 0, info, 0, 16);
        Frames.putLong(info, 16, Math.min(peerId, ownId));
        Frames.putLong(info, 24, Math.max(peerId, ownId));
        System.arraycopy(helloChallenge, 0, info, 32, CHALLENGE_BYTES);
        System.arraycopy(replyChallenge, 0, info, 32 + CHALLENGE_BYTES, CHALLENGE_BYTES);
        return Crypto.hkdf(shared, platformKeyBytes, info, 16);
    }

    /** The proof of holding a pair key: HMAC-SHA256 of both challenges under it, 16 bytes. */
    static byte[] confirmation(byte[] key, byte[] helloChallenge, byte[] replyChallenge) {
        try {
            Mac m = Mac.getInstance("HmacSHA256");
            m.init(new SecretKeySpec(key, "HmacSHA256"));
            m.update("concord confirm v1".getBytes(StandardCharsets.US_ASCII));
            m.update(helloChallenge);
            m.update(replyChallenge);
            return Arrays.copyOf(m.doFinal(), 16);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("this JVM lacks HMAC-SHA256: " + e.getMessage(), e);
        }
    }
}
