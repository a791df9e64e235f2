package io.concord.layers;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.testkit.Medium;
import io.concord.layers.frame.Frames;
import io.concord.layers.security.PlatformKey;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicInteger;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The seven threats of EN 50159 (open transmission), each injected between two agents with the
 * class-7 stack, on the virtual network and on real UDP through an injecting relay. In every case
 * B receives exactly what A sent, once, in order, unchanged, and never a repeated, inserted,
 * corrupted, stale or forged message; the drop counters show the defence that acted.
 */
class ThreatsTest {
    static final int N = 40;

    enum Where { VIRTUAL, REAL_UDP }

    private static ThreatWorld world(Where where, Medium medium, long windowMs) throws Exception {
        return where == Where.VIRTUAL ? new ThreatWorld.Virtual(medium, windowMs) : new ThreatWorld.RealUdp(medium, windowMs);
    }

    /** A sends N messages through the medium; B must get exactly them. */
    private static Map<String, Long> exchange(ThreatWorld w) {
        w.send(w.sender, w.receiverAsSeenByA(), ThreatWorld.contents(N));
        assertTrue(w.awaitReceived(N), "B received " + w.received().size() + " of " + N + "; drops " + w.receiverDrops());
        w.settle(3 * w.windowMs);
        assertEquals(ThreatWorld.expected("a", N), w.received(), "exactly what A sent, once, in order, unchanged");
        return w.receiverDrops();
    }

    private static long count(Map<String, Long> drops, String... reasons) {
        long n = 0;
        for (String r : reasons) {
            n += drops.getOrDefault(r, 0L);
        }
        return n;
    }

    @ParameterizedTest
    @EnumSource(Where.class)
    void repetition(Where where) throws Exception {
        List<byte[]> captured = new ArrayList<>();
        Medium repeat = (from, to, d, out) -> {
            captured.add(d.clone());
            out.deliver(0, d);
            out.deliver(0, d);
            out.deliver(1_000_000, d);
            // Replay an older captured frame too, well inside the acceptance window.
            out.deliver(2_000_000, captured.get(captured.size() / 2));
        };
        try (ThreatWorld w = world(where, repeat, 2_000)) {
            Map<String, Long> drops = exchange(w);
            assertTrue(count(drops, "copy", "repeated") >= N, "repetitions were dropped: " + drops);
        }
    }

    @ParameterizedTest
    @EnumSource(Where.class)
    void deletion(Where where) throws Exception {
        AtomicInteger n = new AtomicInteger();
        Medium delete = (from, to, d, out) -> {
            if (n.incrementAndGet() % 3 != 0) {
                out.deliver(0, d);
            }
        };
        try (ThreatWorld w = world(where, delete, 2_000)) {
            exchange(w);
            assertTrue(n.get() > N, "frames went through the medium, a third of them deleted: " + n.get());
        }
    }

    @ParameterizedTest
    @EnumSource(Where.class)
    void insertion(Where where) throws Exception {
        SplittableRandom random = new SplittableRandom(5);
        Medium insert = (from, to, d, out) -> {
            out.deliver(0, d);
            byte[] junk = new byte[1 + random.nextInt(600)];
            random.nextBytes(junk);
            out.deliver(0, junk);
            if (d.length > Frames.HEADER_BYTES + 20) {
                byte[] forged = d.clone();
                for (int i = Frames.HEADER_BYTES; i < forged.length; i++) {
                    forged[i] = (byte) random.nextInt(256);
                }
                Frames.putLong(forged, 20, random.nextLong());
                out.deliver(0, forged);
                byte[] misdirected = d.clone();
                Frames.putLong(misdirected, 12, random.nextLong());
                out.deliver(0, misdirected);
                byte[] outsider = d.clone();
                Frames.putLong(outsider, 4, random.nextLong());
                out.deliver(0, outsider);
            }
        };
        try (ThreatWorld w = world(where, insert, 2_000)) {
            Map<String, Long> drops = exchange(w);
            assertTrue(count(drops, "malformed-frame") > 0, "random datagrams were refused: " + drops);
            assertTrue(count(drops, "bad-tag", "no-session-key") > 0, "forged frames failed authentication: " + drops);
            assertTrue(count(drops, "misdirected") > 0, "frames for another agent were refused: " + drops);
        }
    }

    @ParameterizedTest
    @EnumSource(Where.class)
    void resequence(Where where) throws Exception {
        AtomicInteger n = new AtomicInteger();
        // Frames leave in groups of five, each group in reverse order.
        Medium reverse = (from, to, d, out) -> out.deliver((5 - n.getAndIncrement() % 5) * 2_000_000L, d);
        try (ThreatWorld w = world(where, reverse, 2_000)) {
            exchange(w);
        }
    }

    @ParameterizedTest
    @EnumSource(Where.class)
    void corruption(Where where) throws Exception {
        SplittableRandom random = new SplittableRandom(9);
        AtomicInteger n = new AtomicInteger();
        Medium corrupt = (from, to, d, out) -> {
            if (n.incrementAndGet() % 2 == 0) {
                int bit = random.nextInt(d.length * 8);
                d[bit / 8] ^= (byte) (1 << (bit % 8));
            }
            out.deliver(0, d);
        };
        try (ThreatWorld w = world(where, corrupt, 2_000)) {
            Map<String, Long> drops = exchange(w);
            assertTrue(count(drops, "bad-tag", "corrupt", "malformed-frame", "misdirected", "unprotected", "no-session-key") > 0,
                    "corrupted frames were dropped: " + drops);
        }
    }

    @ParameterizedTest
    @EnumSource(Where.class)
    void delay(Where where) throws Exception {
        long windowMs = 300;
        AtomicInteger n = new AtomicInteger();
        byte[][] last = {null};
        boolean[] held = {false};
        // Every fifth frame, both its copies, is held back three windows: it must arrive stale and be
        // refused, while the sequence layer gets its content again in time.
        Medium hold = (from, to, d, out) -> {
            if (!java.util.Arrays.equals(d, last[0])) {
                held[0] = n.incrementAndGet() % 5 == 0;
                last[0] = d.clone();
            }
            out.deliver(held[0] ? 3 * windowMs * 1_000_000L : 0, d);
        };
        try (ThreatWorld w = world(where, hold, windowMs)) {
            Map<String, Long> drops = exchange(w);
            assertTrue(count(drops, "stale") > 0, "delayed frames were refused as stale: " + drops);
        }
    }

    @ParameterizedTest
    @EnumSource(Where.class)
    void masquerade(Where where) throws Exception {
        try (ThreatWorld w = world(where, Medium.PASS, 2_000)) {
            // A talks to B first, so B knows A's identity.
            w.send(w.sender, w.receiverAsSeenByA(), "m0");
            assertTrue(w.awaitReceived(1));
            AID aAsKnown = w.received().isEmpty() ? null : w.receiver.got.peek().getSender();

            // 1. A member of the platform signs its own frames but claims to be A in the message.
            ThreatWorld.Puppet member = new ThreatWorld.Puppet();
            w.startOnM("m", member, w.stack());
            member.runtime().execute(() -> member.send(new AclMessage(Performative.INFORM)
                    .setSender(aAsKnown).addReceiver(w.receiverDirect()).setContent("forged by a member")));

            // 2. An impostor takes A's very name, with an identity key of its own.
            ThreatWorld.Puppet impostor = new ThreatWorld.Puppet();
            w.startOnM2("a", impostor, w.stack());
            impostor.runtime().execute(() -> impostor.send(new AclMessage(Performative.INFORM)
                    .addReceiver(w.receiverDirect()).setContent("forged by an impostor")));

            // 3. An outsider without the platform key takes A's name too.
            ThreatWorld.Puppet outsider = new ThreatWorld.Puppet();
            w.startOnM3("a", outsider, w.stackWithKey(PlatformKey.ofHex("ff".repeat(32))));
            outsider.runtime().execute(() -> outsider.send(new AclMessage(Performative.INFORM)
                    .addReceiver(w.receiverDirect()).setContent("forged by an outsider")));

            w.awaitDrops(() -> count(w.receiverDrops(), "identification") > 0
                    && count(w.receiverDrops(), "masquerade") > 0 && count(w.receiverDrops(), "bad-tag") > 0);
            w.send(w.sender, w.receiverAsSeenByA(), ThreatWorld.contents(N));
            assertTrue(w.awaitReceived(N + 1));
            w.settle(100);
            List<String> expected = new ArrayList<>(List.of("a:m0"));
            expected.addAll(ThreatWorld.expected("a", N));
            assertEquals(expected, w.received(), "only A's own messages reached B");
            Map<String, Long> drops = w.receiverDrops();
            assertTrue(count(drops, "identification") > 0, "the member's forged sender was refused: " + drops);
            assertTrue(count(drops, "masquerade") > 0, "the impostor's handshake was refused: " + drops);
            assertTrue(count(drops, "bad-tag") > 0, "the outsider's frames failed authentication: " + drops);
        }
    }
}
