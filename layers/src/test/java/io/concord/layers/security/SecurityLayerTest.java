package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;
import io.concord.core.time.internal.LoopLimits;
import io.concord.testkit.LayerHarness;
import io.concord.core.time.ManualClock;
import io.concord.layers.Stacks;
import io.concord.layers.frame.Frames;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The security layer alone, between two harnesses that stand for two agents. */
class SecurityLayerTest {
    private final ManualClock clock = new ManualClock();
    private static final Address A_ADDR = new Address("h", 1);
    private static final Address B_ADDR = new Address("h", 2);

    private static SecurityLayer layer(SecurityLayer.Protection p, PlatformKey key) {
        return new SecurityLayer(new SecurityLayer.Config(p, key, IdentityStore.ephemeral(), 30_000, 16));
    }

    private LayerHarness agent(String name, SecurityLayer layer) {
        return new LayerHarness(name, clock, layer);
    }

    private static Envelope body(String text, String to) {
        byte[] b = text.getBytes(StandardCharsets.UTF_8);
        byte[] buf = new byte[Frames.HEADROOM + b.length];
        System.arraycopy(b, 0, buf, Frames.HEADROOM, b.length);
        return Envelope.control(Frames.id(to), B_ADDR, buf, Frames.HEADROOM, b.length);
    }

    /** Carries every frame waiting at one harness's bottom into the other's, from the given address. */
    private static int carry(LayerHarness from, Address fromAddress, LayerHarness to) {
        int n = 0;
        Envelope e;
        while ((e = from.pollDown()) != null) {
            byte[] wire = e.dataCopy();
            to.receiveUp(Envelope.incoming(fromAddress, wire, 0, wire.length, 0));
            n++;
        }
        return n;
    }

    private static String text(Envelope e) {
        return new String(e.data(), e.offset(), e.length(), StandardCharsets.UTF_8);
    }

    @Test
    void eachPlatformKeyProtectionFramesAndOpensAMessage() {
        for (SecurityLayer.Protection p : new SecurityLayer.Protection[]{SecurityLayer.Protection.CRC,
                SecurityLayer.Protection.HMAC, SecurityLayer.Protection.GCM_PLATFORM}) {
            LayerHarness a = agent("a@p", layer(p, Stacks.KEY));
            LayerHarness b = agent("b@p", layer(p, Stacks.KEY));
            a.sendDown(body("hello " + p, "b@p"));
            assertEquals(1, carry(a, A_ADDR, b));
            Envelope got = b.pollUp();
            assertNotNull(got, p + " opened");
            assertEquals("hello " + p, text(got));
            assertEquals(Frames.id("a@p"), got.peerId(), "the authenticated source");
        }
    }

    @Test
    void gcmHidesTheContentFromTheWire() {
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.GCM_PLATFORM, Stacks.KEY));
        a.sendDown(body("a secret nobody may read", "b@p"));
        String wire = new String(a.pollDown().dataCopy(), StandardCharsets.ISO_8859_1);
        assertFalse(wire.contains("secret"));
    }

    /**
     * Another platform's frame (its key's id is not this platform's): skipped as such before any
     * tag is computed, and told apart from a forgery; the same frame made to carry this platform's
     * key id fails authentication.
     */
    @Test
    void aWrongPlatformKeyIsAnotherPlatformsFrameAndWithThisKeysIdFailsAuthentication() {
        PlatformKey other = PlatformKey.ofHex("11".repeat(32));
        int ours = Stacks.KEY.frameKeyBits();
        assertTrue(other.frameKeyBits() != ours, "the test's two keys have ids of their own");
        for (SecurityLayer.Protection p : List.of(SecurityLayer.Protection.HMAC, SecurityLayer.Protection.GCM_PLATFORM)) {
            LayerHarness a = agent("a@p", layer(p, other));
            LayerHarness b = agent("b@p", layer(p, Stacks.KEY));
            a.sendDown(body("x", "b@p"));
            byte[] frame = a.pollDown().dataCopy();
            deliver(frame, A_ADDR, b);
            assertNull(b.pollUp());
            assertEquals(Map.of("foreign-key", 1L), b.drops().snapshot(), p + ": skipped as another platform's");
            frame[3] = (byte) ((frame[3] & ~Frames.KEY_ID_MASK) | ours);
            deliver(frame, A_ADDR, b);
            assertNull(b.pollUp());
            assertEquals(1L, b.drops().get("bad-tag"), p + ": with this platform's key id, a forgery");
        }
    }

    /** Under CRC alone there is no key: its frames carry no key id, and one with a key id is malformed. */
    @Test
    void aFrameWithoutAKeyCarriesNoKeyId() {
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.CRC, null));
        LayerHarness b = agent("b@p", layer(SecurityLayer.Protection.CRC, null));
        a.sendDown(body("x", "b@p"));
        byte[] frame = a.pollDown().dataCopy();
        assertEquals(0, frame[3] & Frames.KEY_ID_MASK);
        frame[3] |= 0x08;
        deliver(frame, A_ADDR, b);
        assertEquals(1L, b.drops().get("malformed-frame"));
    }

    @Test
    void everyBitOfTheFrameIsCovered() {
        for (SecurityLayer.Protection p : new SecurityLayer.Protection[]{SecurityLayer.Protection.CRC,
                SecurityLayer.Protection.HMAC, SecurityLayer.Protection.GCM_PLATFORM}) {
            LayerHarness a = agent("a@p", layer(p, Stacks.KEY));
            LayerHarness b = agent("b@p", layer(p, Stacks.KEY));
            a.sendDown(body("every bit counts", "b@p"));
            byte[] wire = a.pollDown().dataCopy();
            for (int bit = 0; bit < wire.length * 8; bit++) {
                byte[] f = wire.clone();
                f[bit / 8] ^= (byte) (1 << (bit % 8));
                b.receiveUp(Envelope.incoming(A_ADDR, f, 0, f.length, 0));
                assertNull(b.pollUp(), p + ": flipping bit " + bit + " must be caught");
            }
            assertEquals(wire.length * 8L, b.drops().total(), p + ": every damaged frame counted " + b.drops());
        }
    }

    @Test
    void aFrameForAnotherAgentIsMisdirected() {
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.HMAC, Stacks.KEY));
        LayerHarness c = agent("c@p", layer(SecurityLayer.Protection.HMAC, Stacks.KEY));
        a.sendDown(body("for b", "b@p"));
        carry(a, A_ADDR, c);
        assertNull(c.pollUp());
        assertEquals(1, c.drops().get("misdirected"));
    }

    @Test
    void weakerProtectionThanRequiredIsRefused() {
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.CRC, null));
        LayerHarness b = agent("b@p", layer(SecurityLayer.Protection.GCM_PLATFORM, Stacks.KEY));
        a.sendDown(body("downgrade", "b@p"));
        carry(a, A_ADDR, b);
        assertNull(b.pollUp());
        assertEquals(1, b.drops().get("unprotected"));
    }

    @Test
    void classSevenAgreesAPairKeyInASignedHandshakeThenSends() {
        SecurityLayer sa = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        SecurityLayer sb = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        LayerHarness a = agent("a@p", sa);
        LayerHarness b = agent("b@p", sb);
        a.sendDown(body("after the handshake", "b@p"));
        assertEquals(1, a.downCount(), "only the hello leaves; the message waits");
        carry(a, A_ADDR, b);          // hello
        assertNull(b.pollUp(), "a hello is not a message");
        carry(b, B_ADDR, a);          // hello reply
        assertTrue(sa.hasSessionWith(Frames.id("b@p")), "the reply echoes a's challenge: a uses the key");
        assertFalse(sb.hasSessionWith(Frames.id("a@p")), "b waits for a to confirm it");
        carry(a, A_ADDR, b);          // the confirmation and the queued message
        assertTrue(sb.hasSessionWith(Frames.id("a@p")));
        assertEquals("after the handshake", text(b.pollUp()));
    }

    @Test
    void aHandshakeOlderThanItsWindowIsRefused() {
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        ManualClock later = new ManualClock(ManualClock.DEFAULT_EPOCH_MS + 60_000);
        LayerHarness b = new LayerHarness("b@p", later, layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        a.sendDown(body("x", "b@p"));
        carry(a, A_ADDR, b);
        assertEquals(1, b.drops().get("stale"));
    }

    @Test
    void anImpostorWithAnotherIdentityKeyIsAMasquerade() {
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        LayerHarness b = agent("b@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        a.sendDown(body("genuine", "b@p"));
        carry(a, A_ADDR, b);
        carry(b, B_ADDR, a);
        carry(a, A_ADDR, b);
        assertEquals("genuine", text(b.pollUp()));
        LayerHarness impostor = agent("a@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        impostor.sendDown(body("forged", "b@p"));
        carry(impostor, A_ADDR, b);
        assertEquals(1, b.drops().get("masquerade"));
        assertEquals(0, b.downCount(), "no reply to an impostor");
    }

    /** A frame claiming to be sealed with a pair key, from any id: 48 bytes anyone can send. */
    private static Envelope forged(long src, String to, long ctr) {
        byte[] f = new byte[48];
        Frames.putShort(f, 0, Frames.MAGIC);
        f[2] = (byte) Frames.VERSION;
        f[3] = (byte) (Frames.PROTECTION_GCM_PAIR | Stacks.KEY.frameKeyBits()); // the key's id is public
        Frames.putLong(f, 4, src);
        Frames.putLong(f, 12, Frames.id(to));
        Frames.putLong(f, 20, ctr);
        java.util.SplittableRandom noise = new java.util.SplittableRandom(src * 31 + ctr);
        for (int i = 28; i < f.length; i++) {
            f[i] = (byte) noise.nextInt(256); // a body and a tag no other frame had
        }
        return Envelope.incoming(new Address("attacker", 9), f, 0, f.length, 0);
    }

    @Test
    void aFrameFromAStrangerCostsNoStateNoSignatureAndAtMostOneSmallNoticeASecondOf64InAll() {
        SecurityLayer sb = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        LayerHarness b = agent("b@p", sb);
        java.util.SplittableRandom r = new java.util.SplittableRandom(1);
        for (int i = 0; i < 1_000; i++) {
            b.receiveUp(forged(r.nextLong(), "b@p", i));
        }
        for (int i = 0; i < 100; i++) {
            b.receiveUp(forged(42, "b@p", i));
        }
        assertEquals(1_100, b.drops().get("no-session-key"), b.drops().toString());
        assertEquals(0, sb.pairCount(), "no state for strangers");
        assertEquals(0, sb.hellosSent(), "no signature for strangers");
        assertEquals(SecurityLayer.REKEY_NOTICES_PER_SECOND, sb.rekeysSent(),
                "one notice per source id a second, and no more than 64 a second in all (1,001 before that cap)");
        Envelope e;
        int n = 0;
        while ((e = b.pollDown()) != null) {
            n++;
            assertTrue(e.length() <= 49, "a notice of 49 bytes for a frame of 48: " + e.length() + " bytes");
        }
        assertEquals(SecurityLayer.REKEY_NOTICES_PER_SECOND, n);
        clock.advanceMs(1_000);
        b.receiveUp(forged(42, "b@p", 100));
        b.receiveUp(forged(42, "b@p", 101));
        assertEquals(SecurityLayer.REKEY_NOTICES_PER_SECOND + 1, sb.rekeysSent(), "a second later, one more for id 42");
    }

    @Test
    void strangersDoNotPushRealPairsOut() {
        SecurityLayer sa = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        SecurityLayer sb = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        LayerHarness a = agent("a@p", sa);
        LayerHarness b = agent("b@p", sb);
        a.sendDown(body("first", "b@p"));
        carry(a, A_ADDR, b);
        carry(b, B_ADDR, a);
        carry(a, A_ADDR, b);
        assertEquals("first", text(b.pollUp()));
        for (int i = 0; i < 5_000; i++) {
            b.receiveUp(forged(1_000_000 + i, "b@p", i));
        }
        assertTrue(sb.hasSessionWith(Frames.id("a@p")), "the real pair is kept");
        while (b.pollDown() != null) {
            // the notices to the strangers' addresses
        }
        a.sendDown(body("second", "b@p"));
        carry(a, A_ADDR, b);
        assertEquals("second", text(b.pollUp()));
    }

    @Test
    void aRestartedAgentAsksItsPeerForANewHandshakeAndTheirMessagesFlowAgain() {
        // b keeps its identity across the restart, as a directory store does.
        Identity kept = IdentityStore.ephemeral().identityFor("b@p");
        IdentityStore bIdentity = name -> kept;
        SecurityLayer sa = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        LayerHarness a = agent("a@p", sa);
        LayerHarness b = agent("b@p", new SecurityLayer(new SecurityLayer.Config(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY, bIdentity, 30_000, 16)));
        a.sendDown(body("before", "b@p"));
        carry(a, A_ADDR, b);
        carry(b, B_ADDR, a);
        carry(a, A_ADDR, b);
        assertEquals("before", text(b.pollUp()));
        // b restarts with its identity and no session keys.
        SecurityLayer sb2 = new SecurityLayer(new SecurityLayer.Config(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY, bIdentity, 30_000, 16));
        LayerHarness b2 = agent("b@p", sb2);
        a.sendDown(body("lost in the restart", "b@p"));
        carry(a, A_ADDR, b2);
        assertEquals(1, b2.drops().get("no-session-key"));
        long hellos = sa.hellosSent();
        assertEquals(1, carry(b2, B_ADDR, a), "one notice");
        assertEquals(hellos + 1, sa.hellosSent(), "the notice made a start a handshake: " + a.drops());
        a.sendDown(body("after", "b@p"));
        carry(a, A_ADDR, b2);      // a's hello (the message waits for it)
        carry(b2, B_ADDR, a);      // b's reply
        carry(a, A_ADDR, b2);      // the message
        Envelope got = b2.pollUp();
        assertNotNull(got, "a: " + a.drops() + " b2: " + b2.drops());
        assertEquals("after", text(got));
    }

    /** A start of the agent with a kept identity: the same Ed25519 key, a new X25519 key for this run. */
    private static SecurityLayer keeping(Identity id) {
        Identity thisRun = Identity.fromSeed(id.seed(), new java.security.SecureRandom());
        return new SecurityLayer(new SecurityLayer.Config(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY, name -> thisRun, 30_000, 16));
    }

    private static byte[] next(LayerHarness from) {
        Envelope e = from.pollDown();
        assertNotNull(e, "a frame was expected");
        return e.dataCopy();
    }

    private static long resealCounter = 1L << 40;

    /**
     * What a holder of the platform key can do with a handshake frame it saw: open it and seal it
     * again under a fresh counter, so that it is no copy of a frame already taken.
     */
    static byte[] resealed(byte[] wire) {
        try {
            javax.crypto.spec.SecretKeySpec k = new javax.crypto.spec.SecretKeySpec(
                    Crypto.hkdf(Stacks.KEY.bytes(), null, "concord platform aead v1", 16), "AES");
            javax.crypto.Cipher c = javax.crypto.Cipher.getInstance("AES/GCM/NoPadding");
            byte[] nonce = new byte[12];
            System.arraycopy(wire, 4, nonce, 0, 4);
            System.arraycopy(wire, 20, nonce, 4, 8);
            c.init(javax.crypto.Cipher.DECRYPT_MODE, k, new javax.crypto.spec.GCMParameterSpec(128, nonce));
            c.updateAAD(wire, 0, Frames.HEADER_BYTES);
            byte[] plain = c.doFinal(wire, Frames.HEADER_BYTES, wire.length - Frames.HEADER_BYTES);
            byte[] out = java.util.Arrays.copyOf(wire, wire.length);
            Frames.putLong(out, 20, resealCounter++);
            System.arraycopy(out, 20, nonce, 4, 8);
            java.util.zip.CRC32C crc = new java.util.zip.CRC32C();
            crc.update(out, 0, Frames.HEADER_BYTES);
            crc.update(plain, 0, plain.length - Frames.CRC_BYTES);
            Frames.putInt(plain, plain.length - Frames.CRC_BYTES, (int) crc.getValue());
            c.init(javax.crypto.Cipher.ENCRYPT_MODE, k, new javax.crypto.spec.GCMParameterSpec(128, nonce));
            c.updateAAD(out, 0, Frames.HEADER_BYTES);
            c.doFinal(plain, 0, plain.length, out, Frames.HEADER_BYTES);
            return out;
        } catch (java.security.GeneralSecurityException e) {
            throw new AssertionError(e);
        }
    }

    private static void deliver(byte[] wire, Address from, LayerHarness to) {
        to.receiveUp(Envelope.incoming(from, wire, 0, wire.length, 0));
    }

    /** a and b shake hands and a's first message arrives; returns a's hello as it went on the wire. */
    private static byte[] shakeHands(LayerHarness a, LayerHarness b, String text) {
        a.sendDown(body(text, "b@p"));
        byte[] hello = next(a);
        deliver(hello, A_ADDR, b);
        carry(b, B_ADDR, a);
        carry(a, A_ADDR, b);
        assertEquals(text, text(b.pollUp()));
        return hello;
    }

    @Test
    void aHelloReplayedFromAnEarlierRunOfThePeerChangesNothing() {
        Identity aId = IdentityStore.ephemeral().identityFor("a@p");
        LayerHarness b = agent("b@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        byte[] oldHello = shakeHands(agent("a@p", keeping(aId)), b, "first run");
        // a restarts with its identity and a new X25519 key, and shakes hands again.
        LayerHarness a2 = agent("a@p", keeping(aId));
        shakeHands(a2, b, "second run");
        clock.advanceMs(5_000); // well inside the handshake window
        deliver(resealed(oldHello), new Address("attacker", 9), b);
        while (b.pollDown() != null) {
            // b's answer to the replayed hello: a key nobody can confirm
        }
        a2.sendDown(body("after the replay", "b@p"));
        carry(a2, A_ADDR, b);
        Envelope got = b.pollUp();
        assertNotNull(got, "the replayed hello broke the pair: " + b.drops());
        assertEquals("after the replay", text(got));
        carry(b, B_ADDR, a2);
        assertEquals(0, a2.upCount(), "and a2 got nothing it did not ask for: " + a2.drops());
    }

    @Test
    void aCopyOfAHelloWhoseKeyIsInUseIsDroppedUnanswered() {
        SecurityLayer sb = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        LayerHarness b = agent("b@p", sb);
        byte[] hello = shakeHands(a, b, "genuine");
        long signed = sb.hellosSent();
        deliver(resealed(hello), A_ADDR, b);
        assertEquals(1, b.drops().get("replayed-handshake"), b.drops().toString());
        assertEquals(0, b.downCount(), "no answer to a replay");
        assertEquals(signed, sb.hellosSent(), "no signature for a replay");
        a.sendDown(body("still flowing", "b@p"));
        carry(a, A_ADDR, b);
        assertEquals("still flowing", text(b.pollUp()));
    }

    @Test
    void aReplyToNoHelloUnderWayIsDropped() {
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        LayerHarness b = agent("b@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        a.sendDown(body("one", "b@p"));
        carry(a, A_ADDR, b);
        byte[] reply = next(b);
        deliver(reply, B_ADDR, a);
        carry(a, A_ADDR, b);
        assertEquals("one", text(b.pollUp()));
        deliver(resealed(reply), B_ADDR, a);
        // A second reply to the hello answered already: the peer answered a retried hello twice,
        // or someone replays it; either way it changes nothing, and is counted apart (not warned).
        assertEquals(1, a.drops().get("handshake-late"), a.drops().toString());
        a.sendDown(body("two", "b@p"));
        carry(a, A_ADDR, b);
        assertEquals("two", text(b.pollUp()));
    }

    @Test
    void framesThatKeepFailingAuthenticationBringANewHandshake() {
        SecurityLayer sa = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        SecurityLayer sb = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        LayerHarness a = agent("a@p", sa);
        LayerHarness b = agent("b@p", sb);
        shakeHands(a, b, "paired");
        // Three frames in a row in a's name that b cannot open (keys that went apart, or forgeries).
        for (int i = 0; i < 3; i++) {
            b.receiveUp(forged(Frames.id("a@p"), "b@p", 1_000 + i));
        }
        assertEquals(3, b.drops().get("bad-tag"));
        Envelope notice = b.pollDown();
        assertNotNull(notice, "b asks a for a new handshake");
        assertEquals(A_ADDR, notice.destination(), "at the address a is known at, not where the frames came from");
        byte[] wire = notice.dataCopy();
        long hellos = sa.hellosSent();
        deliver(wire, B_ADDR, a);
        assertEquals(hellos + 1, sa.hellosSent(), "a starts a handshake");
        a.sendDown(body("on a new key", "b@p"));
        carry(a, A_ADDR, b);
        carry(b, B_ADDR, a);
        carry(a, A_ADDR, b);
        assertEquals("on a new key", text(b.pollUp()));
        deliver(resealed(wire), B_ADDR, a);
        assertEquals(1, a.drops().get("rekey-limit"), "a copy of the notice within a second: " + a.drops());
    }

    @Test
    void twoAgentsThatStartTogetherAgreeOnOneKey() {
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        LayerHarness b = agent("b@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        a.sendDown(body("from a", "b@p"));
        Envelope toA = body("from b", "a@p");
        toA.setDestination(A_ADDR);
        b.sendDown(toA);
        for (int round = 0; round < 4; round++) {
            carry(a, A_ADDR, b);
            carry(b, B_ADDR, a);
        }
        assertEquals("from a", text(b.pollUp()));
        assertEquals("from b", text(a.pollUp()));
        assertEquals(1, a.drops().get("crossed-handshake") + b.drops().get("crossed-handshake"),
                "one of the two hellos gives way: " + a.drops() + " " + b.drops());
    }

    @Test
    void newNamesBeyondThePinLimitAreRefusedAndNoPinIsForgotten() {
        SecurityLayer sb = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        sb.helloRate(Pins.MAX_PINS * 2, 1); // the hello rate limit is another test's
        LayerHarness b = agent("b@p", sb);
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        shakeHands(a, b, "pinned first");
        // A holder of the platform key floods handshakes under new names, each with its own identity.
        Identity one = IdentityStore.ephemeral().identityFor("x");
        for (int i = 0; i < Pins.MAX_PINS + 10; i++) {
            LayerHarness m = agent("m" + i + "@p", keeping(one));
            m.sendDown(body("x", "b@p"));
            deliver(next(m), new Address("attacker", 9), b);
            while (b.pollDown() != null) {
                // the replies
            }
        }
        assertEquals(11, b.drops().get("pin-limit"), "the new names beyond the limit (a holds one pin): " + b.drops());
        // a's pin is still there: an impostor with another identity under a's name is refused.
        LayerHarness impostor = agent("a@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        impostor.sendDown(body("forged", "b@p"));
        carry(impostor, A_ADDR, b);
        assertEquals(1, b.drops().get("masquerade"));
    }

    @Test
    void theConfigurationRefusesWhatCannotWork() {
        assertThrows(IllegalArgumentException.class,
                () -> new SecurityLayer.Config(SecurityLayer.Protection.HMAC, null, null, 1, 1));
        assertThrows(IllegalArgumentException.class,
                () -> new SecurityLayer.Config(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY, null, 1, 1));
    }

    @Test
    void hellosBeyondTheBurstAndTheRateAreDroppedBeforeAnySignatureWork() {
        SecurityLayer sb = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
        LayerHarness b = agent("b@p", sb);
        Identity one = IdentityStore.ephemeral().identityFor("x");
        int n = Handshake.HELLO_BURST + 100;
        int replies = 0;
        for (int i = 0; i < n; i++) {
            LayerHarness m = agent("m" + i + "@p", keeping(one));
            m.sendDown(body("x", "b@p"));
            deliver(next(m), new Address("attacker", 9), b);
            while (b.pollDown() != null) {
                replies++;
            }
        }
        assertEquals(Handshake.HELLO_BURST, replies, "a signed reply to each hello of the burst, and no more");
        assertEquals(100, b.drops().get("handshake-limit"));
        b.advanceMs(1_000);
        for (int i = 0; i < 100; i++) {
            LayerHarness m = agent("late" + i + "@p", keeping(one));
            m.sendDown(body("x", "b@p"));
            deliver(next(m), new Address("attacker", 9), b);
            while (b.pollDown() != null) {
                replies++;
            }
        }
        assertEquals(Handshake.HELLO_BURST + Handshake.HELLOS_PER_SECOND, replies, "then the rate");
        // Once the flood has passed, a real agent gets in.
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY));
        b.advanceMs(1_000);
        shakeHands(a, b, "after the flood");
    }
    @Test
    void theAgentsOfOneLoopTogetherAnswerNoMoreHellosThanTheLoopsBudget() {
        // Five agents on one loop (they share its limits), each able to answer more than the loop may.
        LoopLimits loop = new LoopLimits();
        List<LayerHarness> victims = new ArrayList<>();
        for (int v = 0; v < 5; v++) {
            SecurityLayer sv = layer(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY);
            sv.helloRate(1_000, 1_000);
            victims.add(LayerHarness.builder().name("v" + v + "@p").clock(clock).offer(LoopLimits.class, loop)
                    .build(sv));
        }
        Identity one = IdentityStore.ephemeral().identityFor("x");
        int replies = 0;
        for (int i = 0; i < 1_500; i++) {
            LayerHarness victim = victims.get(i % victims.size());
            String to = "v" + (i % victims.size()) + "@p";
            LayerHarness m = agent("m" + i + "@p", keeping(one));
            m.sendDown(body("x", to));
            deliver(next(m), new Address("attacker", 9), victim);
            while (victim.pollDown() != null) {
                replies++;
            }
        }
        assertEquals(Handshake.LOOP_HELLO_BURST, replies, "the loop's burst, though each agent alone would answer 300");
        long limited = 0;
        for (LayerHarness v : victims) {
            limited += v.drops().get("handshake-limit");
        }
        assertEquals(1_500 - Handshake.LOOP_HELLO_BURST, limited);
    }
}
