package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;
import io.concord.layers.Stacks;
import io.concord.layers.frame.Frames;
import io.concord.layers.security.SecurityLayer.Protection;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import javax.crypto.Cipher;
import javax.crypto.spec.SecretKeySpec;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The frame sealer alone: header, safety code, tags and the memory of tags, on bytes, with no peer or timer. */
class FrameSealerTest {
    private static final long A = Frames.id("a@p");
    private static final long B = Frames.id("b@p");

    private static FrameSealer sealer(Protection p, long ownId, long firstCounter) {
        return new FrameSealer(p, Stacks.KEY, ownId, firstCounter, true, true);
    }

    private static Envelope body(String text) {
        byte[] b = text.getBytes(StandardCharsets.UTF_8);
        byte[] buf = new byte[Frames.HEADROOM + b.length];
        System.arraycopy(b, 0, buf, Frames.HEADROOM, b.length);
        return Envelope.control(B, new Address("h", 2), buf, Frames.HEADROOM, b.length);
    }

    private static byte[] wire(Envelope e) {
        return e.dataCopy();
    }

    @Test
    void theHeaderNamesSourceAndDestinationAndCountsFramesFromTheFirstCounter() {
        FrameSealer a = sealer(Protection.CRC, A, 41);
        for (int i = 0; i < 2; i++) {
            Envelope e = body("hello");
            a.sealWithPlatformKey(e, Frames.PROTECTION_CRC, 0);
            byte[] w = wire(e);
            assertEquals(Frames.MAGIC, Frames.getShort(w, 0));
            assertEquals(Frames.VERSION, w[2]);
            assertEquals(A, Frames.getLong(w, 4));
            assertEquals(B, Frames.getLong(w, 12));
            assertEquals(41 + i, Frames.getLong(w, 20));
            assertEquals(Frames.HEADER_BYTES + 5 + Frames.CRC_BYTES, w.length);
        }
    }

    @Test
    void theSafetyCodeCoversEveryByteOfHeaderAndBody() {
        FrameSealer a = sealer(Protection.CRC, A, 1);
        FrameSealer b = sealer(Protection.CRC, B, 1);
        Envelope e = body("the body");
        a.sealWithPlatformKey(e, Frames.PROTECTION_CRC, 0);
        byte[] w = wire(e);
        int bodyLen = w.length - Frames.HEADER_BYTES - Frames.CRC_BYTES;
        assertTrue(b.safetyCodeMatches(w, 0, w, Frames.HEADER_BYTES, bodyLen));
        for (int i = 0; i < w.length; i++) {
            byte[] bad = w.clone();
            bad[i] ^= 1;
            assertFalse(b.safetyCodeMatches(bad, 0, bad, Frames.HEADER_BYTES, bodyLen), "a flipped bit in byte " + i);
        }
    }

    @Test
    void anHmacTagOpensOnlyUnderTheSamePlatformKeyAndAnUnchangedFrame() {
        FrameSealer a = sealer(Protection.HMAC, A, 1);
        FrameSealer b = sealer(Protection.HMAC, B, 1);
        FrameSealer other = new FrameSealer(Protection.HMAC, PlatformKey.ofHex("ff".repeat(32)), B, 1, true, true);
        Envelope e = body("signed");
        a.sealWithPlatformKey(e, Frames.PROTECTION_HMAC, 0);
        byte[] w = wire(e);
        assertTrue(b.hmacMatches(w, 0, w.length));
        assertFalse(other.hmacMatches(w, 0, w.length), "another platform key");
        w[Frames.HEADER_BYTES] ^= 1;
        assertFalse(b.hmacMatches(w, 0, w.length), "a changed body");
    }

    @Test
    void anAesGcmFrameOpensToItsBodyAndSafetyCodeUnderItsKeyAndNoOther() {
        FrameSealer a = sealer(Protection.GCM_PLATFORM, A, 7);
        FrameSealer b = sealer(Protection.GCM_PLATFORM, B, 1);
        Envelope e = body("secret");
        a.sealWithPlatformKey(e, Frames.PROTECTION_GCM_PLATFORM, 0);
        byte[] w = wire(e);
        assertEquals(Frames.HEADER_BYTES + 6 + Frames.CRC_BYTES + Frames.TAG_BYTES, w.length);
        assertFalse(new String(w, StandardCharsets.ISO_8859_1).contains("secret"), "the body is encrypted");
        byte[] opened = b.openWithPlatformKey(A, 7, w, 0, w.length);
        assertNotNull(opened);
        assertArrayEquals("secret".getBytes(StandardCharsets.UTF_8), Arrays.copyOf(opened, 6));
        assertTrue(b.safetyCodeMatches(w, 0, opened, 0, opened.length - Frames.CRC_BYTES));
        assertNull(b.openWithPlatformKey(A, 8, w, 0, w.length), "another counter: another nonce");
        Cipher gcm = FrameSealer.newGcm();
        assertNull(b.open(gcm, new SecretKeySpec(new byte[16], "AES"), A, 7, w, 0, w.length), "another key");
        byte[] bad = w.clone();
        bad[5] ^= 1;
        assertNull(b.openWithPlatformKey(A, 7, bad, 0, bad.length), "the header is associated data");
    }

    @Test
    void aTagIsACopyOnlyOnceRememberedAndTheLast64AreKept() {
        FrameSealer s = sealer(Protection.GCM_PLATFORM, B, 1);
        assertFalse(s.seenTag(1));
        s.rememberTag(1);
        assertTrue(s.seenTag(1));
        for (long t = 2; t <= 64; t++) {
            s.rememberTag(t);
        }
        assertTrue(s.seenTag(1), "64 remembered");
        s.rememberTag(65);
        assertFalse(s.seenTag(1), "the oldest forgotten for the 65th");
        assertTrue(s.seenTag(65));
    }

    @Test
    void theThreatTestsSwitchesLeaveTheCodeAndTagUnchecked() {
        FrameSealer a = sealer(Protection.HMAC, A, 1);
        FrameSealer unchecked = new FrameSealer(Protection.HMAC, Stacks.KEY, B, 1, false, false);
        Envelope e = body("x");
        a.sealWithPlatformKey(e, Frames.PROTECTION_HMAC, 0);
        byte[] w = wire(e);
        w[Frames.HEADER_BYTES] ^= 1;
        assertTrue(unchecked.hmacMatches(w, 0, w.length));
        assertTrue(unchecked.safetyCodeMatches(w, 0, w, Frames.HEADER_BYTES, 1));
    }
}
