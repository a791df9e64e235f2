package io.concord.core.content;

import java.util.List;
import java.util.Objects;

/**
 * An aggregate: {@code (sequence a b c)} or {@code (set a b c)}.
 *
 * @param type     {@code sequence} or {@code set}
 * @param elements its elements, in order
 */
public record AbsAggregate(String type, List<AbsObject> elements) implements AbsObject {
    /** The name SL gives an ordered aggregate. */
    public static final String SEQUENCE = "sequence";
    /** The name SL gives an unordered aggregate. */
    public static final String SET = "set";

    /** Copies the elements; the type must be {@code sequence} or {@code set}. */
    public AbsAggregate {
        Objects.requireNonNull(type, "type");
        if (!type.equals(SEQUENCE) && !type.equals(SET)) {
            throw new IllegalArgumentException("aggregate type must be sequence or set: " + type);
        }
        elements = List.copyOf(elements);
    }
}
