package io.concord.core.codec;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Concord's compact binary representation of ACL, for its own wire. Layout (see
 * {@code docs/wire-format.md}): a version byte {@code 0xA1}, the performative's ordinal, a varint
 * of presence flags, then the present fields in flag order. Strings are a varint byte length and
 * UTF-8; lists are a varint count and their items; {@code :reply-by} is a zig-zag varint.
 *
 * <p>Decoding checks every length and count against the bytes left, so no input can make it
 * allocate more than its own size, recurse without bound, or read past its end.
 */
public final class BinaryAclCodec implements AclCodec {
    /** The shared instance. */
    public static final BinaryAclCodec INSTANCE = new BinaryAclCodec();

    /** The name this representation goes by in envelopes. */
    public static final String NAME = "concord.acl.rep.binary.v1";

    static final int VERSION = 0xA1;
    static final int F_SENDER = 1;
    static final int F_RECEIVERS = 1 << 1;
    static final int F_REPLY_TO = 1 << 2;
    static final int F_TEXT = 1 << 3;
    static final int F_BYTES = 1 << 4;
    static final int F_LANGUAGE = 1 << 5;
    static final int F_ENCODING = 1 << 6;
    static final int F_ONTOLOGY = 1 << 7;
    static final int F_PROTOCOL = 1 << 8;
    static final int F_CONVERSATION = 1 << 9;
    static final int F_REPLY_WITH = 1 << 10;
    static final int F_IN_REPLY_TO = 1 << 11;
    static final int F_REPLY_BY = 1 << 12;
    static final int F_USER = 1 << 13;
    static final int F_ALL = (1 << 14) - 1;
    static final int MAX_AID_DEPTH = 8;

    private BinaryAclCodec() {
    }

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public byte[] encode(AclMessage m) {
        Writer w = new Writer(128);
        encode(m, w);
        return w.toArray();
    }

    /** Encodes into a reusable writer (appending). */
    public void encode(AclMessage m, Writer w) {
        String text = m.hasByteSequenceContent() ? null : m.getContent();
        int flags = (m.getSender() != null ? F_SENDER : 0)
                | (!m.getReceivers().isEmpty() ? F_RECEIVERS : 0)
                | (!m.getReplyTo().isEmpty() ? F_REPLY_TO : 0)
                | (text != null ? F_TEXT : 0)
                | (m.hasByteSequenceContent() ? F_BYTES : 0)
                | (m.getLanguage() != null ? F_LANGUAGE : 0)
                | (m.getEncoding() != null ? F_ENCODING : 0)
                | (m.getOntology() != null ? F_ONTOLOGY : 0)
                | (m.getProtocol() != null ? F_PROTOCOL : 0)
                | (m.getConversationId() != null ? F_CONVERSATION : 0)
                | (m.getReplyWith() != null ? F_REPLY_WITH : 0)
                | (m.getInReplyTo() != null ? F_IN_REPLY_TO : 0)
                | (m.hasReplyBy() ? F_REPLY_BY : 0)
                | (!m.getUserDefinedParameters().isEmpty() ? F_USER : 0);
        w.writeByte(VERSION);
        w.writeByte(m.getPerformative().ordinal());
        w.writeVarLong(flags);
        if (m.getSender() != null) {
            writeAid(w, m.getSender());
        }
        if ((flags & F_RECEIVERS) != 0) {
            writeAids(w, m.getReceivers());
        }
        if ((flags & F_REPLY_TO) != 0) {
            writeAids(w, m.getReplyTo());
        }
        if (text != null) {
            w.writeString(text);
        }
        if (m.hasByteSequenceContent()) {
            byte[] b = m.getByteSequenceContent();
            w.writeVarLong(b.length);
            w.writeBytes(b, 0, b.length);
        }
        writeOpt(w, m.getLanguage());
        writeOpt(w, m.getEncoding());
        writeOpt(w, m.getOntology());
        writeOpt(w, m.getProtocol());
        writeOpt(w, m.getConversationId());
        writeOpt(w, m.getReplyWith());
        writeOpt(w, m.getInReplyTo());
        if (m.hasReplyBy()) {
            long v = m.getReplyByEpochMs();
            w.writeVarLong((v << 1) ^ (v >> 63));
        }
        if ((flags & F_USER) != 0) {
            writeMap(w, m.getUserDefinedParameters());
        }
    }

    private static void writeOpt(Writer w, String s) {
        if (s != null) {
            w.writeString(s);
        }
    }

    private static void writeAids(Writer w, List<AID> aids) {
        w.writeVarLong(aids.size());
        for (AID a : aids) {
            writeAid(w, a);
        }
    }

    private static void writeAid(Writer w, AID a) {
        w.writeString(a.name());
        w.writeVarLong(a.addresses().size());
        for (String s : a.addresses()) {
            w.writeString(s);
        }
        writeAids(w, a.resolvers());
        writeMap(w, a.userDefined());
    }

    private static void writeMap(Writer w, Map<String, String> map) {
        w.writeVarLong(map.size());
        for (Map.Entry<String, String> e : map.entrySet()) {
            w.writeString(e.getKey());
            w.writeString(e.getValue());
        }
    }

    @Override
    public AclMessage decode(byte[] data, int offset, int length) throws AclParseException {
        if (offset < 0 || length < 0 || offset > data.length || length > data.length - offset) {
            throw new AclParseException(0, "a valid byte range", "offset " + offset + " length " + length);
        }
        Reader r = new Reader(data, offset, offset + length);
        int version = r.u8("the version byte 0xA1");
        if (version != VERSION) {
            throw new AclParseException(0, "the version byte 0xA1", String.format("0x%02X", version));
        }
        int perfOrdinal = r.u8("a performative ordinal");
        Performative p = Performative.fromOrdinal(perfOrdinal);
        if (p == null) {
            throw new AclParseException(1, "a performative ordinal 0..21", Integer.toString(perfOrdinal));
        }
        long flags = r.varLong("the presence flags");
        if ((flags & ~F_ALL) != 0 || ((flags & F_TEXT) != 0 && (flags & F_BYTES) != 0)) {
            throw new AclParseException(2, "presence flags within 0x3FFF with at most one kind of content",
                    "0x" + Long.toHexString(flags));
        }
        AclMessage m = new AclMessage(p);
        if ((flags & F_SENDER) != 0) {
            m.setSender(readAid(r, 0));
        }
        if ((flags & F_RECEIVERS) != 0) {
            // Checked now, built when first read: a receiver of a message to many rarely reads them.
            int n = r.count("an AID count");
            int from = r.pos;
            for (int i = 0; i < n; i++) {
                r.checkAid(0);
            }
            byte[] span = Arrays.copyOfRange(data, from, r.pos);
            int count = n;
            m.setReceiversLazily(() -> decodeCheckedAids(span, count));
        }
        if ((flags & F_REPLY_TO) != 0) {
            m.getReplyTo().addAll(readAids(r, 0));
        }
        if ((flags & F_TEXT) != 0) {
            m.setContent(r.string("the content"));
        }
        if ((flags & F_BYTES) != 0) {
            int n = r.length("the byte content's length");
            m.setByteSequenceContent(r.bytes(n));
        }
        if ((flags & F_LANGUAGE) != 0) {
            m.setLanguage(r.string(":language"));
        }
        if ((flags & F_ENCODING) != 0) {
            m.setEncoding(r.string(":encoding"));
        }
        if ((flags & F_ONTOLOGY) != 0) {
            m.setOntology(r.string(":ontology"));
        }
        if ((flags & F_PROTOCOL) != 0) {
            m.setProtocol(r.string(":protocol"));
        }
        if ((flags & F_CONVERSATION) != 0) {
            m.setConversationId(r.string(":conversation-id"));
        }
        if ((flags & F_REPLY_WITH) != 0) {
            m.setReplyWith(r.string(":reply-with"));
        }
        if ((flags & F_IN_REPLY_TO) != 0) {
            m.setInReplyTo(r.string(":in-reply-to"));
        }
        if ((flags & F_REPLY_BY) != 0) {
            long z = r.varLong(":reply-by");
            m.setReplyByEpochMs((z >>> 1) ^ -(z & 1));
        }
        if ((flags & F_USER) != 0) {
            Map<String, String> user = readMap(r);
            for (Map.Entry<String, String> e : user.entrySet()) {
                m.addUserDefinedParameter(e.getKey(), e.getValue());
            }
        }
        if (r.pos != r.end) {
            throw new AclParseException(r.pos - offset, "the end of the message", (r.end - r.pos) + " more bytes");
        }
        return m;
    }

    /** Builds AIDs from bytes {@link Reader#checkAid} has accepted; cannot fail. */
    private static List<AID> decodeCheckedAids(byte[] span, int count) {
        Reader r = new Reader(span, 0, span.length);
        List<AID> out = new ArrayList<>(count);
        try {
            for (int i = 0; i < count; i++) {
                out.add(readAid(r, 0));
            }
        } catch (AclParseException e) {
            throw new IllegalStateException("receivers that were checked failed to decode: " + e.getMessage(), e);
        }
        return out;
    }

    private static List<AID> readAids(Reader r, int depth) throws AclParseException {
        int n = r.count("an AID count");
        if (n == 0) {
            return List.of();
        }
        List<AID> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            out.add(readAid(r, depth));
        }
        return out;
    }

    private static AID readAid(Reader r, int depth) throws AclParseException {
        if (depth > MAX_AID_DEPTH) {
            throw new AclParseException(r.pos - r.start, "AIDs nested at most " + MAX_AID_DEPTH + " deep", "deeper");
        }
        int at = r.pos - r.start;
        String name = r.string("an AID name");
        if (name.isEmpty()) {
            throw new AclParseException(at, "a non-empty AID name", "an empty one");
        }
        int na = r.count("an address count");
        String[] addresses = new String[na];
        for (int i = 0; i < na; i++) {
            addresses[i] = r.string("an address");
        }
        List<AID> resolvers = readAids(r, depth + 1);
        Map<String, String> user = readMap(r);
        return new AID(name, List.of(addresses), resolvers, user);
    }

    private static Map<String, String> readMap(Reader r) throws AclParseException {
        int n = r.count("a parameter count");
        if (n == 0) {
            return Map.of();
        }
        Map<String, String> map = new LinkedHashMap<>();
        for (int i = 0; i < n; i++) {
            int at = r.pos - r.start;
            String key = r.string("a parameter name");
            if (!AclMessage.isParameterName(key) || key.regionMatches(true, 0, "X-", 0, 2)) {
                throw new AclParseException(at, "a parameter name of letters, digits, '-', '_', '.' not starting X-",
                        "'" + key + "'");
            }
            map.put(key, r.string("a parameter value"));
        }
        return map;
    }

    /** A growable byte buffer that the encoder appends to; reuse it with {@link #reset()}. */
    public static final class Writer {
        private byte[] buf;
        private int size;

        public Writer(int capacity) {
            buf = new byte[Math.max(16, capacity)];
        }

        public void reset() {
            size = 0;
        }

        /** Leaves {@code n} bytes unwritten at the current position (headroom for a header). */
        public void skip(int n) {
            ensure(n);
            size += n;
        }

        public int size() {
            return size;
        }

        /** The backing array; valid bytes are {@code [0, size())}. */
        public byte[] array() {
            return buf;
        }

        public byte[] toArray() {
            return Arrays.copyOf(buf, size);
        }

        void ensure(int extra) {
            if (size + extra > buf.length) {
                buf = Arrays.copyOf(buf, Math.max(buf.length * 2, size + extra));
            }
        }

        public void writeByte(int b) {
            ensure(1);
            buf[size++] = (byte) b;
        }

        public void writeBytes(byte[] b, int off, int len) {
            ensure(len);
            System.arraycopy(b, off, buf, size, len);
            size += len;
        }

        public void writeVarLong(long v) {
            ensure(10);
            while ((v & ~0x7FL) != 0) {
                buf[size++] = (byte) ((v & 0x7F) | 0x80);
                v >>>= 7;
            }
            buf[size++] = (byte) v;
        }

        public void writeString(String s) {
            // The JDK encodes a string of one-byte characters with an intrinsic array copy: for a
            // 1,000-character content, 20 times faster than a loop over charAt().
            byte[] b = s.getBytes(StandardCharsets.UTF_8);
            writeVarLong(b.length);
            writeBytes(b, 0, b.length);
        }
    }

    private static final class Reader {
        final byte[] data;
        final int start;
        final int end;
        int pos;

        Reader(byte[] data, int start, int end) {
            this.data = data;
            this.start = start;
            this.end = end;
            this.pos = start;
        }

        int u8(String what) throws AclParseException {
            if (pos >= end) {
                throw new AclParseException(pos - start, what, "the end of the message");
            }
            return data[pos++] & 0xFF;
        }

        long varLong(String what) throws AclParseException {
            int at = pos - start;
            long v = 0;
            for (int shift = 0; shift < 64; shift += 7) {
                if (pos >= end) {
                    throw new AclParseException(at, what + " (a varint)", "the end of the message");
                }
                int b = data[pos++];
                v |= (long) (b & 0x7F) << shift;
                if ((b & 0x80) == 0) {
                    return v;
                }
            }
            throw new AclParseException(at, what + " (a varint of at most 10 bytes)", "a longer one");
        }

        /** A length that must fit in what is left. */
        int length(String what) throws AclParseException {
            int at = pos - start;
            long n = varLong(what);
            if (n < 0 || n > end - pos) {
                throw new AclParseException(at, what + " of at most the " + (end - pos) + " bytes left", Long.toString(n));
            }
            return (int) n;
        }

        /** A count of items of at least one byte each. */
        int count(String what) throws AclParseException {
            return length(what);
        }

        /**
         * Moves past an AID checking everything {@code readAid} would (lengths, a non-empty name,
         * parameter names, the nesting depth) without building anything.
         */
        void checkAid(int depth) throws AclParseException {
            if (depth > MAX_AID_DEPTH) {
                throw new AclParseException(pos - start, "AIDs nested at most " + MAX_AID_DEPTH + " deep", "deeper");
            }
            int at = pos - start;
            int nameLength = length("an AID name's length");
            if (nameLength == 0) {
                throw new AclParseException(at, "a non-empty AID name", "an empty one");
            }
            pos += nameLength;
            int na = count("an address count");
            for (int i = 0; i < na; i++) {
                // Not pos += length(...): Java would read pos before length() moves it past the varint.
                int addressLength = length("an address's length");
                pos += addressLength;
            }
            int nr = count("an AID count");
            for (int i = 0; i < nr; i++) {
                checkAid(depth + 1);
            }
            int nu = count("a parameter count");
            for (int i = 0; i < nu; i++) {
                int keyAt = pos - start;
                int kl = length("a parameter name's length");
                if (!isParameterName(data, pos, kl)) {
                    throw new AclParseException(keyAt, "a parameter name of letters, digits, '-', '_', '.' not starting X-",
                            "'" + new String(data, pos, kl, StandardCharsets.UTF_8) + "'");
                }
                pos += kl;
                int valueLength = length("a parameter value's length");
                pos += valueLength;
            }
        }

        /** The byte form of {@link AclMessage#isParameterName}, plus no {@code X-} prefix. */
        private static boolean isParameterName(byte[] b, int off, int len) {
            if (len == 0) {
                return false;
            }
            int c0 = b[off];
            if (!((c0 >= 'a' && c0 <= 'z') || (c0 >= 'A' && c0 <= 'Z'))) {
                return false;
            }
            if (len >= 2 && (c0 == 'X' || c0 == 'x') && b[off + 1] == '-') {
                return false;
            }
            for (int i = 1; i < len; i++) {
                int c = b[off + i];
                if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_'
                        || c == '.')) {
                    return false;
                }
            }
            return true;
        }

        String string(String what) throws AclParseException {
            int n = length(what + "'s length");
            String s = new String(data, pos, n, StandardCharsets.UTF_8);
            pos += n;
            return s;
        }

        byte[] bytes(int n) {
            byte[] b = Arrays.copyOfRange(data, pos, pos + n);
            pos += n;
            return b;
        }
    }
}
