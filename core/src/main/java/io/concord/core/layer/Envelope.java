package io.concord.core.layer;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.net.Address;

import java.util.Arrays;

/**
 * What layers pass to each other: one message for one receiver. Above the codec it carries the
 * {@link AclMessage}; below it the encoded bytes; on the way up, the transport source. Each layer
 * may attach its own header under a small numeric id (as JGroups protocols do), so layers never
 * parse each other's data.
 */
public final class Envelope {
    private AclMessage message;
    private AID receiver;
    private byte[] data;
    private int offset;
    private int length;
    private Address source;
    private Address destination;
    private long arrivalNs;
    private long peerId;
    private Object[] headers;
    private int lane;
    private boolean report;
    private boolean byAgent;

    /** An envelope going down: a message for one of its receivers. */
    public static Envelope outgoing(AclMessage message, AID receiver, Address destination) {
        Envelope e = new Envelope();
        e.message = message;
        e.receiver = receiver;
        e.destination = destination;
        return e;
    }

    /** An envelope coming up: bytes that arrived from a source. The bytes are not copied. */
    public static Envelope incoming(Address source, byte[] data, int offset, int length, long arrivalNs) {
        Envelope e = new Envelope();
        e.source = source;
        e.data = data;
        e.offset = offset;
        e.length = length;
        e.arrivalNs = arrivalNs;
        return e;
    }

    public AclMessage message() {
        return message;
    }

    public void setMessage(AclMessage message) {
        this.message = message;
    }

    /** The receiver this copy is for (going down). */
    public AID receiver() {
        return receiver;
    }

    public byte[] data() {
        return data;
    }

    public int offset() {
        return offset;
    }

    public int length() {
        return length;
    }

    /** Replaces the bytes. */
    public void setData(byte[] data, int offset, int length) {
        this.data = data;
        this.offset = offset;
        this.length = length;
    }

    /** The bytes as an array of their own (copies only if they are a slice). */
    public byte[] dataCopy() {
        if (offset == 0 && length == data.length) {
            return data;
        }
        return Arrays.copyOfRange(data, offset, offset + length);
    }

    /** Makes the bytes this envelope's own, so that it may be kept past the receive call. */
    public void detachData() {
        if (data != null) {
            data = Arrays.copyOfRange(data, offset, offset + length);
            offset = 0;
        }
    }

    /** Where the bytes came from (going up). */
    public Address source() {
        return source;
    }

    /** Where the bytes go (going down). */
    public Address destination() {
        return destination;
    }

    public void setDestination(Address destination) {
        this.destination = destination;
    }

    /**
     * The peer's frame id: going down, the destination's; going up, the authenticated source's
     * (set by the security layer). 0 until someone sets it.
     */
    public long peerId() {
        return peerId;
    }

    public void setPeerId(long peerId) {
        this.peerId = peerId;
    }

    /** An envelope for a control frame of a layer (no ACL message), to a peer's id and address. */
    public static Envelope control(long peerId, Address destination, byte[] data, int offset, int length) {
        Envelope e = new Envelope();
        e.peerId = peerId;
        e.destination = destination;
        e.setData(data, offset, length);
        return e;
    }

    /**
     * Makes room for {@code n} bytes before the current data (a lower layer's header) and returns
     * where they start. Uses the headroom left by the layer that made the bytes, else reallocates.
     */
    public int prepend(int n) {
        if (offset < n) {
            int headroom = Math.max(n, 64);
            byte[] grown = new byte[headroom + length + 32];
            System.arraycopy(data, offset, grown, headroom, length);
            data = grown;
            offset = headroom;
        }
        offset -= n;
        length += n;
        return offset;
    }

    /** Makes room for {@code n} bytes after the current data (a trailer) and returns where they start. */
    public int append(int n) {
        int end = offset + length;
        if (end + n > data.length) {
            byte[] grown = new byte[offset + length + n + 32];
            System.arraycopy(data, offset, grown, offset, length);
            data = grown;
        }
        length += n;
        return end;
    }

    /** Drops {@code n} bytes from the front (a header that has been read). */
    public void skip(int n) {
        if (n > length) {
            throw new IllegalArgumentException("cannot skip " + n + " of " + length + " bytes");
        }
        offset += n;
        length -= n;
    }

    /** Drops {@code n} bytes from the end (a trailer that has been read). */
    public void trim(int n) {
        if (n > length) {
            throw new IllegalArgumentException("cannot trim " + n + " of " + length + " bytes");
        }
        length -= n;
    }

    /** The loop time at which the bytes arrived (going up). */
    public long arrivalNs() {
        return arrivalNs;
    }

    /**
     * The lane this frame goes out on (0 unless set): frames of one lane to one address may share
     * a datagram; the copies of one frame, sent against loss, go on lanes of their own.
     */
    public int lane() {
        return lane;
    }

    /** Sets the lane (see {@link #lane()}). */
    public void lane(int lane) {
        this.lane = lane;
    }

    /**
     * True for a report the platform makes on its own (a sniffer's event): when its receiver
     * cannot take it now, the sending layer refuses it ({@link SendRejectedException}) rather than
     * holding it, so that an observer that is behind holds the observed agent back in nothing.
     */
    public boolean isReport() {
        return report;
    }

    /** Marks this envelope as a report (see {@link #isReport()}); returns it. */
    public Envelope report() {
        this.report = true;
        return this;
    }

    /**
     * True for a message the agent itself sent (its behaviours, through {@code send}), false for
     * what the layers send on their own (the platform's lists and heartbeats, a sniffer's events,
     * acknowledgements): flow control pauses an agent only for its own messages.
     */
    public boolean sentByAgent() {
        return byAgent;
    }

    /** Marks this envelope as the agent's own message (see {@link #sentByAgent()}); returns it. */
    public Envelope markSentByAgent() {
        this.byAgent = true;
        return this;
    }

    /** A layer's header, or {@code null}. */
    @SuppressWarnings("unchecked")
    public <T> T header(int id) {
        return headers == null || id >= headers.length ? null : (T) headers[id];
    }

    /** Sets a layer's header under its id (0..63). */
    public void putHeader(int id, Object header) {
        if (id < 0 || id > 63) {
            throw new IllegalArgumentException("header ids are 0..63, got " + id);
        }
        if (headers == null) {
            headers = new Object[Math.max(4, id + 1)];
        } else if (id >= headers.length) {
            headers = Arrays.copyOf(headers, id + 1);
        }
        headers[id] = header;
    }

    @Override
    public String toString() {
        return "Envelope[" + (message != null ? message.getPerformative() + " " : "")
                + (receiver != null ? "to " + receiver.name() + " " : "")
                + (source != null ? "from " + source + " " : "")
                + (data != null ? length + " bytes" : "") + "]";
    }
}
