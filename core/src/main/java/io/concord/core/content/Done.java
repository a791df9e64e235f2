package io.concord.core.content;

/**
 * The basic ontology's {@code (done (action ...))}: the action has been done.
 *
 * @param action the action
 */
public record Done(Action action) implements Predicate {
}
