package io.concord.layers.platform;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.LayerContext;


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

    private final PlatformContext ctx;
    private final LayerContext layer;
    private final AgentLists lists;
    private final String self;
    private final WaitRoom room;
    private long admitted;

    MembershipGate(PlatformContext ctx, LayerContext layer, AgentLists lists, String self) {
        this.ctx = ctx;
        this.layer = layer;
        this.lists = lists;
        this.self = self;
        this.room = new WaitRoom(ctx, WAIT_MS, MAX_HELD, (h, why) -> layer.drop(h.env(), why == WaitRoom.Why.STOPPED
                ? "stopped" : "not-member", switch (why) {
                    case FULL -> h.key() + " is not in the platform's lists, and " + MAX_HELD + " messages already wait for them";
                    case EXPIRED -> h.key() + " is not in the platform's lists (not joined, or removed); its message waited "
                            + WAIT_MS + " ms for them";
                    case STOPPED -> "the agent stopped while a message of " + h.key() + " waited for the lists";
                }));
    }

    private boolean member(String name) {
        return name.equals(self) || lists.route(name, ctx.nowNs()) != null;
    }

    /**
     * Passes an application message up if its sender is a member; else it waits for the lists.
     * A member never has a message waiting here: a name becomes a member only when the routes are
     * rebuilt, which calls {@link #listsChanged} and lets its messages out first, so order holds.
     */
    void admit(Envelope env, String sender) {
        if (member(sender)) {
            admitted++;
            layer.passUp(env);
            return;
        }
        room.hold(env, sender);
    }

    /** The lists changed: messages of senders they now name go up, in the order they came. */
    void listsChanged() {
        room.release(this::member, env -> {
            admitted++;
            layer.passUp(env);
        });
    }

    /** Messages waiting now. */
    int held() {
        return room.size();
    }

    /** Messages that had to wait for the lists (tests, the console). */
    long waited() {
        return room.waited();
    }

    void stop() {
        room.stop();
    }
}
