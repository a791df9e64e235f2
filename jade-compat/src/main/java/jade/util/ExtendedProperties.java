package jade.util;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Enumeration;
import java.util.List;

/**
 * JADE's properties with typed getters, {@code key=value} or {@code key:value} arguments and
 * {@code ${key}} substitutions in values.
 */
public class ExtendedProperties extends jade.util.leap.Properties {
    private static final long serialVersionUID = 1L;
    public static final String IMPORT_KEY = "import";

    public ExtendedProperties() {
        super();
    }

    /** Properties from {@code key=value} (or {@code key:value}) strings. */
    public ExtendedProperties(String[] args) {
        this();
        addProperties(args);
    }

    /** Adds each {@code key=value} (or {@code key:value}) string; a bare key gets {@code true}. */
    public synchronized void addProperties(String[] args) {
        for (String a : args) {
            addProperty(a);
        }
    }

    protected void addProperty(String property) {
        int i = getSeparatorIndex(property);
        if (i < 0) {
            put(property.trim(), "true");
        } else {
            put(property.substring(0, i).trim(), property.substring(i + 1).trim());
        }
    }

    /** Where the first {@code =} or {@code :} is, or -1. */
    protected int getSeparatorIndex(String property) {
        int eq = property.indexOf('=');
        int colon = property.indexOf(':');
        if (eq < 0) {
            return colon;
        }
        return colon < 0 ? eq : Math.min(eq, colon);
    }

    /** The keys, sorted. */
    public synchronized Enumeration sortedKeys() {
        List<String> keys = new ArrayList<>();
        for (Object k : keySet()) {
            keys.add(String.valueOf(k));
        }
        Collections.sort(keys);
        return Collections.enumeration(keys);
    }

    /** Copies every property of another set into this one. */
    public synchronized void copyProperties(ExtendedProperties source) {
        putAll(source);
    }

    /** The properties whose key starts with {@code prefix}, the prefix taken off. */
    public synchronized ExtendedProperties extractSubset(String prefix) {
        ExtendedProperties sub = new ExtendedProperties();
        for (Object k : keySet()) {
            String key = String.valueOf(k);
            if (key.startsWith(prefix)) {
                sub.put(key.substring(prefix.length()), get(k));
            }
        }
        return sub;
    }

    /** The value with its {@code ${key}} references replaced. */
    @Override
    public String getProperty(String key) {
        String v = getRawProperty(key);
        return v == null ? null : doSubstitutions(v);
    }

    @Override
    public String getProperty(String key, String defaultValue) {
        String v = getProperty(key);
        return v == null ? defaultValue : v;
    }

    /** Sets the property unless it is set; returns its value before. */
    public Object setPropertyIfNot(String key, String value) {
        Object old = get(key);
        if (old == null) {
            put(key, value);
        }
        return old;
    }

    /** The value as stored, without substitutions. */
    public String getRawProperty(String key) {
        Object v = get(key);
        return v == null ? null : String.valueOf(v);
    }

    /** The value of the first key equal to {@code key} ignoring case. */
    public String getPropertyIgnoreCase(String key) {
        for (Object k : keySet()) {
            if (String.valueOf(k).equalsIgnoreCase(key)) {
                return getProperty(String.valueOf(k));
            }
        }
        return null;
    }

    public int getIntProperty(String key, int defaultValue) {
        String v = getProperty(key);
        if (v == null) {
            return defaultValue;
        }
        try {
            return Integer.parseInt(v.trim());
        } catch (NumberFormatException e) {
            return defaultValue;
        }
    }

    /** Sets an int property; returns the value before (or the new one if there was none). */
    public int setIntProperty(String key, int value) {
        int old = getIntProperty(key, value);
        put(key, Integer.toString(value));
        return old;
    }

    /** {@code true}, {@code yes}, {@code on}, {@code 1} (any case) are true. */
    public boolean getBooleanProperty(String key, boolean defaultValue) {
        String v = getProperty(key);
        if (v == null) {
            return defaultValue;
        }
        String t = v.trim().toLowerCase(java.util.Locale.ROOT);
        return t.equals("true") || t.equals("yes") || t.equals("on") || t.equals("1");
    }

    public void setBooleanProperty(String key, boolean value) {
        put(key, value ? "true" : "false");
    }

    /** Gives a property a new key; returns its value. */
    public Object renameKey(String oldKey, String newKey) {
        Object v = remove(oldKey);
        if (v != null) {
            put(newKey, v);
        }
        return v;
    }

    /** Replaces each {@code ${key}} by that property's value (an unknown key by nothing). */
    public String doSubstitutions(String value) {
        return doSubstitutions(value, false);
    }

    /** As {@link #doSubstitutions(String)}; with {@code allowUndefined} an unknown {@code ${key}} stays as it is. */
    public String doSubstitutions(String value, boolean allowUndefined) {
        StringBuilder b = new StringBuilder();
        int i = 0;
        while (i < value.length()) {
            int start = value.indexOf("${", i);
            int end = start < 0 ? -1 : value.indexOf('}', start);
            if (start < 0 || end < 0) {
                b.append(value, i, value.length());
                break;
            }
            b.append(value, i, start);
            String key = value.substring(start + 2, end);
            String v = getProperty(key);
            if (v == null && allowUndefined) {
                b.append(value, start, end + 1);
            } else if (v != null) {
                b.append(v);
            }
            i = end + 1;
        }
        return b.toString();
    }

    /** Prints each {@code key=value}, sorted by key. */
    @Override
    public void list(PrintStream out) {
        for (Enumeration e = sortedKeys(); e.hasMoreElements(); ) {
            String k = (String) e.nextElement();
            out.println(k + "=" + getRawProperty(k));
        }
    }

    /** Each property as {@code key=value}, sorted by key. */
    public String[] toStringArray() {
        List<String> l = new ArrayList<>();
        for (Enumeration e = sortedKeys(); e.hasMoreElements(); ) {
            String k = (String) e.nextElement();
            l.add(k + "=" + getRawProperty(k));
        }
        return l.toArray(new String[0]);
    }
}
