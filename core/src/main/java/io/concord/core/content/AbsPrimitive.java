package io.concord.core.content;

import java.time.Instant;
import java.util.Arrays;
import java.util.Objects;

/**
 * A primitive value: a {@link String}, a {@link Boolean}, a number ({@link Long}, {@link Integer},
 * {@link Double}, {@link Float}), a date ({@link Instant}, written in FIPA's UTC form with
 * milliseconds) or a byte string ({@code byte[]}).
 *
 * @param value the value, never null
 */
public record AbsPrimitive(Object value) implements AbsObject {

    /** Checks the value is of a supported type. */
    public AbsPrimitive {
        Objects.requireNonNull(value, "value");
        if (!(value instanceof String || value instanceof Boolean || value instanceof Long
                || value instanceof Integer || value instanceof Double || value instanceof Float
                || value instanceof Instant || value instanceof byte[])) {
            throw new IllegalArgumentException("not a primitive: " + value.getClass().getName());
        }
        if (value instanceof byte[] b) {
            value = b.clone();
        }
    }

    /** Wraps a value. */
    public static AbsPrimitive of(Object value) {
        return new AbsPrimitive(value);
    }

    @Override
    public Object value() {
        return value instanceof byte[] b ? b.clone() : value;
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof AbsPrimitive p)) {
            return false;
        }
        if (value instanceof byte[] a && p.value instanceof byte[] b) {
            return Arrays.equals(a, b);
        }
        return value.equals(p.value);
    }

    @Override
    public int hashCode() {
        return value instanceof byte[] b ? Arrays.hashCode(b) : value.hashCode();
    }

    @Override
    public String toString() {
        return value instanceof byte[] b ? "bytes" + Arrays.toString(b) : String.valueOf(value);
    }
}
