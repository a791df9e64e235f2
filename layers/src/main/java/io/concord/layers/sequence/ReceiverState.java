package io.concord.layers.sequence;

import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * What the sequence layer keeps per sender: its stream and session, the next number expected,
 * the reorder buffer, the NAK and ACK timers, and whether the last acknowledgement shut the
 * window. Loop thread only.
 */
final class ReceiverState {
    int stream;
    /** The first sequence number of the stream this session got, or 0. */
    long since;
    long expected = 1;
    long highest;
    final Envelope[] buffer;
    final long[] bufferSeq;
    int buffered;
    Address address;
    long nakTimer = -1;
    int nakRetries;
    int sinceAck;
    long ackTimer = -1;
    /** The last acknowledgement told the sender that this agent's mailbox was full (window 0). */
    boolean closed;
    final Map<Integer, Long> oldStreams = new LinkedHashMap<>();
    final long[] resendAllowed = new long[8];

    ReceiverState(int window) {
        buffer = new Envelope[window];
        bufferSeq = new long[window];
    }
}
