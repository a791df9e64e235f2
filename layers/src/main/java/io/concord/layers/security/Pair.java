package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;

import java.util.ArrayDeque;
import javax.crypto.Cipher;
import javax.crypto.spec.SecretKeySpec;

/**
 * What an agent keeps per peer under class 7 ({@link Handshake}): the keys, the messages that wait
 * for one, the handshake under way. Loop thread only.
 */
final class Pair {
    /** The key in use, confirmed by both ends; null while none is. */
    SecretKeySpec key;
    // One cipher per key and direction: the JDK expands an AES key again whenever a cipher is
    // initialised with another key than last time, which would cost more than the encryption.
    Cipher encrypt;
    Cipher decrypt;
    /** The key before, still opened for frames under way while a new one was agreed. */
    SecretKeySpec previousKey;
    Cipher previousDecrypt;
    Address address;
    final ArrayDeque<Envelope> queue = new ArrayDeque<>();
    long timer = -1;
    int attempts;
    /** The challenge of this agent's hello under way, or null. */
    byte[] challenge;
    /** The challenge of this agent's last hello that was answered: another reply to it is late, not a replay. */
    byte[] answeredChallenge;
    /**
     * This agent's own hello's challenge when the peer's handshake, which it answered, was confirmed
     * first (hellos crossed): the peer's answer to it may still come, late, not a replay.
     */
    byte[] supersededChallenge;
    /** Replies this agent sent, each waiting for the peer's confirmation. */
    final ArrayDeque<Pending> pending = new ArrayDeque<>();
    /** The challenge of the last hello whose key was confirmed: a copy of it is a replay. */
    byte[] confirmedHello;
    int failures;
    long lastRekeyAnswered = Long.MIN_VALUE;

    /** A reply sent and not yet confirmed: the key it gives (and its cipher), and the signed reply to send again. */
    record Pending(byte[] helloChallenge, byte[] replyChallenge, byte[] keyBytes, SecretKeySpec key, Cipher decrypt,
                   byte[] reply) {
        Pending(byte[] helloChallenge, byte[] replyChallenge, byte[] keyBytes, byte[] reply) {
            this(helloChallenge, replyChallenge, keyBytes, new SecretKeySpec(keyBytes, "AES"), FrameSealer.newGcm(), reply);
        }
    }

    /** The key in use becomes the previous one: still opened, no longer used to seal. */
    void retire() {
        if (key != null) {
            previousKey = key;
            previousDecrypt = decrypt;
        }
        key = null;
        encrypt = null;
        decrypt = null;
    }
}
