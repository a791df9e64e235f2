package io.concord.core.content;

/**
 * The basic ontology's {@code (= left right)}.
 *
 * @param left  one term
 * @param right the other
 */
public record Equals(Object left, Object right) implements Predicate {
}
