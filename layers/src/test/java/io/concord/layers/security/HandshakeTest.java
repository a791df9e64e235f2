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
