package io.concord.core.content;

import java.time.Instant;
import java.time.ZoneOffset;
import java.util.Base64;
import java.util.List;

/** The SL writer; see {@link SlCodec}. */
final class SlWriter {
    private static final java.util.regex.Pattern NUMBER = java.util.regex.Pattern.compile(
            "[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?");
    private final StringBuilder out = new StringBuilder();
    private final SlCodec codec;

    private SlWriter(SlCodec codec) {
        this.codec = codec;
    }

    static String write(List<? extends AbsObject> elements, SlCodec codec) throws ContentException {
        if (elements.isEmpty()) {
            throw new ContentException("empty content expression");
        }
        SlWriter w = new SlWriter(codec);
        w.out.append('(');
        for (AbsObject e : elements) {
            w.term(e, 1);
            // JADE writes a list of several elements with a space after each: (a b )
            if (elements.size() > 1) {
                w.out.append(' ');
            }
        }
        w.out.append(')');
        return w.out.toString();
    }

    private void term(AbsObject o, int depth) throws ContentException {
        if (o instanceof AbsPrimitive p) {
            primitive(p.value());
        } else if (o instanceof AbsVariable v) {
            out.append('?').append(v.name());
        } else if (o instanceof AbsAggregate a) {
            open(a.type(), depth);
            for (AbsObject e : a.elements()) {
                out.append(' ');
                term(e, depth + 1);
            }
            out.append(')');
        } else {
            AbsCompound c = (AbsCompound) o;
            String wrong = codec.checkOperator(c);
            if (wrong != null) {
                throw new ContentException(wrong);
            }
            open(c.name(), depth);
            for (AbsCompound.Slot s : c.slots()) {
                out.append(' ');
                if (s.name() != null) {
                    out.append(':').append(s.name()).append(' ');
                }
                term(s.value(), depth + 1);
            }
            out.append(')');
        }
    }

    private void open(String name, int depth) throws ContentException {
        if (depth + 1 > codec.maxDepth()) {
            throw new ContentException("content nested deeper than the limit of " + codec.maxDepth());
        }
        if (!isSymbol(name)) {
            throw new ContentException("not an SL symbol: '" + name + "'");
        }
        out.append('(').append(name);
    }

    private void primitive(Object v) throws ContentException {
        if (v instanceof String s) {
            string(s);
        } else if (v instanceof Instant t) {
            out.append(SlReader.DATE.format(t.atOffset(ZoneOffset.UTC))).append('Z');
        } else if (v instanceof byte[] b) {
            String text = Base64.getEncoder().encodeToString(b);
            out.append('#').append(text.length()).append('"').append(text);
        } else if (v instanceof Double d && !Double.isFinite(d)) {
            throw new ContentException("SL has no number " + d);
        } else if (v instanceof Float f && !Float.isFinite(f)) {
            throw new ContentException("SL has no number " + f);
        } else {
            out.append(v);
        }
    }

    private void string(String s) throws ContentException {
        if (isWord(s)) {
            out.append(s);
            return;
        }
        if (s.endsWith("\\") || s.contains("\\\"")) {
            throw new ContentException("a string with a backslash at its end or before a quote cannot be"
                    + " written in SL as JADE reads it");
        }
        out.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '"') {
                out.append('\\');
            }
            out.append(c);
        }
        out.append('"');
    }

    /** A name the reader takes as a compound's symbol. */
    static boolean isSymbol(String s) {
        if (s.isEmpty() || "#:?".indexOf(s.charAt(0)) >= 0) {
            return false;
        }
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c <= ' ' || c == '(' || c == ')' || c == '"') {
                return false;
            }
        }
        return true;
    }

    /**
     * A string JADE's writer leaves bare: not empty; no character at or below U+0020, above
     * U+007F, or among {@code "()}; a first character that is not one of {@code #-0123456789:?};
     * not {@code true} or {@code false} in any case. One deviation from JADE: a string that reads as
     * a number ({@code +1}, {@code .5}) is quoted, where JADE leaves it bare and then reads a number.
     */
    static boolean isWord(String s) {
        if (s.isEmpty() || "#-0123456789:?".indexOf(s.charAt(0)) >= 0 || NUMBER.matcher(s).matches()
                || s.equalsIgnoreCase("true") || s.equalsIgnoreCase("false")) {
            return false;
        }
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c <= ' ' || c > 0x7f || c == '(' || c == ')' || c == '"') {
                return false;
            }
        }
        return true;
    }
}
