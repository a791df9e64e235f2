package io.concord.layers.platform;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.LayerContext;

import java.util.ArrayDeque;
import java.util.Iterator;

/**
 * The membership control of the dissertation: an application message is taken only from an agent
 * the platform's lists name (this agent's LAL and GAL, or one that left them less than the route
 * grace ago). Under class 7 the pair key has already authenticated the sender, so a key holder
 * that never joined, or was removed, reaches nobody.
 *
 * <p>An agent that joined a moment ago may speak before the container's new list reaches this
 * agent (and an agent that has not joined yet knows nobody). Its messages wait here, in arrival
 * order, until the lists name the sender, at most {@link #WAIT_MS}; then they are dropped
 * ({@code not-member}). At most {@link #MAX_HELD} messages wait in all; beyond that the eldest is
 * dropped ({@code not-member}, "too many waiting"). A message is never delivered out of order
 * behind one of the same sender that waits.
 */
final class MembershipGate {
    /** How long a message from an agent not (yet) in the lists waits for them. */
    static final long WAIT_MS = 2_000;
    static final int MAX_HELD = 256;

    private record Held(Envelope env, String sender, long sinceNs) {
    }

    private final PlatformContext ctx;
    private final LayerContext layer;
    private final AgentLists lists;
    private final String self;
    private final ArrayDeque<Held> held = new ArrayDeque<>();
    private long timer = -1;
    private long admitted;
    private long waited;

    MembershipGate(PlatformContext ctx, LayerContext layer, AgentLists lists, String self) {
        this.ctx = ctx;
        this.layer = layer;
        this.lists = lists;
        this.self = self;
    }

    private boolean member(String name) {
        return name.equals(self) || lists.route(name, ctx.nowNs()) != null;
    }

    private boolean waiting(String name) {
        for (Held h : held) {
            if (h.sender().equals(name)) {
                return true;
            }
        }
        return false;
    }

    /** Passes an application message up if its sender is a member; else it waits for the lists. */
    void admit(Envelope env, String sender) {
        if (member(sender) && (held.isEmpty() || !waiting(sender))) {
            admitted++;
            layer.passUp(env);
            return;
        }
        if (held.size() >= MAX_HELD) {
            Held eldest = held.poll();
            layer.drop(eldest.env(), "not-member", eldest.sender() + " is not in the platform's lists, and "
                    + MAX_HELD + " messages already wait for them");
        }
        held.add(new Held(env, sender, ctx.nowNs()));
        waited++;
        if (timer < 0) {
            timer = ctx.after(WAIT_MS, this::expire);
        }
    }

    /** The lists changed: messages of senders they now name go up, in the order they came. */
    void listsChanged() {
        if (held.isEmpty()) {
            return;
        }
        for (Iterator<Held> it = held.iterator(); it.hasNext(); ) {
            Held h = it.next();
            if (member(h.sender())) {
                it.remove();
                admitted++;
                layer.passUp(h.env());
            }
        }
        if (held.isEmpty()) {
            timer = ctx.cancel(timer);
        }
    }

    private void expire() {
        timer = -1;
        long now = ctx.nowNs();
        while (!held.isEmpty() && now - held.peek().sinceNs() >= WAIT_MS * 1_000_000L) {
            Held h = held.poll();
            layer.drop(h.env(), "not-member", h.sender() + " is not in the platform's lists (not joined, or removed); "
                    + "its message waited " + WAIT_MS + " ms for them");
        }
        if (!held.isEmpty()) {
            long leftMs = Math.max(1, WAIT_MS - (now - held.peek().sinceNs()) / 1_000_000L);
            timer = ctx.after(leftMs, this::expire);
        }
    }

    /** Messages waiting now. */
    int held() {
        return held.size();
    }

    /** Messages that had to wait for the lists (tests, the console). */
    long waited() {
        return waited;
    }

    void stop() {
        timer = ctx.cancel(timer);
        for (Held h : held) {
            layer.drop(h.env(), "stopped", "the agent stopped while a message of " + h.sender() + " waited for the lists");
        }
        held.clear();
    }
}
