package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;

import java.util.ArrayDeque;
import java.util.LinkedHashSet;
import java.util.Set;

/**
 * What the sequence layer keeps per receiver: the numbers sent and acknowledged, the frames kept
 * for retransmission, the probe, and the flow window's share (the receiver's credit and the
 * frames held for it). Loop thread only.
 */
final class SenderState {
    long nextSeq = 1;
    long acked;
    /** The receiver's session, from its acknowledgements; 0 until the first. */
    int peerSession;
    final Set<Integer> endedSessions = new LinkedHashSet<>();
    Address address;
    final byte[][] ring;
    final long[] ringSeq;
    final int[] ringLen;
    long probeTimer = -1;
    int probes;
    /** Frames past the acknowledged ones the receiver takes (its window); -1 until it says. */
    int credit = -1;
    /** Frames that wait for the receiver's window to open, in order: the agent's own and the layers'. */
    final ArrayDeque<Envelope> held = new ArrayDeque<>();
    /** Of {@link #held}, the agent's own messages (the rest the layers sent): only these hold the agent back. */
    int heldOfAgent;
    /** Counted among the receivers that hold the agent back. */
    boolean holding;
    /**
     * The receiver has not acknowledged anything for {@link FlowWindow#SILENT_MS} while frames
     * wait for it (stopped, gone, cut off): what waits for it still waits, but it no longer holds
     * the agent back, whose other conversations go on. Cleared by its next acknowledgement.
     */
    boolean silent;
    /** When this receiver last acknowledged something new, or when frames began to wait for it unacknowledged. */
    long progressNs = Long.MIN_VALUE;
    /**
     * When this receiver last answered at all (an acknowledgement of nothing new, a shut window's
     * answer to a probe included): a receiver that has taken everything and shut its window is
     * slow while it answers, silent once it stops.
     */
    long heardNs = Long.MIN_VALUE;

    SenderState(int size) {
        ring = new byte[size][];
        ringSeq = new long[size];
        ringLen = new int[size];
    }
}
