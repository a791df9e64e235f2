package io.concord.core.content;

/**
 * The basic ontology's {@code (result (action ...) value)}: what the action gave.
 *
 * @param action the action
 * @param value  its result: a concept, a primitive or a {@link java.util.List} (a sequence)
 */
public record Result(Action action, Object value) implements Predicate {
}
