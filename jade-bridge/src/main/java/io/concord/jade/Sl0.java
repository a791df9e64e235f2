package io.concord.jade;

import java.util.ArrayList;
import java.util.List;

/**
 * The part of FIPA SL0 that the FIPA-Agent-Management requests of JADE use: S-expressions of words,
 * quoted strings and parenthesised lists, parsed strictly (an unbalanced or cut-off expression is
 * an error), and printed back.
 */
final class Sl0 {
    private Sl0() {
    }

    /** A word or a quoted string. */
    record Atom(String text, boolean quoted) {
        @Override
        public String toString() {
            return quoted ? "\"" + text.replace("\\", "\\\\").replace("\"", "\\\"") + "\"" : text;
        }
    }

    /** A parenthesised list. */
    record Expr(List<Object> items) {
        String head() {
            return items.isEmpty() || !(items.get(0) instanceof Atom a) ? "" : a.text();
        }

        /** The value after {@code :slot}, or null. */
        Object slot(String name) {
            for (int i = 0; i + 1 < items.size(); i++) {
                if (items.get(i) instanceof Atom a && !a.quoted() && a.text().equalsIgnoreCase(":" + name)) {
                    return items.get(i + 1);
                }
            }
            return null;
        }

        String text(String slot) {
            Object v = slot(slot);
            return v instanceof Atom a ? a.text() : null;
        }

        @Override
        public String toString() {
            StringBuilder b = new StringBuilder("(");
            for (int i = 0; i < items.size(); i++) {
                if (i > 0) {
                    b.append(' ');
                }
                b.append(items.get(i));
            }
            return b.append(')').toString();
        }
    }

    /**
     * Parses one expression (leading and trailing whitespace allowed).
     *
     * @throws IllegalArgumentException with the offset of the problem
     */
    static Expr parse(String s) {
        int[] at = {0};
        skip(s, at);
        if (at[0] >= s.length() || s.charAt(at[0]) != '(') {
            throw new IllegalArgumentException("SL0 content must start with '(' (offset " + at[0] + ")");
        }
        Expr e = list(s, at, 0);
        skip(s, at);
        if (at[0] != s.length()) {
            throw new IllegalArgumentException("text after the SL0 expression at offset " + at[0]);
        }
        return e;
    }

    private static void skip(String s, int[] at) {
        while (at[0] < s.length() && Character.isWhitespace(s.charAt(at[0]))) {
            at[0]++;
        }
    }

    private static Expr list(String s, int[] at, int depth) {
        if (depth > 64) {
            throw new IllegalArgumentException("SL0 nested deeper than 64 at offset " + at[0]);
        }
        at[0]++; // (
        List<Object> items = new ArrayList<>();
        while (true) {
            skip(s, at);
            if (at[0] >= s.length()) {
                throw new IllegalArgumentException("SL0 expression cut off: a '(' is never closed");
            }
            char c = s.charAt(at[0]);
            if (c == ')') {
                at[0]++;
                return new Expr(items);
            }
            if (c == '(') {
                items.add(list(s, at, depth + 1));
            } else if (c == '"') {
                StringBuilder b = new StringBuilder();
                at[0]++;
                while (true) {
                    if (at[0] >= s.length()) {
                        throw new IllegalArgumentException("an SL0 string is never closed");
                    }
                    char x = s.charAt(at[0]++);
                    if (x == '\\' && at[0] < s.length()) {
                        b.append(s.charAt(at[0]++));
                    } else if (x == '"') {
                        break;
                    } else {
                        b.append(x);
                    }
                }
                items.add(new Atom(b.toString(), true));
            } else {
                int start = at[0];
                while (at[0] < s.length() && !Character.isWhitespace(s.charAt(at[0])) && s.charAt(at[0]) != '('
                        && s.charAt(at[0]) != ')' && s.charAt(at[0]) != '"') {
                    at[0]++;
                }
                items.add(new Atom(s.substring(start, at[0]), false));
            }
        }
    }

    /** Writes a word bare when it can be, else quoted. */
    static String word(String w) {
        boolean bare = !w.isEmpty() && "#0123456789-".indexOf(w.charAt(0)) < 0;
        for (int i = 0; bare && i < w.length(); i++) {
            char c = w.charAt(i);
            bare = c > ' ' && c < 127 && c != '"' && c != '(' && c != ')';
        }
        return bare ? w : new Atom(w, true).toString();
    }
}
