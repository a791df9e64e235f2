package io.concord.core.content;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A compact binary form of the same abstract content SL carries, for agents that do not need
 * text (in the spirit of JADE's LEAP language). A content is a version byte ({@value #VERSION})
 * then the element count and elements; each value is a tag byte then its body. Integers are
 * zig-zag varints, floating point numbers IEEE 754 big-endian, strings and byte strings a varint
 * length then the bytes (UTF-8 for strings), dates epoch milliseconds. Symbols and slot names are
 * written once and then referred to by number. Limits as {@link SlCodec}'s: nesting depth and
 * input size; every count is checked against the bytes left, so a reader allocates no more than
 * the input's size. Instances are immutable and thread-safe.
 */
public final class BinaryContentCodec {
    /** The format's version, its first byte. */
    public static final int VERSION = 1;
    /** The language name for the message's {@code :language} slot. */
    public static final String LANGUAGE = "concord-binary";

    static final int STRING = 1, LONG = 2, INT = 3, DOUBLE = 4, FLOAT = 5, TRUE = 6, FALSE = 7, DATE = 8,
            BYTES = 9, VARIABLE = 10, SEQUENCE = 11, SET = 12, NAMED = 13, POSITIONAL = 14;

    private final int maxDepth;
    private final int maxBytes;

    /** With {@link SlCodec}'s default limits. */
    public BinaryContentCodec() {
        this(SlCodec.DEFAULT_MAX_DEPTH, SlCodec.DEFAULT_MAX_CHARS);
    }

    /**
     * With limits.
     *
     * @param maxDepth the deepest nesting read or written, at least 2
     * @param maxBytes the largest input read, at least 2
     */
    public BinaryContentCodec(int maxDepth, int maxBytes) {
        if (maxDepth < 2 || maxBytes < 2) {
            throw new IllegalArgumentException("maxDepth and maxBytes must be at least 2");
        }
        this.maxDepth = maxDepth;
        this.maxBytes = maxBytes;
    }

    /** The language name, {@value #LANGUAGE}. */
    public String languageName() {
        return LANGUAGE;
    }

    /** Writes a content expression. */
    public byte[] write(List<? extends AbsObject> elements) throws ContentException {
        if (elements.isEmpty()) {
            throw new ContentException("empty content expression");
        }
        Writer w = new Writer();
        w.out.write(VERSION);
        w.varint(elements.size());
        for (AbsObject e : elements) {
            w.value(e, 2);
        }
        return w.out.toByteArray();
    }

    /** Reads a content expression; a malformed input names the byte offset. */
    public List<AbsObject> read(byte[] bytes) throws ContentException {
        if (bytes.length > maxBytes) {
            throw new ContentException("content of " + bytes.length + " bytes is over the limit of " + maxBytes);
        }
        Reader r = new Reader(bytes);
        int version = r.u8();
        if (version != VERSION) {
            throw r.error("unknown version " + version);
        }
        int n = r.count();
        if (n == 0) {
            throw r.error("empty content expression");
        }
        List<AbsObject> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            out.add(r.value(2));
        }
        if (r.pos != bytes.length) {
            throw r.error("bytes after the content expression");
        }
        return out;
    }

    private final class Writer {
        final ByteArrayOutputStream out = new ByteArrayOutputStream();
        final Map<String, Integer> names = new HashMap<>();

        void value(AbsObject o, int depth) throws ContentException {
            if (depth > maxDepth) {
                throw new ContentException("content nested deeper than the limit of " + maxDepth);
            }
            if (o instanceof AbsPrimitive p) {
                primitive(p.value());
            } else if (o instanceof AbsVariable v) {
                out.write(VARIABLE);
                string(v.name());
            } else if (o instanceof AbsAggregate a) {
                out.write(a.type().equals(AbsAggregate.SET) ? SET : SEQUENCE);
                varint(a.elements().size());
                for (AbsObject e : a.elements()) {
                    value(e, depth + 1);
                }
            } else {
                AbsCompound c = (AbsCompound) o;
                out.write(c.isNamed() ? NAMED : POSITIONAL);
                name(c.name());
                varint(c.slots().size());
                for (AbsCompound.Slot s : c.slots()) {
                    if (s.name() != null) {
                        name(s.name());
                    }
                    value(s.value(), depth + 1);
                }
            }
        }

        void primitive(Object v) {
            if (v instanceof String s) {
                out.write(STRING);
                string(s);
            } else if (v instanceof Long l) {
                out.write(LONG);
                zigzag(l);
            } else if (v instanceof Integer i) {
                out.write(INT);
                zigzag(i);
            } else if (v instanceof Double d) {
                out.write(DOUBLE);
                fixed(Double.doubleToLongBits(d), 8);
            } else if (v instanceof Float f) {
                out.write(FLOAT);
                fixed(Float.floatToIntBits(f), 4);
            } else if (v instanceof Boolean b) {
                out.write(b ? TRUE : FALSE);
            } else if (v instanceof Instant t) {
                out.write(DATE);
                zigzag(t.toEpochMilli());
            } else {
                byte[] b = (byte[]) v;
                out.write(BYTES);
                varint(b.length);
                out.writeBytes(b);
            }
        }

        void name(String s) {
            Integer ref = names.get(s);
            if (ref != null) {
                varint(ref + 1);
            } else {
                names.put(s, names.size());
                varint(0);
                string(s);
            }
        }

        void string(String s) {
            byte[] b = s.getBytes(StandardCharsets.UTF_8);
            varint(b.length);
            out.writeBytes(b);
        }

        void zigzag(long v) {
            varint((v << 1) ^ (v >> 63));
        }

        void varint(long v) {
            while ((v & ~0x7FL) != 0) {
                out.write((int) ((v & 0x7F) | 0x80));
                v >>>= 7;
            }
            out.write((int) v);
        }

        void fixed(long bits, int bytes) {
            for (int i = bytes - 1; i >= 0; i--) {
                out.write((int) (bits >>> (8 * i)));
            }
        }
    }

    private final class Reader {
        final byte[] in;
        final List<String> names = new ArrayList<>();
        int pos;

        Reader(byte[] in) {
            this.in = in;
        }

        AbsObject value(int depth) throws ContentException {
            if (depth > maxDepth) {
                throw error("nesting deeper than the limit of " + maxDepth);
            }
            int at = pos;
            int tag = u8();
            switch (tag) {
                case STRING: return new AbsPrimitive(string());
                case LONG: return new AbsPrimitive(zigzag());
                case INT: {
                    long v = zigzag();
                    if (v < Integer.MIN_VALUE || v > Integer.MAX_VALUE) {
                        throw error("int out of range");
                    }
                    return new AbsPrimitive((int) v);
                }
                case DOUBLE: {
                    double d = Double.longBitsToDouble(fixed(8));
                    if (!Double.isFinite(d)) {
                        throw error("number out of range");
                    }
                    return new AbsPrimitive(d);
                }
                case FLOAT: {
                    float f = Float.intBitsToFloat((int) fixed(4));
                    if (!Float.isFinite(f)) {
                        throw error("number out of range");
                    }
                    return new AbsPrimitive(f);
                }
                case TRUE: return new AbsPrimitive(Boolean.TRUE);
                case FALSE: return new AbsPrimitive(Boolean.FALSE);
                case DATE: {
                    try {
                        return new AbsPrimitive(Instant.ofEpochMilli(zigzag()));
                    } catch (RuntimeException e) {
                        throw error("date out of range");
                    }
                }
                case BYTES: {
                    int n = count();
                    byte[] b = java.util.Arrays.copyOfRange(in, pos, pos + n);
                    pos += n;
                    return new AbsPrimitive(b);
                }
                case VARIABLE: {
                    String name = string();
                    if (name.isEmpty()) {
                        throw error("empty variable name");
                    }
                    return new AbsVariable(name);
                }
                case SEQUENCE:
                case SET: {
                    int n = count();
                    List<AbsObject> elements = new ArrayList<>(n);
                    for (int i = 0; i < n; i++) {
                        elements.add(value(depth + 1));
                    }
                    return new AbsAggregate(tag == SET ? AbsAggregate.SET : AbsAggregate.SEQUENCE, elements);
                }
                case NAMED:
                case POSITIONAL: {
                    String name = name();
                    int n = count();
                    List<AbsCompound.Slot> slots = new ArrayList<>(n);
                    for (int i = 0; i < n; i++) {
                        String slot = tag == NAMED ? name() : null;
                        slots.add(new AbsCompound.Slot(slot, value(depth + 1)));
                    }
                    return new AbsCompound(name, slots);
                }
                default:
                    pos = at;
                    throw error("unknown tag " + tag);
            }
        }

        String name() throws ContentException {
            long ref = varint();
            if (ref == 0) {
                String s = string();
                if (s.isEmpty()) {
                    throw error("empty name");
                }
                names.add(s);
                return s;
            }
            if (ref < 0 || ref > names.size()) {
                throw error("reference to unknown name " + ref);
            }
            return names.get((int) ref - 1);
        }

        String string() throws ContentException {
            int n = count();
            String s = new String(in, pos, n, StandardCharsets.UTF_8);
            pos += n;
            return s;
        }

        /** A count or length, which cannot be more than the bytes left. */
        int count() throws ContentException {
            long n = varint();
            if (n < 0 || n > in.length - pos) {
                throw error("count " + n + " runs past the end");
            }
            return (int) n;
        }

        long zigzag() throws ContentException {
            long v = varint();
            return (v >>> 1) ^ -(v & 1);
        }

        long varint() throws ContentException {
            long v = 0;
            for (int shift = 0; shift < 64; shift += 7) {
                int b = u8();
                v |= (long) (b & 0x7F) << shift;
                if ((b & 0x80) == 0) {
                    return v;
                }
            }
            throw error("varint too long");
        }

        long fixed(int bytes) throws ContentException {
            long v = 0;
            for (int i = 0; i < bytes; i++) {
                v = (v << 8) | u8();
            }
            return v;
        }

        int u8() throws ContentException {
            if (pos >= in.length) {
                throw error("unexpected end of content");
            }
            return in[pos++] & 0xFF;
        }

        ContentException error(String what) {
            return new ContentException(what + " at byte " + pos);
        }
    }
}
