package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.LayerContext;
import io.concord.core.layer.SendRejectedException;

/**
 * The sequence layer's flow control (JGroups' UFC does this part, on credits): a sender keeps at
 * most the receiver's window of frames unacknowledged and holds the rest, pausing its agent while
 * it holds any of the agent's own messages (what the layers send on their own, the platform's
 * lists and heartbeats, waits in order but pauses nobody: a receiver that is behind must not stall
 * every member that speaks to it); a receiver announces in each acknowledgement the window it
 * takes, 0 while its agent's mailbox is full, and the whole window again once the agent has
 * taken the mailbox down. It lives in the sequence layer because only that layer knows what is unacknowledged; the
 * {@link Retransmission} part sends what this part lets go. One per agent, called on its loop.
 */
final class FlowWindow {
    /**
     * A receiver that acknowledges nothing for this long while frames wait for it is silent: it
     * stops holding the agent back (no head-of-line stall behind a stopped or gone peer); a slow
     * one acknowledges, or answers probes with its window shut, and keeps holding it back.
     */
    static final long SILENT_MS = 1_000;
    private final int reorderWindow;
    private final boolean on;
    /** Receivers with the agent's own messages held for them: while any, the agent is paused. */
    private int congested;

    /**
     * @param reorderWindow the receiver's reorder window, the most a sender may have unacknowledged
     * @param on            false only in the threat tests ({@code Defence.FLOW_CONTROL})
     */
    FlowWindow(int reorderWindow, boolean on) {
        this.reorderWindow = reorderWindow;
        this.on = on;
    }

    /** True if a frame to this receiver must wait: others wait already, or its window is full. */
    boolean mustHold(SenderState o) {
        return on && (!o.held.isEmpty() || !windowOpen(o));
    }

    /** Frames this sender may have unacknowledged: the receiver's window, at most its reorder window. */
    private boolean windowOpen(SenderState o) {
        int window = o.credit < 0 ? reorderWindow : Math.min(reorderWindow, o.credit);
        return o.nextSeq - 1 - o.acked < window;
    }

    /**
     * Holds a frame until the receiver's window opens, and pauses the agent while any is held.
     *
     * @throws SendRejectedException ({@code flow-control}) past {@link SequenceLayer#MAX_HELD} held for the receiver
     */
    void hold(LayerContext ctx, Envelope env, SenderState o) {
        if (o.held.size() >= SequenceLayer.MAX_HELD) {
            throw new SendRejectedException("flow-control", SequenceLayer.MAX_HELD + " messages to " + o.address
                    + " wait already for it to take the ones before (it is slower than this sender, or gone); "
                    + "send fewer in one action of a behaviour: the agent is paused until the receiver catches up");
        }
        env.detachData();
        o.held.add(env);
        if (!env.sentByAgent()) {
            return;   // the platform's own (its lists, heartbeats): waits in order, pauses nobody
        }
        o.heldOfAgent++;
        if (!o.holding && !o.silent) {
            o.holding = true;
            if (congested++ == 0) {
                ctx.host().backpressure(true);
            }
        }
    }

    /**
     * The receiver has been silent for {@link #SILENT_MS} with frames waiting: it no longer holds
     * the agent back (what waits for it keeps waiting, bounded by {@link SequenceLayer#MAX_HELD}).
     */
    void silent(LayerContext ctx, SenderState o) {
        if (o.silent) {
            return;
        }
        o.silent = true;
        if (o.holding) {
            o.holding = false;
            if (--congested == 0) {
                ctx.host().backpressure(false);
            }
        }
    }

    /** The receiver acknowledged again: if frames still wait for it, it holds the agent back again (slow, not gone). */
    void heard(LayerContext ctx, SenderState o) {
        if (!o.silent) {
            return;
        }
        o.silent = false;
        if (o.heldOfAgent > 0 && !o.holding && on) {
            o.holding = true;
            if (congested++ == 0) {
                ctx.host().backpressure(true);
            }
        }
    }

    /** The window a receiver announced in its latest acknowledgement. */
    void credit(SenderState o, int announced) {
        o.credit = Math.max(0, announced);
    }

    /** Sends what is held for a receiver as far as its window allows; the agent goes on once none of its own is held. */
    void release(LayerContext ctx, SenderState o, Retransmission sender) {
        while (!o.held.isEmpty() && (windowOpen(o) || !on)) {
            Envelope env = o.held.poll();
            if (env.sentByAgent()) {
                o.heldOfAgent--;
            }
            sender.transmit(ctx, env, o);
        }
        if (o.heldOfAgent == 0 && o.holding) {
            o.holding = false;
            if (--congested == 0) {
                ctx.host().backpressure(false);
            }
        }
    }

    /**
     * The window to announce in an acknowledgement: the reorder window while the agent keeps up
     * with its mailbox, 0 while the mailbox is full (announced again when the agent has taken it
     * down, {@link Delivery#inboxDrained}).
     */
    int windowToAnnounce(LayerContext ctx, ReceiverState in) {
        in.closed = on && ctx.host().inboxFull();
        return in.closed ? 0 : reorderWindow;
    }
}
