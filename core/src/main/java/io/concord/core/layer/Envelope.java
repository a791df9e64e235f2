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
    private Object[] headers;

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

    /** The loop time at which the bytes arrived (going up). */
    public long arrivalNs() {
        return arrivalNs;
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
