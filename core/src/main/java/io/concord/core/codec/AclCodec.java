package io.concord.core.codec;

import io.concord.core.acl.AclMessage;

/** Turns ACL messages into bytes and back. Implementations are thread-safe and stateless. */
public interface AclCodec {

    /** The FIPA name of this representation, e.g. {@code fipa.acl.rep.string.std}. */
    String name();

    /** Encodes a message. */
    byte[] encode(AclMessage msg);

    /**
     * Decodes a whole message from {@code data[offset, offset+length)}.
     *
     * @throws AclParseException if the input is not exactly one well-formed message; no other
     *                           exception escapes, whatever the input
     */
    AclMessage decode(byte[] data, int offset, int length) throws AclParseException;

    /** Decodes a whole array. */
    default AclMessage decode(byte[] data) throws AclParseException {
        return decode(data, 0, data.length);
    }
}
