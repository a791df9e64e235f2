package io.concord.layers.security;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.net.Address;
import io.concord.testkit.LayerHarness;
import io.concord.core.time.ManualClock;
import io.concord.core.time.internal.TokenBucket;
import io.concord.layers.Stacks;
import io.concord.layers.frame.Frames;
import io.concord.layers.security.SecurityLayer.Protection;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The handshake alone, for two agents: each has its handshake and its frame sealer, and a
 * {@link LayerHarness} around a probe layer gives the handshake its context (time, timers, drops,
 * the way down). The test opens the frames between them as the security layer would.
 */
class HandshakeTest {
    private final ManualClock clock = new ManualClock();
    private final Side a = new Side("a@p", new Address("h", 1));
    private final Side b = new Side("b@p", new Address("h", 2));

    /** Hands the layer's context to the test. */
    private static final class Probe extends Layer {
        LayerContext ctx;

        @Override
        public void init(LayerContext c) {
            ctx = c;
        }
    }

    private final class Side {
        final String name;
        final Address at;
        final long id;
        final Probe probe = new Probe();
        final LayerHarness harness;
        final FrameSealer sealer;
        final Handshake handshake;

        Side(String name, Address at) {
            this.name = name;
            this.at = at;
            this.id = Frames.id(name);
            this.harness = LayerHarness.builder().name(name).clock(clock).build(probe);
            SecurityLayer.Config config = new SecurityLayer.Config(Protection.GCM_PAIR, Stacks.KEY, IdentityStore.ephemeral(),
                    30_000, 16);
            this.sealer = new FrameSealer(Protection.GCM_PAIR, Stacks.KEY, id, 1, true, true);
            this.handshake = new Handshake(config, sealer, id, name, config.identities().identityFor(name),
                    new TokenBucket(Handshake.HELLO_BURST, Handshake.HELLOS_PER_SECOND), null);
        }

        void send(String text, Side to) {
            byte[] t = text.getBytes(StandardCharsets.UTF_8);
            byte[] buf = new byte[Frames.HEADROOM + t.length];
            System.arraycopy(t, 0, buf, Frames.HEADROOM, t.length);
            handshake.onDown(probe.ctx, Envelope.control(to.id, to.at, buf, Frames.HEADROOM, t.length));
        }

        /** Opens every frame this side sent and hands it to the other: handshake frames to its handshake, data to the test. */
        StringBuilder carryTo(Side to) {
            StringBuilder delivered = new StringBuilder();
            Envelope e;
            while ((e = harness.pollDown()) != null) {
                byte[] w = e.dataCopy();
                Envelope in = Envelope.incoming(at, w, 0, w.length, 0);
                long src = Frames.getLong(w, 4);
                long ctr = Frames.getLong(w, 20);
                boolean handshakeFrame = (w[3] & Frames.FLAG_HANDSHAKE) != 0;
                byte[] body = handshakeFrame ? to.sealer.openWithPlatformKey(src, ctr, w, 0, w.length)
                        : to.handshake.open(to.probe.ctx, in, src, ctr, w, 0, w.length);
                if (body == null) {
                    continue;
                }
                int bodyLen = body.length - Frames.CRC_BYTES;
                assertTrue(to.sealer.safetyCodeMatches(w, 0, body, 0, bodyLen));
                if (handshakeFrame) {
                    to.handshake.onHandshake(to.probe.ctx, in, src, body, 0, bodyLen);
                } else {
                    delivered.append(new String(body, 0, bodyLen, StandardCharsets.UTF_8));
                }
            }
            return delivered;
        }

        long drops(String reason) {
            return harness.drops().get(reason);
        }

        /** The frames this side has sent and nobody has carried yet, in order. */
        java.util.List<Envelope> sent() {
            java.util.List<Envelope> out = new java.util.ArrayList<>();
            for (Envelope e; (e = harness.pollDown()) != null; ) {
                out.add(e);
            }
            return out;
        }

        /** Hands one handshake frame this side sent to the other's handshake. */
        void deliver(Envelope e, Side to) {
            byte[] w = e.dataCopy();
            Envelope in = Envelope.incoming(at, w, 0, w.length, 0);
            byte[] body = to.sealer.openWithPlatformKey(Frames.getLong(w, 4), Frames.getLong(w, 20), w, 0, w.length);
            to.handshake.onHandshake(to.probe.ctx, in, Frames.getLong(w, 4), body, 0, body.length - Frames.CRC_BYTES);
        }
    }

    /**
     * Two hellos crossed: the smaller id's handshake goes on, so the larger answers it, and its own
     * hello, still under way, reaches the smaller one only after the smaller has the key (the wire
     * reordered it, or it was a retry). The smaller answers it; that answer reaches the larger after
     * the confirmation made its own hello needless. It is late, not a replay: counted as
     * handshake-late (logged at debug), so that a clean start warns of nothing.
     */
    @Test
    void aReplyToAHelloTheCrossedHandshakeMadeNeedlessIsLateNotAReplay() {
        Side small = a.id < b.id ? a : b;
        Side large = small == a ? b : a;
        small.send("from small", large);
        large.send("from large", small);
        java.util.List<Envelope> helloSmall = small.sent();
        java.util.List<Envelope> helloLarge = large.sent();
        assertEquals(1, helloSmall.size());
        assertEquals(1, helloLarge.size());
        small.deliver(helloSmall.get(0), large);          // the larger answers the smaller's hello
        for (Envelope e : handshakes(large.sent())) {
            large.deliver(e, small);                        // its reply: the smaller uses the key, confirms
        }
        for (Envelope e : handshakes(small.sent())) {
            small.deliver(e, large);                        // the confirmation: the larger uses the key
        }
        assertTrue(small.handshake.hasSessionWith(large.id) && large.handshake.hasSessionWith(small.id), "one key, both ends");
        large.deliver(helloLarge.get(0), small);          // the larger's own hello, late
        for (Envelope e : handshakes(small.sent())) {
            small.deliver(e, large);                        // the smaller's answer to it
        }
        assertEquals(0, large.drops("replayed-handshake"), large.harness.drops().toString());
        assertEquals(1, large.drops("handshake-late"), large.harness.drops().toString());
    }

    private static java.util.List<Envelope> handshakes(java.util.List<Envelope> frames) {
        return frames.stream().filter(e -> (e.dataCopy()[3] & Frames.FLAG_HANDSHAKE) != 0).toList();
    }

    @Test
    void aHelloAReplyAndAConfirmationGiveBothEndsOneKeyAndTheMessageThatWaitedGoes() {
        a.send("first", b);
        assertFalse(a.handshake.hasSessionWith(b.id), "the message waits for the key");
        assertEquals("", a.carryTo(b).toString(), "a hello, no data");
        assertEquals("", b.carryTo(a).toString(), "a signed reply");
        assertTrue(a.handshake.hasSessionWith(b.id), "the reply's echo proves it fresh: a uses the key");
        assertFalse(b.handshake.hasSessionWith(a.id), "b waits for the confirmation");
        assertEquals("first", a.carryTo(b).toString(), "the confirmation, then the message under the pair key");
        assertTrue(b.handshake.hasSessionWith(a.id), "b uses the key once a proved it holds it");
        b.send("back", a);
        assertEquals("back", b.carryTo(a).toString(), "no handshake the other way");
        assertEquals(2, a.handshake.hellosSent() + b.handshake.hellosSent(), "one hello, one reply: two signatures");
    }

    @Test
    void anUnansweredHelloIsRepeatedWithBackOffThenItsMessagesAreDroppedAndCounted() {
        a.send("lost", b);
        int hellos = 1;
        a.harness.pollDown();
        for (long waitMs : new long[] {100, 200, 400, 800, 1_600, 2_000, 2_000, 2_000, 2_000}) {
            a.harness.advanceMs(waitMs - 1);
            assertEquals(0, a.harness.downCount(), "not before " + waitMs + " ms");
            a.harness.advanceMs(1);
            assertNotNull(a.harness.pollDown(), "again after " + waitMs + " ms");
            hellos++;
        }
        assertEquals(10, hellos);
        a.harness.advanceMs(2_000);
        assertEquals(0, a.harness.downCount(), "ten hellos, then no more");
        assertEquals(1, a.drops("no-handshake"), "the waiting message is dropped, counted");
    }

    @Test
    void aFrameUnderAPairKeyTheReceiverDoesNotHoldCostsNoStateAndOneNotice() {
        a.send("first", b);
        a.carryTo(b);
        b.carryTo(a);
        a.carryTo(b);
        Side b2 = new Side("b@p", new Address("h", 2)); // b restarted: it holds no key
        a.send("after the restart", b);
        assertEquals("", a.carryTo(b2).toString());
        assertEquals(1, b2.drops("no-session-key"));
        assertEquals(0, b2.handshake.pairCount(), "no state for an unauthenticated frame");
        assertEquals(1, b2.handshake.rekeysSent(), "a rekey notice asks the sender for a handshake");
        assertEquals(0, b2.handshake.hellosSent(), "and nothing signed");
    }

    @Test
    void aCopyOfAHelloWhoseKeyIsInUseIsDroppedUnanswered() {
        a.send("first", b);
        byte[] hello = a.harness.pollDown().dataCopy();
        Envelope in = Envelope.incoming(a.at, hello, 0, hello.length, 0);
        byte[] body = b.sealer.openWithPlatformKey(a.id, Frames.getLong(hello, 20), hello, 0, hello.length);
        b.handshake.onHandshake(b.probe.ctx, in, a.id, body, 0, body.length - Frames.CRC_BYTES);
        b.carryTo(a);
        a.carryTo(b);
        assertTrue(b.handshake.hasSessionWith(a.id));
        long signed = b.handshake.hellosSent();
        b.handshake.onHandshake(b.probe.ctx, in, a.id, body, 0, body.length - Frames.CRC_BYTES);
        assertEquals(1, b.drops("replayed-handshake"));
        assertEquals(signed, b.handshake.hellosSent(), "no signature for a replay");
    }
}
