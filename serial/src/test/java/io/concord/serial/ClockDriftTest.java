package io.concord.serial;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A board whose clock runs 1 % slow, for 10 minutes of virtual time: the board and a host's
 * receiver joined in memory, each on its own manual clock, the host driving at its heartbeat.
 * Nothing is stale at either end, the board never trips, and the host never goes 500 ms without a
 * STATE (which would be the link down). Version 1's check, with no drift tolerated, loses the
 * link after 50 s.
 */
class ClockDriftTest {

    /** What the 10 minutes showed. */
    record Outcome(long hostStale, long boardStale, boolean boardTripped, long longestSilenceMs, long states) {
    }

    static Outcome run(double boardRate, SequenceCheck hostCheck) {
        BoardTest.Motors motors = new BoardTest.Motors();
        FrameCodec codec = new FrameCodec();
        List<byte[]> toHost = new ArrayList<>();
        Board board = new Board(motors, codec, "drift", toHost::add);
        long[] lastState = {0};
        long[] longest = {0};
        long[] states = {0};
        long[] hostNow = {0};
        Drops hostDrops = new Drops();
        FrameReceiver host = new FrameReceiver(codec, true, hostCheck, f -> {
            if (f.type() == Frame.Type.STATE) {
                longest[0] = Math.max(longest[0], hostNow[0] - lastState[0]);
                lastState[0] = hostNow[0];
                states[0]++;
            }
        }, hostDrops);
        boolean tripped = false;
        int seq = 0;
        board.switchOn(1, 0);
        for (long ms = 0; ms <= 600_000; ms++) {
            hostNow[0] = ms;
            long boardMs = (long) (ms * boardRate);
            if (ms % 50 == 0) {
                // The host's heartbeat, 2 ms on the line.
                int flags = seq == 0 ? Frame.SYNC : 0;
                byte[] b = codec.encode(seq == 0 ? new Frame(Frame.Type.PING, flags, seq, ms, BoardProtocol.ping(0))
                        : new Frame(Frame.Type.DRIVE, 0, seq, ms, BoardProtocol.drive(seq < 3 ? 0 : 200, seq < 3 ? 0 : 200)));
                seq = (seq + 1) & 0xFFFF;
                board.onBytes(b, 0, b.length, (long) ((ms + 2) * boardRate));
            }
            board.tick(boardMs);
            tripped |= board.tripped();
            for (byte[] b : toHost) {
                host.feed(b, 0, b.length, ms + 3);
            }
            toHost.clear();
        }
        longest[0] = Math.max(longest[0], 600_000 - lastState[0]);
        return new Outcome(hostDrops.get("stale"), board.drops().get("stale"), tripped, longest[0], states[0]);
    }

    @Test
    void aBoardClockOnePercentSlowForTenMinutesLosesNothing() {
        Outcome o = run(0.99, new SequenceCheck(500));
        assertEquals(0, o.hostStale(), o.toString());
        assertEquals(0, o.boardStale(), o.toString());
        assertFalse(o.boardTripped(), o.toString());
        assertTrue(o.longestSilenceMs() < 500, "the link never goes down: " + o);
        assertTrue(o.states() > 11_000, "20 STATEs a second of the board's slow clock: " + o);
        Outcome fast = run(1.01, new SequenceCheck(500));
        assertEquals(0, fast.hostStale() + fast.boardStale(), "a fast clock: " + fast);
    }

    @Test
    void withoutTheDriftToleranceTheLinkIsLostAfterFiftySeconds() {
        Outcome o = run(0.99, new SequenceCheck(500, 0));
        assertTrue(o.hostStale() > 10_000, o.toString());
        assertTrue(o.longestSilenceMs() > 500, "the link would be down: " + o);
    }

    /**
     * A session whose first frame sat 600 ms on the wire (bytes waiting in the port's buffer when
     * it opened), then a board 10 % slow: the drift is read as 10 %, not blurred by the first frame's
     * delay (measured from the first frame, it read 0.7 % over 6.8 s over real ptys).
     */
    @Test
    void theDriftIsMeasuredOnTheLeastDelayedFramesNotTheFirst() {
        SequenceCheck check = new SequenceCheck(500);
        // host ms 1000: a frame the board stamped at 400 (600 ms late); then one every 50 ms, on time.
        check.check(new Frame(Frame.Type.STATE, 0, 1, 400, new byte[0]), 1_000);
        double boardMs = 1_000;
        for (int i = 2; i < 130; i++) {
            long host = 1_000 + (i - 1) * 50L;
            boardMs += 50 * 0.9;
            check.check(new Frame(Frame.Type.STATE, 0, i, Math.round(boardMs), new byte[0]), host);
        }
        assertEquals(0.10, check.drift(), 0.005, "measured over " + check.driftSpanMs() + " ms");
    }
}
