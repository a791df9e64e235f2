package io.concord.core.agent;

import io.concord.core.time.Clock;
import io.concord.core.time.ManualClock;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The loop's idle strategy alone, on a clock the test moves: how long it waits awake, and when it parks. */
class IdleStrategyTest {
    final ManualClock clock = new ManualClock();

    /** How many empty cycles it waits awake before it parks (then parks, and wakes {@code wokeAfterNs} later). */
    static int awakeCycles(IdleStrategy s, ManualClock clock, long wokeAfterNs) {
        int n = 0;
        while (s.waitAwake()) {
            n++;
        }
        long at = s.parking();
        clock.advanceNs(wokeAfterNs);
        s.woke(at);
        return n;
    }

    @Test
    void waitsAwakeForItsBudgetThenParks() {
        IdleStrategy s = new IdleStrategy(clock, 2, 6);
        assertEquals(8, awakeCycles(s, clock, 1_000_000));
        s.worked(true);
        assertEquals(8, awakeCycles(s, clock, 1_000_000), "each idle spell starts again");
    }

    @Test
    void parksThatWaitingAwakeWouldNotHaveCaughtHalveTheBudgetAndQuickWakesDoubleIt() {
        IdleStrategy s = new IdleStrategy(clock, 0, 8);
        for (int i = 0; i < 32; i++) {
            assertEquals(8, awakeCycles(s, clock, 1_000_000), "after " + i + " long parks");
        }
        assertEquals(4, awakeCycles(s, clock, 1_000_000), "32 long parks: half the budget");
        for (int i = 0; i < 31; i++) {
            awakeCycles(s, clock, 1_000_000);
        }
        assertEquals(2, awakeCycles(s, clock, 1_000), "halved again");
        for (int i = 0; i < 31; i++) {
            awakeCycles(s, clock, 1_000);
        }
        assertEquals(4, awakeCycles(s, clock, 1_000), "32 quick wakes: doubled");
    }

    @Test
    void workThatComesWhileAwakeCountsForWaitingAwake() {
        IdleStrategy s = new IdleStrategy(clock, 0, 8);
        for (int i = 0; i < 32; i++) {
            assertTrue(s.waitAwake());
            s.worked(true); // a datagram came while it yielded
        }
        assertEquals(8, awakeCycles(s, clock, 1_000_000), "no loss counted: the budget stays whole");
        s.worked(false);
    }

    @Test
    void aYieldThatLostTheCpuToAnotherThreadParksAtOnce() {
        ManualClock busy = new ManualClock();
        // Every read of this clock finds a whole time slice gone: the cores are contended.
        Clock slow = new Clock() {
            @Override
            public long nanoTime() {
                busy.advanceNs(IdleStrategy.CONTENDED_YIELD_NS + 1);
                return busy.nanoTime();
            }

            @Override
            public long epochMillis() {
                return busy.epochMillis();
            }
        };
        IdleStrategy s = new IdleStrategy(slow, 0, 200);
        assertTrue(s.waitAwake(), "the yield happened");
        assertEquals(1, s.contendedYields());
        assertFalse(s.waitAwake(), "and it parks at once, not after 200 yields");
    }
}
