package io.concord.layers;

import io.concord.layers.defence.Defence;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.testkit.Medium;
import io.concord.layers.frame.Frames;
import io.concord.layers.security.PlatformKey;
import io.concord.layers.Profile;
import org.junit.jupiter.params.ParameterizedTest;
import org.opentest4j.AssertionFailedError;
import org.junit.jupiter.params.provider.EnumSource;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.zip.CRC32C;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicInteger;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The seven threats of EN 50159 (open transmission), each injected between two agents, on the
 * virtual network and on real UDP through an injecting relay. In every case B receives exactly what
 * A sent, once, in order, unchanged, and never a repeated, inserted, corrupted, stale or forged
 * message.
 *
 * <p>Each test exercises the defence it names, past the others: a replay comes after the tag
 * memory has forgotten it, so that the sequence window must act; a deleted frame loses both its
 * copies, so that it must be retransmitted; corruption is shown on the CRC alone (profile CLOSED),
 * insertion on the HMAC tag (class 3), delay on frames that can only arrive late. And each test
 * runs again on the virtual network on stacks built without that defence ({@link Defence}) and must
 * then fail.
 */
class ThreatsTest {
    static final int N = 40;

    enum Where { VIRTUAL, REAL_UDP }

    @FunctionalInterface
    interface Scenario {
        void run(Where where, Set<Defence> off) throws Exception;
    }

    /**
     * Runs the scenario with every defence on; then, on the virtual network, with one defence off,
     * where it must fail: the test is shown to depend on that defence.
     */
    private static void withDefenceOff(Where where, Defence defence, Scenario scenario) throws Exception {
        scenario.run(where, Set.of());
        if (where == Where.VIRTUAL) {
            // The same scenario on stacks built without that one defence (their builder's option,
            // nothing global): it must fail.
            AssertionFailedError e = assertThrows(AssertionFailedError.class, () -> scenario.run(where, EnumSet.of(defence)),
                    "with its defence switched off, the threat reaches B");
            assertTrue(e.getMessage().startsWith("exactly what A sent") || e.getMessage().startsWith("only A's own"),
                    "and it is what B receives that is wrong, not only a counter: " + e.getMessage());
        }
    }

    private static ThreatWorld world(Where where, Medium medium, long windowMs, Profile profile, Set<Defence> off) throws Exception {
        return where == Where.VIRTUAL ? new ThreatWorld.Virtual(medium, windowMs, profile, null, off)
                : new ThreatWorld.RealUdp(medium, windowMs, profile, null, off);
    }

    /** A sends the contents through the medium; B must get exactly {@code expected}. */
    private static Map<String, Long> exchange(ThreatWorld w, String[] contents, List<String> expected) {
        w.send(w.sender, w.receiverAsSeenByA(), contents);
        boolean all = w.awaitReceived(expected.size());
        w.settle(3 * w.windowMs);
        assertEquals(expected, w.received(), "exactly what A sent, once, in order, unchanged (all in: " + all
                + "); drops " + w.receiverDrops());
        return w.receiverDrops();
    }

    private static Map<String, Long> exchange(ThreatWorld w) {
        return exchange(w, ThreatWorld.contents(N), ThreatWorld.expected("a", N));
    }

    private static long count(Map<String, Long> drops, String... reasons) {
        long n = 0;
        for (String r : reasons) {
            n += drops.getOrDefault(r, 0L);
        }
        return n;
    }

    /** Calls {@code each} once per distinct frame (a frame's copies are identical bytes): index, and whether a copy. */
    private static Medium perFrame(FrameRule rule) {
        byte[][] last = {null};
        int[] index = {-1};
        return (from, to, d, out) -> {
            boolean copy = Arrays.equals(d, last[0]);
            if (!copy) {
                index[0]++;
                last[0] = d.clone();
            }
            rule.apply(index[0], copy, d, out);
        };
    }

    @FunctionalInterface
    interface FrameRule {
        void apply(int index, boolean copy, byte[] d, Medium.Emitter out);
    }

    /** Sets a frame's CRC-32C again after its body was changed (anyone can: the code is no secret). */
    private static void recomputeCrc(byte[] f, int tagBytes) {
        int at = f.length - tagBytes - Frames.CRC_BYTES;
        CRC32C crc = new CRC32C();
        crc.update(f, 0, at);
        Frames.putInt(f, at, (int) crc.getValue());
    }

    // ---- repetition: the sequence window -----------------------------------------------------------

    @ParameterizedTest
    @EnumSource(Where.class)
    void repetition(Where where) throws Exception {
        withDefenceOff(where, Defence.SEQUENCE_WINDOW, ThreatsTest::repetition0);
    }

    private static void repetition0(Where where, Set<Defence> off) throws Exception {
        int n = 100;
        List<byte[]> captured = new ArrayList<>();
        Medium repeat = (from, to, d, out) -> {
            captured.add(d.clone());
            out.deliver(0, d);
            out.deliver(0, d); // an immediate copy: the tag memory's
            if (captured.size() == 150) {
                // Every frame so far again, inside the acceptance window: the first ones are older
                // than the 64 tags remembered, so only the sequence window can refuse them.
                for (byte[] old : List.copyOf(captured)) {
                    out.deliver(1_000_000, old);
                }
            }
        };
        try (ThreatWorld w = world(where, repeat, 2_000, Profile.CLASS_7, off)) {
            Map<String, Long> drops = exchange(w, ThreatWorld.contents(n), ThreatWorld.expected("a", n));
            assertTrue(count(drops, "repeated") > 0, "the sequence window refused replays: " + drops);
        }
    }

    // ---- deletion: retransmission ---------------------------------------------------------------------

    @ParameterizedTest
    @EnumSource(Where.class)
    void deletion(Where where) throws Exception {
        withDefenceOff(where, Defence.RETRANSMISSION, ThreatsTest::deletion0);
    }

    private static void deletion0(Where where, Set<Defence> off) throws Exception {
        AtomicInteger deleted = new AtomicInteger();
        // Every third frame is lost with both its copies: only retransmission brings its message.
        Medium delete = perFrame((i, copy, d, out) -> {
            if (i % 3 == 2) {
                deleted.incrementAndGet();
            } else {
                out.deliver(0, d);
            }
        });
        try (ThreatWorld w = world(where, delete, 2_000, Profile.CLASS_7, off)) {
            exchange(w);
            assertTrue(deleted.get() > N / 2, "frames were deleted, copies and all: " + deleted.get());
        }
    }

    // ---- insertion: the authentication tag ------------------------------------------------------------

    @ParameterizedTest
    @EnumSource(Where.class)
    void insertion(Where where) throws Exception {
        withDefenceOff(where, Defence.HMAC_TAG, ThreatsTest::insertion0);
    }

    private static void insertion0(Where where, Set<Defence> off) throws Exception {
        SplittableRandom random = new SplittableRandom(5);
        Medium insert = (from, to, d, out) -> {
            if (d.length > Frames.HEADER_BYTES + 40) {
                // An attacker without the key changes a frame it saw, sets its CRC right, and sends
                // it ahead of the real one: only the HMAC tag tells them apart.
                byte[] forged = d.clone();
                int body = d.length - Frames.HEADER_BYTES - Frames.CRC_BYTES - Frames.TAG_BYTES;
                forged[Frames.HEADER_BYTES + body / 2 + random.nextInt(body / 2)] ^= (byte) (1 + random.nextInt(255));
                recomputeCrc(forged, Frames.TAG_BYTES);
                out.deliver(0, forged);
                byte[] misdirected = d.clone();
                Frames.putLong(misdirected, 12, random.nextLong());
                out.deliver(0, misdirected);
            }
            byte[] junk = new byte[1 + random.nextInt(600)];
            random.nextBytes(junk);
            out.deliver(0, junk);
            out.deliver(0, d);
        };
        try (ThreatWorld w = world(where, insert, 2_000, Profile.CLASS_3, off)) {
            Map<String, Long> drops = exchange(w);
            assertTrue(count(drops, "bad-tag") > 0, "forged frames failed authentication: " + drops);
            assertTrue(count(drops, "malformed-frame") > 0, "random datagrams were refused: " + drops);
            assertTrue(count(drops, "misdirected") > 0, "frames for another agent were refused: " + drops);
        }
    }

    // ---- resequence: the reorder buffer ---------------------------------------------------------------

    @ParameterizedTest
    @EnumSource(Where.class)
    void resequence(Where where) throws Exception {
        withDefenceOff(where, Defence.REORDER_BUFFER, ThreatsTest::resequence0);
    }

    private static void resequence0(Where where, Set<Defence> off) throws Exception {
        // Frames leave in groups of five, each group in reverse order (a frame's copies together).
        Medium reverse = perFrame((i, copy, d, out) -> out.deliver((5 - i % 5) * 2_000_000L, d));
        try (ThreatWorld w = world(where, reverse, 2_000, Profile.CLASS_7, off)) {
            exchange(w);
        }
    }

    // ---- corruption: the safety code, and the tag -----------------------------------------------------

    @ParameterizedTest
    @EnumSource(Where.class)
    void corruption(Where where) throws Exception {
        withDefenceOff(where, Defence.SAFETY_CODE, (w, off) -> corruption0(w, Profile.CLOSED, off));
    }

    @ParameterizedTest
    @EnumSource(Where.class)
    void corruptionUnderClassSeven(Where where) throws Exception {
        corruption0(where, Profile.CLASS_7, Set.of());
    }

    private static void corruption0(Where where, Profile profile, Set<Defence> off) throws Exception {
        SplittableRandom random = new SplittableRandom(9);
        // The first copy of every second frame has one bit flipped in its body; the second copy is whole.
        Medium corrupt = perFrame((i, copy, d, out) -> {
            if (i % 2 == 1 && !copy && d.length > Frames.HEADER_BYTES + 8) {
                byte[] bad = d.clone();
                int bit = random.nextInt((d.length - Frames.HEADER_BYTES) * 8);
                bad[Frames.HEADER_BYTES + bit / 8] ^= (byte) (1 << (bit % 8));
                out.deliver(0, bad);
            } else {
                out.deliver(0, d);
            }
        });
        try (ThreatWorld w = world(where, corrupt, 2_000, profile, off)) {
            Map<String, Long> drops = exchange(w);
            String reason = profile == Profile.CLOSED ? "corrupt" : "bad-tag";
            assertTrue(count(drops, reason) > 0, "corrupted frames were dropped (" + reason + "): " + drops);
        }
    }

    // ---- delay: the acceptance window -----------------------------------------------------------------

    @ParameterizedTest
    @EnumSource(Where.class)
    void delay(Where where) throws Exception {
        withDefenceOff(where, Defence.ACCEPTANCE_WINDOW, ThreatsTest::delay0);
    }

    private static boolean contains(byte[] d, byte[] what) {
        outer:
        for (int i = 0; i + what.length <= d.length; i++) {
            for (int j = 0; j < what.length; j++) {
                if (d[i + j] != what[j]) {
                    continue outer;
                }
            }
            return true;
        }
        return false;
    }

    private static void delay0(Where where, Set<Defence> off) throws Exception {
        long windowMs = 100;
        String[] contents = new String[N];
        List<String> expected = new ArrayList<>();
        for (int i = 0; i < N; i++) {
            contents[i] = String.format("msg-%02d", i);
            if (i != 7) {
                expected.add("a:" + contents[i]);
            }
        }
        byte[] m7 = "msg-07".getBytes(java.nio.charset.StandardCharsets.UTF_8);
        // Every frame of one message, copies and retransmissions alike, takes three windows to
        // arrive: it can only arrive late, and a late message is never delivered. The receiver
        // gives up asking for it after 7 NAKs (1.27 s) instead of 40: long after the first late
        // copy came, so that without the acceptance window that copy would be delivered.
        Medium hold = (from, to, d, out) -> out.deliver(contains(d, m7) ? 3 * windowMs * 1_000_000L : 0, d);
        io.concord.layers.sequence.SequenceLayer.Config quick = new io.concord.layers.sequence.SequenceLayer.Config(
                256, 1024, 5, 32, 20, 30, 10, 7, 4096);
        try (ThreatWorld w = where == Where.VIRTUAL ? new ThreatWorld.Virtual(hold, windowMs, Profile.CLOSED, quick, off)
                : new ThreatWorld.RealUdp(hold, windowMs, Profile.CLOSED, quick, off)) {
            Map<String, Long> drops = exchange(w, contents, expected);
            assertTrue(count(drops, "stale") > 0, "delayed frames were refused as stale: " + drops);
        }
    }

    @ParameterizedTest
    @EnumSource(Where.class)
    void masquerade(Where where) throws Exception {
        withDefenceOff(where, Defence.IDENTIFICATION, ThreatsTest::masquerade0);
    }

    private static void masquerade0(Where where, Set<Defence> off) throws Exception {
        try (ThreatWorld w = world(where, Medium.PASS, 2_000, Profile.CLASS_7, off)) {
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
                    && count(w.receiverDrops(), "masquerade") > 0
                    && count(w.receiverDrops(), "bad-tag") + count(w.receiverDrops(), "foreign-key") > 0);
            w.send(w.sender, w.receiverAsSeenByA(), ThreatWorld.contents(N));
            assertTrue(w.awaitReceived(N + 1));
            w.settle(100);
            List<String> expected = new ArrayList<>(List.of("a:m0"));
            expected.addAll(ThreatWorld.expected("a", N));
            assertEquals(expected, w.received(), "only A's own messages reached B");
            Map<String, Long> drops = w.receiverDrops();
            assertTrue(count(drops, "identification") > 0, "the member's forged sender was refused: " + drops);
            assertTrue(count(drops, "masquerade") > 0, "the impostor's handshake was refused: " + drops);
            // Its key's id is not the platform's: skipped as another platform's frames (or, 1 key in 32, failing the tag).
            assertTrue(count(drops, "bad-tag") + count(drops, "foreign-key") > 0, "the outsider's frames were refused: " + drops);
        }
    }

    // ---- an insider's forged stream reset: sessions only the peer itself can restart ----------------

    @ParameterizedTest
    @EnumSource(Where.class)
    void forgedStreamReset(Where where) throws Exception {
        withDefenceOff(where, Defence.SESSION_PROOF, ThreatsTest::forgedStreamReset0);
    }

    /**
     * A key holder (the platform key, an identity of its own) seals a frame "for any agent" in A's
     * name, whose sequence header says A restarted (a data frame of a new stream). Before the
     * defence, B took it for A's new session and dropped all of A's real frames as an earlier
     * session's: one datagram silenced A for B (and, between containers, split the platform).
     */
    private static void forgedStreamReset0(Where where, Set<Defence> off) throws Exception {
        try (ThreatWorld w = world(where, Medium.PASS, 2_000, Profile.CLASS_7, off)) {
            w.send(w.sender, w.receiverAsSeenByA(), "m0");
            assertTrue(w.awaitReceived(1));
            ThreatWorld.Puppet forger = new ThreatWorld.Puppet();
            w.startOnM("a", forger, forgingStack(w.stack()));
            AID b = w.receiverDirect();
            AID anyAtB = new AID(Frames.ANY_LOCAL_NAME + "@" + b.platform(), b.addresses().toArray(String[]::new));
            forger.runtime().execute(() -> forger.send(new AclMessage(Performative.INFORM).addReceiver(anyAtB)
                    .setContent("a new session of a, says a key holder")));
            w.awaitDrops(() -> count(w.receiverDrops(), "unauthenticated") + count(w.receiverDrops(), "not-member")
                    + count(w.receiverDrops(), "malformed-message") > 0);
            w.settle(100);
            w.send(w.sender, w.receiverAsSeenByA(), ThreatWorld.contents(N));
            boolean all = w.awaitReceived(N + 1);
            w.settle(3 * w.windowMs);
            List<String> expected = new ArrayList<>(List.of("a:m0"));
            expected.addAll(ThreatWorld.expected("a", N));
            assertEquals(expected, w.received(), "exactly what A sent, once, in order, unchanged (all in: " + all
                    + "); drops " + w.receiverDrops());
            assertTrue(count(w.receiverDrops(), "unauthenticated") > 0, "the forged reset was refused: " + w.receiverDrops());
        }
    }

    /**
     * The attacker's stack: the class-7 stack with, under its sequence layer, a rewrite that turns
     * the unsequenced frame "for any agent" into the first data frame of a new stream.
     */
    private static java.util.function.Supplier<List<io.concord.core.layer.Layer>> forgingStack(
            java.util.function.Supplier<List<io.concord.core.layer.Layer>> base) {
        return () -> {
            List<io.concord.core.layer.Layer> layers = new ArrayList<>(base.get());
            int at = 0;
            while (!(layers.get(at) instanceof io.concord.layers.sequence.SequenceLayer)) {
                at++;
            }
            layers.add(at + 1, new io.concord.core.layer.Layer() {
                @Override
                public void onDown(io.concord.core.layer.LayerContext ctx, io.concord.core.layer.Envelope env) {
                    byte[] d = env.data();
                    int o = env.offset();
                    if (env.peerId() == Frames.ANY && d[o] == 5) {
                        d[o] = 0; // DATA
                        Frames.putInt(d, o + 1, 0x5EED); // a stream A never had
                        Frames.putLong(d, o + 5, 1);
                    }
                    ctx.passDown(env);
                }
            });
            return layers;
        };
    }
}
