package io.concord.layers.security;

import org.bouncycastle.crypto.agreement.X25519Agreement;
import org.bouncycastle.crypto.params.Ed25519PrivateKeyParameters;
import org.bouncycastle.crypto.params.Ed25519PublicKeyParameters;
import org.bouncycastle.crypto.params.X25519PrivateKeyParameters;
import org.bouncycastle.crypto.params.X25519PublicKeyParameters;
import org.bouncycastle.crypto.signers.Ed25519Signer;

import java.security.SecureRandom;

/**
 * An agent's keys: a long-lived Ed25519 identity (its signature proves who it is) and an X25519
 * key for this run (agreed with a peer's, it gives the pair's session key). Bouncy Castle: its
 * Ed25519 is 6-20 times faster than the JDK's on these machines.
 */
public final class Identity {
    private final Ed25519PrivateKeyParameters signing;
    private final byte[] signingPublic;
    private final X25519PrivateKeyParameters agreement;
    private final byte[] agreementPublic;

    private Identity(Ed25519PrivateKeyParameters signing, SecureRandom random) {
        this.signing = signing;
        this.signingPublic = signing.generatePublicKey().getEncoded();
        this.agreement = new X25519PrivateKeyParameters(random);
        this.agreementPublic = agreement.generatePublicKey().getEncoded();
    }

    /** A new identity. */
    public static Identity generate(SecureRandom random) {
        return new Identity(new Ed25519PrivateKeyParameters(random), random);
    }

    /** An identity from a stored 32-byte Ed25519 seed, with a fresh X25519 key. */
    public static Identity fromSeed(byte[] seed, SecureRandom random) {
        return new Identity(new Ed25519PrivateKeyParameters(seed, 0), random);
    }

    /** The Ed25519 seed, for storing. */
    byte[] seed() {
        return signing.getEncoded();
    }

    /** The Ed25519 public key (32 bytes). */
    public byte[] signingPublicKey() {
        return signingPublic.clone();
    }

    /** The X25519 public key of this run (32 bytes). */
    public byte[] agreementPublicKey() {
        return agreementPublic.clone();
    }

    /** Signs with the identity key. */
    public byte[] sign(byte[] data, int offset, int length) {
        Ed25519Signer s = new Ed25519Signer();
        s.init(true, signing);
        s.update(data, offset, length);
        return s.generateSignature();
    }

    /** Checks an Ed25519 signature. */
    public static boolean verify(byte[] publicKey, byte[] data, int offset, int length, byte[] signature) {
        Ed25519Signer s = new Ed25519Signer();
        s.init(false, new Ed25519PublicKeyParameters(publicKey, 0));
        s.update(data, offset, length);
        return s.verifySignature(signature);
    }

    /** The X25519 shared secret with a peer's agreement key. */
    public byte[] agree(byte[] peerAgreementPublic) {
        X25519Agreement a = new X25519Agreement();
        a.init(agreement);
        byte[] out = new byte[a.getAgreementSize()];
        a.calculateAgreement(new X25519PublicKeyParameters(peerAgreementPublic, 0), out, 0);
        return out;
    }
}
