package io.concord.jadecompat.internal;

import java.util.ArrayList;
import java.util.List;

/**
 * Just enough of FIPA SL's surface syntax for the DF's messages: an expression is a word (a
 * {@link String}) or a parenthesised list of expressions (a {@link List}); quoted strings are read
 * with {@code \"} unescaped. Written strictly: a word is quoted unless it is plain.
 */
public final class Sl {
    private Sl() {
    }

    /** Parses one expression (the first, if the text holds several). */
    public static Object parse(String text) {
        int[] at = {0};
        Object e = next(text, at);
        if (e == null) {
            throw new IllegalArgumentException("no SL expression in: " + text);
        }
        return e;
    }

    private static Object next(String s, int[] at) {
        while (at[0] < s.length() && Character.isWhitespace(s.charAt(at[0]))) {
            at[0]++;
        }
        if (at[0] >= s.length()) {
            return null;
        }
        char c = s.charAt(at[0]);
        if (c == '(') {
            at[0]++;
            List<Object> l = new ArrayList<>();
            while (true) {
                while (at[0] < s.length() && Character.isWhitespace(s.charAt(at[0]))) {
                    at[0]++;
                }
                if (at[0] >= s.length()) {
                    throw new IllegalArgumentException("unbalanced parentheses in: " + s);
                }
                if (s.charAt(at[0]) == ')') {
                    at[0]++;
                    return l;
                }
                l.add(next(s, at));
            }
        }
        if (c == ')') {
            throw new IllegalArgumentException("unexpected ) at " + at[0] + " in: " + s);
        }
        StringBuilder b = new StringBuilder();
        if (c == '"') {
            at[0]++;
            while (at[0] < s.length() && s.charAt(at[0]) != '"') {
                if (s.charAt(at[0]) == '\\' && at[0] + 1 < s.length() && s.charAt(at[0] + 1) == '"') {
                    at[0]++;
                }
                b.append(s.charAt(at[0]++));
            }
            at[0]++;
            return b.toString();
        }
        while (at[0] < s.length() && !Character.isWhitespace(s.charAt(at[0])) && "()\"".indexOf(s.charAt(at[0])) < 0) {
            b.append(s.charAt(at[0]++));
        }
        return b.toString();
    }

    /** Writes an expression back (lists in parentheses, words quoted where needed). */
    public static String write(Object e) {
        StringBuilder b = new StringBuilder();
        write(b, e);
        return b.toString();
    }

    private static void write(StringBuilder b, Object e) {
        if (e instanceof List<?> l) {
            b.append('(');
            for (int i = 0; i < l.size(); i++) {
                if (i > 0) {
                    b.append(' ');
                }
                write(b, l.get(i));
            }
            b.append(')');
        } else {
            b.append(word(String.valueOf(e)));
        }
    }

    /** A word as SL wants it: bare if plain ASCII with no delimiters, else quoted with {@code "} escaped. */
    public static String word(String w) {
        boolean plain = !w.isEmpty() && "#0123456789-\"".indexOf(w.charAt(0)) < 0;
        for (int i = 0; plain && i < w.length(); i++) {
            char c = w.charAt(i);
            plain = c > 0x20 && c < 0x7f && "()\"".indexOf(c) < 0;
        }
        if (!plain && isNumber(w)) {
            return w;
        }
        return plain ? w : "\"" + w.replace("\"", "\\\"") + "\"";
    }

    private static boolean isNumber(String w) {
        try {
            Double.parseDouble(w);
            return !w.isEmpty();
        } catch (NumberFormatException e) {
            return false;
        }
    }

    /** The value after {@code :slot} in a list such as {@code (frame :slot value ...)}, or null. */
    public static Object slot(List<?> frame, String slot) {
        for (int i = 1; i + 1 < frame.size(); i++) {
            if (frame.get(i) instanceof String s && s.equalsIgnoreCase(":" + slot)) {
                return frame.get(i + 1);
            }
        }
        return null;
    }

    /** The first list, depth first, whose head is this word, or null. */
    public static List<?> find(Object e, String head) {
        if (e instanceof List<?> l) {
            if (!l.isEmpty() && l.get(0) instanceof String h && h.equalsIgnoreCase(head)) {
                return l;
            }
            for (Object x : l) {
                List<?> f = find(x, head);
                if (f != null) {
                    return f;
                }
            }
        }
        return null;
    }
}
