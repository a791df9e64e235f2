package io.concord.layers.observe;

/** Writes the few JSON strings the observation service sends (no parser: the console reads them). */
final class Json {
    private Json() {
    }

    /** Appends a JSON string literal ({@code null} as null). */
    public static StringBuilder string(StringBuilder b, String s) {
        if (s == null) {
            return b.append("null");
        }
        b.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> {
                    if (c < 0x20 || c == 0x2028 || c == 0x2029) {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        return b.append('"');
    }

    /** Appends {@code "name":"value"}. */
    public static StringBuilder field(StringBuilder b, String name, String value) {
        string(b, name).append(':');
        return string(b, value);
    }

    /** A JSON string literal. */
    public static String quote(String s) {
        return string(new StringBuilder(), s).toString();
    }
}
