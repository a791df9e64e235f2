package io.concord.agents.proto;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The text of the wheelchair agents' messages: a verb, then {@code key=value} fields, each
 * separated by "; " ({@code transport; task=T1; from=3; to=9; priority=3; unload=60}). Values
 * hold no ';' and no line breaks; lists are comma-separated. Written for people reading the
 * conversation as much as for the agents. See docs/wheelchair-protocol.md.
 *
 * <p>The low-level reader and writer of {@link WheelchairMessage}, the one codec: agents speak in
 * its records, not in this text.
 */
public final class Content {
    private final String verb;
    private final Map<String, String> fields;

    private Content(String verb, Map<String, String> fields) {
        this.verb = verb;
        this.fields = fields;
    }

    /** A content with a verb and no fields yet. */
    public static Content of(String verb) {
        check(verb, "verb");
        return new Content(verb, new LinkedHashMap<>());
    }

    /** Adds a field (numbers in the ROOT locale). */
    public Content with(String key, Object value) {
        check(key, "key");
        String v = value instanceof Double d ? fmt(d) : String.valueOf(value);
        if (v.indexOf(';') >= 0 || v.indexOf('\n') >= 0 || v.indexOf('\r') >= 0) {
            v = v.replace(';', ',').replace('\n', ' ').replace('\r', ' ');
        }
        fields.put(key, v);
        return this;
    }

    /** Adds a field if its value is not null. */
    public Content maybe(String key, Object value) {
        return value == null ? this : with(key, value);
    }

    private static String fmt(double d) {
        return String.format(Locale.ROOT, "%.2f", d);
    }

    private static void check(String s, String what) {
        if (s == null || s.isEmpty() || s.indexOf(';') >= 0 || s.indexOf('=') >= 0 || s.indexOf(' ') >= 0) {
            throw new IllegalArgumentException("a content " + what + " must be a word, got '" + s + "'");
        }
    }

    /**
     * Reads a content.
     *
     * @throws IllegalArgumentException naming what is wrong
     */
    public static Content parse(String text) {
        if (text == null || text.isBlank()) {
            throw new IllegalArgumentException("empty content");
        }
        String[] parts = text.split(";");
        String verb = parts[0].trim();
        if (verb.isEmpty() || verb.contains("=") || verb.contains(" ")) {
            throw new IllegalArgumentException("content must start with a verb, got '" + parts[0] + "'");
        }
        Map<String, String> f = new LinkedHashMap<>();
        for (int i = 1; i < parts.length; i++) {
            String p = parts[i].trim();
            if (p.isEmpty()) {
                continue;
            }
            int eq = p.indexOf('=');
            if (eq <= 0) {
                throw new IllegalArgumentException("field '" + p + "' is not key=value");
            }
            f.put(p.substring(0, eq).trim(), p.substring(eq + 1).trim());
        }
        return new Content(verb, f);
    }

    /** The verb. */
    public String verb() {
        return verb;
    }

    /** True if the verb is this one. */
    public boolean is(String v) {
        return verb.equals(v);
    }

    /** Every field. */
    public Map<String, String> fields() {
        return Collections.unmodifiableMap(fields);
    }

    /** A field's value, or null. */
    public String get(String key) {
        return fields.get(key);
    }

    /** A required field's value. */
    public String text(String key) {
        String v = fields.get(key);
        if (v == null || v.isEmpty()) {
            throw new IllegalArgumentException("'" + verb + "' needs a field '" + key + "'");
        }
        return v;
    }

    /** A required whole-number field. */
    public int integer(String key) {
        String v = text(key);
        try {
            return Integer.parseInt(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("field '" + key + "' must be a whole number, got '" + v + "'");
        }
    }

    /** A required number field. */
    public double number(String key) {
        String v = text(key);
        try {
            double d = Double.parseDouble(v);
            if (!Double.isFinite(d)) {
                throw new NumberFormatException();
            }
            return d;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("field '" + key + "' must be a number, got '" + v + "'");
        }
    }

    /** A number field with a default. */
    public double number(String key, double dflt) {
        return fields.containsKey(key) ? number(key) : dflt;
    }

    /** A comma-separated list field (empty if absent). */
    public List<String> list(String key) {
        String v = fields.get(key);
        List<String> out = new ArrayList<>();
        if (v != null && !v.isEmpty()) {
            for (String s : v.split(",")) {
                if (!s.isBlank()) {
                    out.add(s.trim());
                }
            }
        }
        return out;
    }

    @Override
    public String toString() {
        StringBuilder b = new StringBuilder(verb);
        for (Map.Entry<String, String> e : fields.entrySet()) {
            b.append("; ").append(e.getKey()).append('=').append(e.getValue());
        }
        return b.toString();
    }
}
