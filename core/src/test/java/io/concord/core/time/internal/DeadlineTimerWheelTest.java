package io.concord.core.time.internal;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class DeadlineTimerWheelTest {
    private static final long MS = 1_000_000L;

    @Test
    void firesNothingBeforeTheDeadlineAndTheTimerAtIt() {
        DeadlineTimerWheel w = DeadlineTimerWheel.forAgents(0);
        long id = w.schedule(5 * MS);
        List<Long> fired = new ArrayList<>();
        assertEquals(0, w.poll(5 * MS - 1, (now, t) -> fired.add(t)));
        assertEquals(1, w.poll(5 * MS, (now, t) -> fired.add(t)));
        assertEquals(List.of(id), fired);
        assertEquals(0, w.timerCount());
    }

    @Test
    void firesInDeadlineOrderThenSchedulingOrder() {
        DeadlineTimerWheel w = new DeadlineTimerWheel(0, 1L << 20, 8);
        long c = w.schedule(30 * MS);
        long a = w.schedule(10 * MS);
        long b1 = w.schedule(20 * MS);
        long b2 = w.schedule(20 * MS);
        List<Long> fired = new ArrayList<>();
        w.poll(100 * MS, (now, t) -> fired.add(t));
        assertEquals(List.of(a, b1, b2, c), fired);
    }

    @Test
    void keepsTimersMoreThanOneTurnAwayUntilTheirTime() {
        DeadlineTimerWheel w = new DeadlineTimerWheel(0, 1L << 20, 8); // one turn is ~8.4 ms
        long far = w.schedule(50 * MS);
        List<Long> fired = new ArrayList<>();
        w.poll(9 * MS, (now, t) -> fired.add(t));
        w.poll(30 * MS, (now, t) -> fired.add(t));
        assertTrue(fired.isEmpty());
        w.poll(50 * MS, (now, t) -> fired.add(t));
        assertEquals(List.of(far), fired);
    }

    @Test
    void cancelsOnceAndReportsIt() {
        DeadlineTimerWheel w = DeadlineTimerWheel.forAgents(0);
        long id = w.schedule(MS);
        assertTrue(w.cancel(id));
        assertFalse(w.cancel(id));
        assertEquals(0, w.poll(10 * MS, (now, t) -> { throw new AssertionError("cancelled timer fired"); }));
    }

    @Test
    void aHandlerMayCancelALaterTimerOfTheSameBatch() {
        DeadlineTimerWheel w = DeadlineTimerWheel.forAgents(0);
        long first = w.schedule(MS);
        long second = w.schedule(2 * MS);
        List<Long> fired = new ArrayList<>();
        w.poll(10 * MS, (now, t) -> {
            fired.add(t);
            w.cancel(second);
        });
        assertEquals(List.of(first), fired);
    }

    @Test
    void aTimerInThePastFiresOnTheNextPoll() {
        DeadlineTimerWheel w = DeadlineTimerWheel.forAgents(0);
        w.poll(100 * MS, (now, t) -> { });
        long late = w.schedule(MS);
        List<Long> fired = new ArrayList<>();
        w.poll(100 * MS, (now, t) -> fired.add(t));
        assertEquals(List.of(late), fired);
    }

    @Test
    void growsASlotThatHoldsManyTimers() {
        DeadlineTimerWheel w = new DeadlineTimerWheel(0, 1L << 20, 2);
        for (int i = 0; i < 1000; i++) {
            w.schedule(MS);
        }
        assertEquals(1000, w.poll(2 * MS, (now, t) -> { }));
        assertEquals(Long.MAX_VALUE, w.earliestDeadline());
    }

    @Test
    void reportsTheEarliestDeadline() {
        DeadlineTimerWheel w = DeadlineTimerWheel.forAgents(0);
        w.schedule(70 * MS);
        w.schedule(7 * MS);
        assertEquals(7 * MS, w.earliestDeadline());
    }

    @Test
    void refusesSizesThatAreNotPowersOfTwo() {
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> new DeadlineTimerWheel(0, 1000, 8));
    }
}
