package io.concord.layers.security;

import org.bouncycastle.crypto.digests.SHA256Digest;
import org.bouncycastle.crypto.generators.HKDFBytesGenerator;
import org.bouncycastle.crypto.params.HKDFParameters;

import java.nio.charset.StandardCharsets;

/** Small cryptographic helpers: HKDF-SHA256 (Bouncy Castle, since Java 17 has none). */
final class Crypto {
    private Crypto() {
    }

    /** HKDF-SHA256 (RFC 5869): {@code length} bytes from input keying material, salt and info. */
    public static byte[] hkdf(byte[] ikm, byte[] salt, byte[] info, int length) {
        HKDFBytesGenerator g = new HKDFBytesGenerator(new SHA256Digest());
        g.init(new HKDFParameters(ikm, salt, info));
        byte[] out = new byte[length];
        g.generateBytes(out, 0, length);
        return out;
    }

    /** HKDF with a text label as info. */
    public static byte[] hkdf(byte[] ikm, byte[] salt, String label, int length) {
        return hkdf(ikm, salt, label.getBytes(StandardCharsets.US_ASCII), length);
    }
}
