package io.concord.layers.security;

import io.concord.layers.frame.Frames;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * A signed hello or reply of the {@link Handshake}, as it travels in a handshake frame's body:
 * type u8, name length u16, name, Ed25519 signing key (32), X25519 agreement key (32), time in ms
 * u64, challenge (16), the hello's challenge echoed in a reply (16), and the Ed25519 signature (64)
 * over all of it followed by the receiver's frame id, so that it cannot be replayed to another
 * agent.
 */
record Hello(String name, byte[] signingKey, byte[] agreementKey, long timeMs, byte[] challenge, byte[] echo) {
    static final int HELLO = 1;
    static final int REPLY = 2;
    private static final int CHALLENGE_BYTES = PairKeys.CHALLENGE_BYTES;

    /** The length of what a hello or a reply of a name of {@code nameLen} bytes signs, less the receiver's id. */
    static int signedLength(int type, int nameLen) {
        return 1 + 2 + nameLen + 32 + 32 + 8 + CHALLENGE_BYTES + (type == REPLY ? CHALLENGE_BYTES : 0);
    }

    /** Writes and signs a hello ({@code echo == null}) or a reply to the agent of {@code peerId}: a handshake frame's body. */
    static byte[] write(Identity identity, String ownName, int type, long nowMs, byte[] challenge, byte[] echo, long peerId) {
        byte[] name = ownName.getBytes(StandardCharsets.UTF_8);
        int signedLen = 1 + 2 + name.length + 32 + 32 + 8 + CHALLENGE_BYTES + (echo != null ? CHALLENGE_BYTES : 0);
        byte[] signed = new byte[signedLen + 8];
        signed[0] = (byte) type;
        Frames.putShort(signed, 1, name.length);
        System.arraycopy(name, 0, signed, 3, name.length);
        int p = 3 + name.length;
        System.arraycopy(identity.signingPublicKey(), 0, signed, p, 32);
        System.arraycopy(identity.agreementPublicKey(), 0, signed, p + 32, 32);
        Frames.putLong(signed, p + 64, nowMs);
        System.arraycopy(challenge, 0, signed, p + 72, CHALLENGE_BYTES);
        if (echo != null) {
            System.arraycopy(echo, 0, signed, p + 72 + CHALLENGE_BYTES, CHALLENGE_BYTES);
        }
        // The signature also covers the destination id, so a hello cannot be replayed to another agent.
        Frames.putLong(signed, signedLen, peerId);
        byte[] sig = identity.sign(signed, 0, signedLen + 8);
        byte[] body = Arrays.copyOf(signed, signedLen + 64);
        System.arraycopy(sig, 0, body, signedLen, 64);
        return body;
    }

    /** Reads a hello or a reply whose type and length are checked already ({@link #signedLength}). */
    static Hello read(byte[] b, int off, int type, int nameLen) {
        String name = new String(b, off + 3, nameLen, StandardCharsets.UTF_8);
        int p = off + 3 + nameLen;
        byte[] signingKey = Arrays.copyOfRange(b, p, p + 32);
        byte[] agreementKey = Arrays.copyOfRange(b, p + 32, p + 64);
        long ts = Frames.getLong(b, p + 64);
        byte[] challenge = Arrays.copyOfRange(b, p + 72, p + 72 + CHALLENGE_BYTES);
        byte[] echo = type == REPLY ? Arrays.copyOfRange(b, p + 72 + CHALLENGE_BYTES, p + 72 + 2 * CHALLENGE_BYTES) : null;
        return new Hello(name, signingKey, agreementKey, ts, challenge, echo);
    }

    /** True if the body at {@code off} is signed, for the agent of {@code ownId}, by the key it presents. */
    boolean signedFor(byte[] b, int off, int signedLen, long ownId) {
        byte[] signed = new byte[signedLen + 8];
        System.arraycopy(b, off, signed, 0, signedLen);
        Frames.putLong(signed, signedLen, ownId);
        byte[] sig = Arrays.copyOfRange(b, off + signedLen, off + signedLen + 64);
        return Identity.verify(signingKey, signed, 0, signed.length, sig);
    }
}
