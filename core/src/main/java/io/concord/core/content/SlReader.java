package io.concord.core.content;

import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.regex.Pattern;

/** One pass of the SL reader over one text; see {@link SlCodec}. */
final class SlReader {
    static final DateTimeFormatter DATE = DateTimeFormatter.ofPattern("uuuuMMdd'T'HHmmssSSS");
    private static final Pattern INTEGER = Pattern.compile("[-+]?[0-9]+");
    private static final Pattern HEX = Pattern.compile("[-+]?0[xX][0-9a-fA-F]+");
    private static final Pattern FLOAT = Pattern.compile(
            "[-+]?([0-9]+\\.[0-9]*|\\.[0-9]+|[0-9]+)([eE][-+]?[0-9]+)?");
    private static final Pattern DATE_TOKEN = Pattern.compile("[+-]?[0-9]{8}[tT][0-9]{9}[a-zA-Z]?");

    private final String s;
    private final SlCodec codec;
    private int pos;

    SlReader(String text, SlCodec codec) {
        this.s = text;
        this.codec = codec;
    }

    List<AbsObject> content() throws SlParseException {
        skipSpace();
        expect('(');
        List<AbsObject> elements = new ArrayList<>();
        skipSpace();
        while (peek() != ')') {
            elements.add(term(1));
            skipSpace();
        }
        pos++;
        skipSpace();
        if (pos < s.length()) {
            throw error("text after the content expression");
        }
        if (elements.isEmpty()) {
            throw error("empty content expression");
        }
        return elements;
    }

    private AbsObject term(int depth) throws SlParseException {
        char c = peek();
        switch (c) {
            case '(':
                return compound(depth + 1);
            case '"':
                return new AbsPrimitive(quoted());
            case '#':
                return byteString();
            case '?':
                if (s.startsWith("??", pos)) {
                    // JADE's writer leaves a string starting with "??" bare (SL's meta symbol)
                    return new AbsPrimitive(token());
                }
                return variable();
            case ')':
                throw error("unexpected ')'");
            case ':':
                throw error("unexpected slot name");
            default:
                return constant();
        }
    }

    private AbsObject compound(int depth) throws SlParseException {
        int start = pos;
        if (depth > codec.maxDepth()) {
            throw error("nesting deeper than the limit of " + codec.maxDepth());
        }
        pos++;
        skipSpace();
        char first = peek();
        if (first == '(' || first == '"' || first == ')' || first == ':' || first == '?' || first == '#') {
            throw error("expected a symbol after '('");
        }
        String name = token();
        if (name.isEmpty()) {
            throw error("expected a symbol after '('");
        }
        List<AbsObject> positional = new ArrayList<>();
        List<AbsCompound.Slot> slots = new ArrayList<>();
        skipSpace();
        while (peek() != ')') {
            if (peek() == ':') {
                pos++;
                int at = pos;
                String slot = token();
                if (slot.isEmpty()) {
                    throw new SlParseException("empty slot name", at);
                }
                skipSpace();
                if (peek() == ')' || peek() == ':') {
                    throw error("slot :" + slot + " has no value");
                }
                slots.add(new AbsCompound.Slot(slot, term(depth)));
            } else {
                positional.add(term(depth));
            }
            skipSpace();
        }
        pos++;
        if (name.equals(AbsAggregate.SEQUENCE) || name.equals(AbsAggregate.SET)) {
            if (!slots.isEmpty()) {
                throw new SlParseException("aggregate " + name + " has a named slot", start);
            }
            return new AbsAggregate(name, positional);
        }
        if (!slots.isEmpty() && !positional.isEmpty()) {
            throw new SlParseException(name + " mixes named and positional arguments", start);
        }
        AbsCompound result;
        if (slots.isEmpty()) {
            result = AbsCompound.positional(name, positional.toArray(AbsObject[]::new));
        } else {
            result = new AbsCompound(name, slots);
        }
        String wrong = codec.checkOperator(result);
        if (wrong != null) {
            throw new SlParseException(wrong, start);
        }
        return result;
    }

    private String quoted() throws SlParseException {
        int start = pos;
        pos++;
        StringBuilder b = new StringBuilder();
        while (pos < s.length()) {
            char c = s.charAt(pos++);
            if (c == '"') {
                return b.toString();
            }
            if (c == '\\' && pos < s.length()) {
                char n = s.charAt(pos++);
                if (n != '"') {
                    b.append('\\');
                }
                b.append(n);
            } else {
                b.append(c);
            }
        }
        throw new SlParseException("unterminated string", start);
    }

    private AbsObject byteString() throws SlParseException {
        int start = pos;
        pos++;
        int digits = pos;
        while (pos < s.length() && s.charAt(pos) >= '0' && s.charAt(pos) <= '9') {
            pos++;
        }
        if (pos == digits || pos - digits > 9 || pos >= s.length() || s.charAt(pos) != '"') {
            throw new SlParseException("malformed byte string, expected #<length>\"", start);
        }
        int length = Integer.parseInt(s.substring(digits, pos));
        pos++;
        if (length > s.length() - pos) {
            throw new SlParseException("byte string of " + length + " characters runs past the end", start);
        }
        String body = s.substring(pos, pos + length);
        pos += length;
        try {
            return new AbsPrimitive(Base64.getDecoder().decode(body));
        } catch (IllegalArgumentException e) {
            throw new SlParseException("byte string is not Base64", start);
        }
    }

    private AbsObject variable() throws SlParseException {
        int start = pos;
        pos++;
        String name = token();
        if (name.isEmpty() || name.startsWith("?")) {
            throw new SlParseException("malformed variable", start);
        }
        return new AbsVariable(name);
    }

    private AbsObject constant() throws SlParseException {
        int start = pos;
        String t = token();
        if (t.isEmpty()) {
            throw error("expected a term");
        }
        char c = t.charAt(0);
        // JADE's writer leaves strings that start with '+' or '.' bare, so only these start a number
        boolean numeric = (c >= '0' && c <= '9') || c == '-';
        if (!numeric) {
            if (t.equalsIgnoreCase("true")) {
                return new AbsPrimitive(Boolean.TRUE);
            }
            if (t.equalsIgnoreCase("false")) {
                return new AbsPrimitive(Boolean.FALSE);
            }
            return new AbsPrimitive(t);
        }
        try {
            if (INTEGER.matcher(t).matches()) {
                return new AbsPrimitive(Long.parseLong(t.startsWith("+") ? t.substring(1) : t));
            }
            if (HEX.matcher(t).matches()) {
                boolean negative = t.startsWith("-");
                String digits = t.substring(t.indexOf('x') + t.indexOf('X') + 2);
                long v = Long.parseLong(digits, 16);
                return new AbsPrimitive(negative ? -v : v);
            }
            if (DATE_TOKEN.matcher(t).matches()) {
                String body = t.replaceFirst("^[+-]", "").substring(0, 18).replace('t', 'T');
                return new AbsPrimitive(LocalDateTime.parse(body, DATE).toInstant(ZoneOffset.UTC));
            }
            if (FLOAT.matcher(t).matches()) {
                double d = Double.parseDouble(t);
                if (Double.isInfinite(d)) {
                    throw new SlParseException("number out of range", start);
                }
                return new AbsPrimitive(d);
            }
        } catch (NumberFormatException | DateTimeParseException e) {
            throw new SlParseException("malformed number or date '" + clip(t) + "'", start);
        }
        throw new SlParseException("malformed number or date '" + clip(t) + "'", start);
    }

    /** Characters up to white space, a parenthesis or a quote. */
    private String token() {
        int start = pos;
        while (pos < s.length()) {
            char c = s.charAt(pos);
            if (c <= ' ' || c == '(' || c == ')' || c == '"') {
                break;
            }
            pos++;
        }
        return s.substring(start, pos);
    }

    private static String clip(String t) {
        return t.length() > 40 ? t.substring(0, 40) + "..." : t;
    }

    private void skipSpace() {
        while (pos < s.length() && s.charAt(pos) <= ' ') {
            pos++;
        }
    }

    private char peek() throws SlParseException {
        if (pos >= s.length()) {
            throw error("unexpected end of text");
        }
        return s.charAt(pos);
    }

    private void expect(char c) throws SlParseException {
        if (peek() != c) {
            throw error("expected '" + c + "'");
        }
        pos++;
    }

    private SlParseException error(String what) {
        return new SlParseException(what, pos);
    }
}
