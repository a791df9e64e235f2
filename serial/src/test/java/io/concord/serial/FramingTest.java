package io.concord.serial;

import org.junit.jupiter.api.Test;

import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Frames survive any chunking and garbage; every frame not taken is counted by its reason. */
class FramingTest {

    /** The board's receiving side (these are host frames), keeping what it takes. */
    static final class Receiver {
        final List<Frame> taken = new ArrayList<>();
        final FrameReceiver rx;
        final Drops drops;
        long nowMs;

        Receiver(FrameCodec codec) {
            rx = new FrameReceiver(codec, false, 200, taken::add);
            drops = rx.drops();
        }

        void feed(byte[] b, int off, int len) {
            rx.feed(b, off, len, nowMs);
        }
    }

    private static byte[] frames(FrameCodec c, int from, int n, long t0) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (int i = from; i < from + n; i++) {
            out.writeBytes(c.encode(new Frame(Frame.Type.DRIVE, 0, i, t0 + i, BoardProtocol.drive(i % 1000, -(i % 1000)))));
        }
        return out.toByteArray();
    }

    @Test
    void anyChunkingGivesTheSameFrames() {
        FrameCodec c = new FrameCodec();
        byte[] wire = frames(c, 0, 200, 0);
        SplittableRandom r = new SplittableRandom(5);
        for (int round = 0; round < 50; round++) {
            Receiver rx = new Receiver(c);
            for (int i = 0; i < wire.length; ) {
                int n = Math.min(wire.length - i, 1 + r.nextInt(40));
                rx.feed(wire, i, n);
                i += n;
            }
            assertEquals(200, rx.taken.size());
            assertEquals(0, rx.drops.total());
        }
    }

    @Test
    void garbageCostsAtMostTheFrameItLandsIn() {
        FrameCodec c = new FrameCodec();
        Receiver rx = new Receiver(c);
        rx.feed(new byte[] {0x13, 0x37, (byte) 0xFF, 0x42}, 0, 4);
        byte[] wire = frames(c, 0, 10, 0);
        rx.feed(wire, 0, wire.length);
        // The garbage joins the first frame's bytes: that frame is lost as corrupt, the rest are taken.
        assertEquals(9, rx.taken.size());
        assertEquals(1, rx.drops.get("corrupt"));
    }

    @Test
    void aFlippedBitIsCorruptAnotherKeyIsAMacDropAndAnOverlongRunIsOversized() {
        FrameCodec plain = new FrameCodec();
        byte[] one = plain.encode(new Frame(Frame.Type.STOP, 0, 1, 5, new byte[0]));
        one[5] ^= 0x04;
        Receiver rx = new Receiver(plain);
        rx.feed(one, 0, one.length);
        assertEquals(1, rx.drops.get("corrupt"));

        FrameCodec a = new FrameCodec(new byte[16]);
        byte[] k = new byte[16];
        k[0] = 1;
        Receiver other = new Receiver(new FrameCodec(k));
        byte[] signed = a.encode(new Frame(Frame.Type.STOP, 0, 1, 5, new byte[0]));
        other.feed(signed, 0, signed.length);
        assertEquals(1, other.drops.get("mac"));
        Receiver unpaired = new Receiver(plain);
        unpaired.feed(signed, 0, signed.length);
        assertEquals(1, unpaired.drops.get("mac"), "a MAC this end cannot check is not taken");

        byte[] junk = new byte[3000];
        java.util.Arrays.fill(junk, (byte) 7);
        rx.feed(junk, 0, junk.length);
        rx.feed(new byte[] {0}, 0, 1);
        assertEquals(1, rx.drops.get("oversized"));
        byte[] after = frames(plain, 2, 1, 0);
        rx.feed(after, 0, after.length);
        assertEquals(1, rx.taken.size(), "the next frame is taken");
    }

    @Test
    void repeatedReorderedAndStaleFramesAreDropped() {
        FrameCodec c = new FrameCodec();
        Receiver rx = new Receiver(c);
        byte[] f1 = frames(c, 1, 1, 1000);
        byte[] f2 = frames(c, 2, 1, 1000);
        byte[] f3 = frames(c, 3, 1, 1000);
        rx.nowMs = 5000;
        rx.feed(f1, 0, f1.length);
        rx.feed(f1, 0, f1.length);
        rx.feed(f3, 0, f3.length);
        rx.feed(f2, 0, f2.length);
        assertEquals(1, rx.drops.get("repeated"));
        assertEquals(1, rx.drops.get("out-of-order"));
        // The reference grows by the 2 % drift tolerance of the time since the last frame: 5 ms here.
        rx.nowMs = 5000 + 206 + 3;
        byte[] f4 = frames(c, 4, 1, 1000);
        rx.feed(f4, 0, f4.length);
        assertEquals(1, rx.drops.get("stale"), "sent 1 ms after frame 3, arrived 208 ms later than the least delayed, 4.2 ms of drift allowed");
        assertEquals(2, rx.taken.size());
        // Sequence numbers wrap: 65535 then 0 is in order.
        Receiver w = new Receiver(c);
        byte[] a = c.encode(new Frame(Frame.Type.STOP, 0, 65_535, 0, new byte[0]));
        byte[] b = c.encode(new Frame(Frame.Type.STOP, 0, 0, 1, new byte[0]));
        w.feed(a, 0, a.length);
        w.feed(b, 0, b.length);
        assertEquals(2, w.taken.size());
    }

    /** A board's clock 1 % slow, 20 frames a second for 10 minutes: every frame on time is taken. */
    @Test
    void aSenderWhoseClockRunsOnePercentSlowIsNeverStaleAndTheCheckWithoutDriftFailsIt() {
        assertEquals(0, staleOfASlowSender(SequenceCheck.DRIFT, 0.99, 0));
        assertEquals(0, staleOfASlowSender(SequenceCheck.DRIFT, 1.01, 0), "a fast clock");
        // The defence off: the check of version 1 (the least offset, no drift) drops every frame
        // after the first 50 s (500 ms / 1 %).
        assertTrue(staleOfASlowSender(0, 0.99, 0) > 10_000);
    }

    /** A delay that grows faster than any clock drifts (frames held back by a relay) is still stale. */
    @Test
    void aDelayGrowingFasterThanTheToleratedDriftIsStale() {
        assertTrue(staleOfASlowSender(SequenceCheck.DRIFT, 1.0, 0.05) > 0, "5 % more delay every second");
    }

    /** Frames dropped as stale at a host (500 ms) of a sender at {@code rate}, each delayed by {@code growth} of the time so far. */
    private static int staleOfASlowSender(double drift, double rate, double growth) {
        SequenceCheck check = new SequenceCheck(500, drift);
        int stale = 0;
        for (int i = 0; i < 20 * 600; i++) {
            long local = i * 50L + 3 + (i * 7L) % 5;          // 3-7 ms on the line
            local += (long) (growth * i * 50);
            long senderTime = (long) (i * 50L * rate);
            if ("stale".equals(check.check(new Frame(Frame.Type.STATE, 0, i & 0xFFFF, senderTime, new byte[0]), local))) {
                stale++;
            }
        }
        return stale;
    }

    /**
     * A board that restarted and whose HELLO was lost: its first STATE, with the next boot number
     * and seq 1, is taken (version 1 dropped it as out-of-order for up to 32,768 frames); a frame
     * of the previous boot is then refused as old-boot.
     */
    @Test
    void aRebootIsSeenInTheFirstStateEvenWithoutItsHelloAndTheOldBootIsRefused() {
        FrameCodec c = new FrameCodec();
        List<Frame> taken = new ArrayList<>();
        FrameReceiver host = new FrameReceiver(c, true, 500, taken::add);
        java.util.function.BiFunction<Long, Integer, byte[]> state = (boot, seq) -> c.encode(new Frame(Frame.Type.STATE, 0, seq,
                seq * 50L, BoardProtocol.state(new BoardProtocol.State(boot, 0, 0, new int[0], false, false, true, BoardProtocol.ARMED,
                        24_000, java.util.Set.of(), null))));
        for (int seq = 5000; seq < 5003; seq++) {
            byte[] b = state.apply(1L, seq);
            host.feed(b, 0, b.length, 1_000);
        }
        byte[] rebooted = state.apply(2L, 1);
        host.feed(rebooted, 0, rebooted.length, 1_010);
        assertEquals(4, taken.size(), "the new boot's first STATE is taken: " + host.drops());
        assertEquals(2, host.boot());
        byte[] old = state.apply(1L, 5003);
        host.feed(old, 0, old.length, 1_020);
        assertEquals(1, host.drops().get("old-boot"));
        assertEquals(4, taken.size());
    }
}
