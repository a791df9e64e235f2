package io.concord.layers.platform;

import io.concord.core.layer.Envelope;

import java.util.ArrayDeque;
import java.util.Iterator;
import java.util.function.Consumer;
import java.util.function.Predicate;

/**
 * Messages that wait, in arrival order, for something the platform will know in a moment (a
 * sender in the lists, a container elected): at most {@code max} in all and each at most
 * {@code waitMs}. Past either bound a message leaves through {@code giveUp}, the eldest first, with
 * the reason why; released ones leave in the order they came. Loop thread only.
 */
final class WaitRoom {
    /** A waiting message and what it waits for (a sender's name, a receiver's). */
    record Held(Envelope env, String key, long sinceNs) {
    }

    /** Why a message left without its wait being met. */
    enum Why { FULL, EXPIRED, STOPPED }

    /** Takes a message that leaves without its wait being met. */
    interface GiveUp {
        void accept(Held held, Why why);
    }

    private final PlatformContext ctx;
    private final long waitMs;
    private final int max;
    private final GiveUp giveUp;
    private final ArrayDeque<Held> held = new ArrayDeque<>();
    private long timer = -1;
    private long waited;

    WaitRoom(PlatformContext ctx, long waitMs, int max, GiveUp giveUp) {
        this.ctx = ctx;
        this.waitMs = waitMs;
        this.max = max;
        this.giveUp = giveUp;
    }

    /** Holds a message; the eldest leaves if the room is full. */
    void hold(Envelope env, String key) {
        if (held.size() >= max) {
            giveUp.accept(held.poll(), Why.FULL);
        }
        held.add(new Held(env, key, ctx.nowNs()));
        waited++;
        if (timer < 0) {
            timer = ctx.after(waitMs, this::expire);
        }
    }

    /** Lets out, in the order they came, the messages whose key is now {@code ready}. */
    void release(Predicate<String> ready, Consumer<Envelope> out) {
        if (held.isEmpty()) {
            return;
        }
        for (Iterator<Held> it = held.iterator(); it.hasNext(); ) {
            Held h = it.next();
            if (ready.test(h.key())) {
                it.remove();
                out.accept(h.env());
            }
        }
        if (held.isEmpty()) {
            timer = ctx.cancel(timer);
        }
    }

    private void expire() {
        timer = -1;
        long now = ctx.nowNs();
        while (!held.isEmpty() && now - held.peek().sinceNs() >= waitMs * 1_000_000L) {
            giveUp.accept(held.poll(), Why.EXPIRED);
        }
        if (!held.isEmpty()) {
            long leftMs = Math.max(1, waitMs - (now - held.peek().sinceNs()) / 1_000_000L);
            timer = ctx.after(leftMs, this::expire);
        }
    }

    /** Messages waiting now. */
    int size() {
        return held.size();
    }

    /** Messages that had to wait, since start. */
    long waited() {
        return waited;
    }

    /** Every waiting message leaves through {@code giveUp}. */
    void stop() {
        timer = ctx.cancel(timer);
        while (!held.isEmpty()) {
            giveUp.accept(held.poll(), Why.STOPPED);
        }
    }
}
