package io.concord.core.time.internal;

import java.util.Arrays;

/**
 * A passive hashed timer wheel in the manner of Agrona's: timers are scheduled for an absolute
 * deadline (monotonic nanoseconds) and fire when the owner polls the wheel with the current time.
 * No thread, no clock of its own. Not thread-safe: one loop owns it.
 *
 * <p>Timer ids are {@code long}s that encode slot and index, so cancelling is O(1). Timers that
 * fall due in the same poll fire in deadline order, ties broken by scheduling order, so a
 * simulation that polls with the same times sees the same sequence.
 */
public final class DeadlineTimerWheel {

    /** Receives expired timers. */
    @FunctionalInterface
    public interface Handler {
        /**
         * Called for each expired timer.
         *
         * @param nowNs  the time the wheel was polled with
         * @param timerId the id {@link #schedule} returned
         */
        void onExpiry(long nowNs, long timerId);
    }

    /** Returned by lookups when there is no timer. */
    public static final long NO_TIMER = -1;

    private static final long EMPTY = Long.MAX_VALUE;

    private final long tickNs;
    // The earliest deadline, kept while it is known: a scan finds it; scheduling an earlier one
    // lowers it; cancelling (or firing) the timer that holds it forgets it until the next scan.
    private long knownMin = Long.MAX_VALUE;
    private boolean minKnown = true;
    private final int ticksPerWheel;
    private final int mask;
    private final long startNs;
    private long[][] deadlines;
    private long[][] sequences;
    private long currentTick;
    private long timerCount;
    // Active timers per slot, so that a scan for the earliest deadline skips the empty slots.
    private final int[] slotCounts;
    private long nextSequence;

    // scratch for ordered expiry within a poll
    private long[] dueIds = new long[16];
    private long[] dueDeadlines = new long[16];
    private long[] dueSeqs = new long[16];

    /**
     * @param startNs       the time of tick zero
     * @param tickNs        the resolution; a power of two
     * @param ticksPerWheel the number of slots; a power of two
     */
    public DeadlineTimerWheel(long startNs, long tickNs, int ticksPerWheel) {
        if (Long.bitCount(tickNs) != 1 || Integer.bitCount(ticksPerWheel) != 1) {
            throw new IllegalArgumentException("tickNs and ticksPerWheel must be powers of two, got "
                    + tickNs + " and " + ticksPerWheel);
        }
        this.startNs = startNs;
        this.tickNs = tickNs;
        this.ticksPerWheel = ticksPerWheel;
        this.mask = ticksPerWheel - 1;
        this.slotCounts = new int[ticksPerWheel];
        this.deadlines = new long[ticksPerWheel][4];
        this.sequences = new long[ticksPerWheel][4];
        for (long[] slot : deadlines) {
            Arrays.fill(slot, EMPTY);
        }
    }

    /** A wheel with a 1.048576 ms tick and 1024 slots, suited to agent timeouts. */
    public static DeadlineTimerWheel forAgents(long startNs) {
        return new DeadlineTimerWheel(startNs, 1L << 20, 1024);
    }

    /** Number of active timers. */
    public long timerCount() {
        return timerCount;
    }

    /**
     * Schedules a timer.
     *
     * @return its id, to cancel it or to recognise it on expiry
     */
    public long schedule(long deadlineNs) {
        long deadlineTick = Math.max((deadlineNs - startNs) / tickNs, currentTick);
        int slot = (int) (deadlineTick & mask);
        long[] slotDeadlines = deadlines[slot];
        for (int i = 0; i < slotDeadlines.length; i++) {
            if (slotDeadlines[i] == EMPTY) {
                return place(slot, i, deadlineNs);
            }
        }
        int old = slotDeadlines.length;
        long[] grown = Arrays.copyOf(slotDeadlines, old * 2);
        Arrays.fill(grown, old, grown.length, EMPTY);
        deadlines[slot] = grown;
        sequences[slot] = Arrays.copyOf(sequences[slot], old * 2);
        return place(slot, old, deadlineNs);
    }

    private long place(int slot, int index, long deadlineNs) {
        if (minKnown && deadlineNs < knownMin) {
            knownMin = deadlineNs;
        }
        deadlines[slot][index] = deadlineNs;
        sequences[slot][index] = nextSequence++;
        timerCount++;
        slotCounts[slot]++;
        return ((long) slot << 32) | index;
    }

    /** Cancels a timer; false if it had already fired or been cancelled. */
    public boolean cancel(long timerId) {
        if (timerId < 0) {
            return false;
        }
        int slot = (int) (timerId >>> 32);
        int index = (int) timerId;
        if (slot >= ticksPerWheel || index >= deadlines[slot].length || deadlines[slot][index] == EMPTY) {
            return false;
        }
        if (deadlines[slot][index] == knownMin) {
            minKnown = false;
        }
        deadlines[slot][index] = EMPTY;
        timerCount--;
        slotCounts[slot]--;
        return true;
    }

    /** The deadline of a timer, or {@link #NO_TIMER} if it is not active. */
    public long deadline(long timerId) {
        int slot = (int) (timerId >>> 32);
        int index = (int) timerId;
        if (timerId < 0 || slot >= ticksPerWheel || index >= deadlines[slot].length) {
            return NO_TIMER;
        }
        long d = deadlines[slot][index];
        return d == EMPTY ? NO_TIMER : d;
    }

    /**
     * The earliest deadline of any active timer, or {@link Long#MAX_VALUE} if none. Scans the wheel:
     * meant for an idle loop deciding how long it may sleep, not for the hot path.
     */
    public long earliestDeadline() {
        if (timerCount == 0) {
            return Long.MAX_VALUE;
        }
        if (minKnown) {
            return knownMin;
        }
        long min = Long.MAX_VALUE;
        for (int i = 0; i < ticksPerWheel; i++) {
            if (slotCounts[i] == 0) {
                continue;
            }
            for (long d : deadlines[i]) {
                if (d < min) {
                    min = d;
                }
            }
        }
        knownMin = min;
        minKnown = true;
        return min;
    }

    /**
     * Fires every timer whose deadline is at or before {@code nowNs}, in deadline order.
     *
     * @return the number of timers fired
     */
    public int poll(long nowNs, Handler handler) {
        if (timerCount == 0) {
            currentTick = Math.max(currentTick, (nowNs - startNs) / tickNs);
            return 0;
        }
        long nowTick = (nowNs - startNs) / tickNs;
        int due = 0;
        // Walk every slot whose tick has passed (at most one full turn), collecting due timers.
        long lastTick = Math.min(nowTick, currentTick + ticksPerWheel - 1);
        for (long tick = currentTick; tick <= lastTick; tick++) {
            int slot = (int) (tick & mask);
            long[] slotDeadlines = deadlines[slot];
            for (int i = 0; i < slotDeadlines.length; i++) {
                long d = slotDeadlines[i];
                if (d != EMPTY && d <= nowNs) {
                    due = addDue(due, ((long) slot << 32) | i, d, sequences[slot][i]);
                }
            }
        }
        if (due > 1) {
            sortDue(due);
        }
        int fired = 0;
        for (int k = 0; k < due; k++) {
            long id = dueIds[k];
            // A handler may have cancelled a later timer of this batch.
            if (deadline(id) == dueDeadlines[k] && cancel(id)) {
                handler.onExpiry(nowNs, id);
                fired++;
            }
        }
        currentTick = Math.max(currentTick, nowTick);
        return fired;
    }

    private int addDue(int n, long id, long deadline, long seq) {
        if (n == dueIds.length) {
            dueIds = Arrays.copyOf(dueIds, n * 2);
            dueDeadlines = Arrays.copyOf(dueDeadlines, n * 2);
            dueSeqs = Arrays.copyOf(dueSeqs, n * 2);
        }
        dueIds[n] = id;
        dueDeadlines[n] = deadline;
        dueSeqs[n] = seq;
        return n + 1;
    }

    private void sortDue(int n) {
        // Insertion sort: batches are small.
        for (int i = 1; i < n; i++) {
            long id = dueIds[i];
            long d = dueDeadlines[i];
            long s = dueSeqs[i];
            int j = i - 1;
            while (j >= 0 && (dueDeadlines[j] > d || (dueDeadlines[j] == d && dueSeqs[j] > s))) {
                dueIds[j + 1] = dueIds[j];
                dueDeadlines[j + 1] = dueDeadlines[j];
                dueSeqs[j + 1] = dueSeqs[j];
                j--;
            }
            dueIds[j + 1] = id;
            dueDeadlines[j + 1] = d;
            dueSeqs[j + 1] = s;
        }
    }
}
