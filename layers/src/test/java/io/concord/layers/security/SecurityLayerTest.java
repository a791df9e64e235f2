package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;
import io.concord.core.testkit.LayerHarness;
import io.concord.core.time.ManualClock;
import io.concord.layers.Stacks;
import io.concord.layers.frame.Frames;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;

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

    @Test
    void aWrongPlatformKeyFailsAuthentication() {
        LayerHarness a = agent("a@p", layer(SecurityLayer.Protection.GCM_PLATFORM, PlatformKey.ofHex("11".repeat(32))));
        LayerHarness b = agent("b@p", layer(SecurityLayer.Protection.GCM_PLATFORM, Stacks.KEY));
        a.sendDown(body("x", "b@p"));
        carry(a, A_ADDR, b);
        assertNull(b.pollUp());
        assertEquals(1, b.drops().get("bad-tag"));
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
        assertTrue(sa.hasSessionWith(Frames.id("b@p")));
        assertTrue(sb.hasSessionWith(Frames.id("a@p")));
        carry(a, A_ADDR, b);          // the queued message
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

    @Test
    void theConfigurationRefusesWhatCannotWork() {
        assertThrows(IllegalArgumentException.class,
                () -> new SecurityLayer.Config(SecurityLayer.Protection.HMAC, null, null, 1, 1));
        assertThrows(IllegalArgumentException.class,
                () -> new SecurityLayer.Config(SecurityLayer.Protection.GCM_PAIR, Stacks.KEY, null, 1, 1));
    }
}
