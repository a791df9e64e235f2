package io.concord.jadecompat.internal;

import java.nio.charset.StandardCharsets;

/**
 * JADE's agent names as Concord's. JADE takes any local name ({@code "timetable agent"}); a
 * Concord agent's name is a word (no spaces, quotes, parentheses, {@code @}). concord-jade names
 * the Concord agent by the JADE name with those characters (and {@code %}) percent-encoded as
 * UTF-8 ({@code timetable%20agent}), and decodes every name it hands back to JADE code, so JADE
 * code only ever sees its own names; Concord's agents and tools (the console, logs) see the
 * encoded ones.
 */
public final class Names {
    private Names() {
    }

    private static boolean plain(int c) {
        return c > ' ' && c < 0x7f && c != '(' && c != ')' && c != '"' && c != '@' && c != '%';
    }

    /** A JADE local name as a Concord word. */
    public static String encodeLocal(String local) {
        if (local == null || local.chars().allMatch(Names::plain)) {
            return local;
        }
        StringBuilder b = new StringBuilder();
        for (byte x : local.getBytes(StandardCharsets.UTF_8)) {
            int c = x & 0xff;
            if (plain(c)) {
                b.append((char) c);
            } else {
                b.append('%').append(Character.toUpperCase(Character.forDigit(c >> 4, 16)))
                        .append(Character.toUpperCase(Character.forDigit(c & 0xf, 16)));
            }
        }
        return b.toString();
    }

    /** A JADE full name ({@code local@platform}, or a local name) as Concord's: the local part encoded. */
    public static String encodeFull(String name) {
        if (name == null) {
            return null;
        }
        int at = name.lastIndexOf('@');
        return at < 0 ? encodeLocal(name) : encodeLocal(name.substring(0, at)) + name.substring(at);
    }

    /** A Concord name (local or full) as JADE's: percent escapes decoded. */
    public static String decode(String name) {
        if (name == null || name.indexOf('%') < 0) {
            return name;
        }
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        for (int i = 0; i < name.length(); i++) {
            char c = name.charAt(i);
            int hi = i + 2 < name.length() ? Character.digit(name.charAt(i + 1), 16) : -1;
            int lo = i + 2 < name.length() ? Character.digit(name.charAt(i + 2), 16) : -1;
            if (c == '%' && hi >= 0 && lo >= 0) {
                out.write(hi * 16 + lo);
                i += 2;
            } else {
                byte[] bytes = String.valueOf(c).getBytes(StandardCharsets.UTF_8);
                out.write(bytes, 0, bytes.length);
            }
        }
        return out.toString(StandardCharsets.UTF_8);
    }
}
