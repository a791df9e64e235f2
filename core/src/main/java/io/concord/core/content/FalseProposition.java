package io.concord.core.content;

/** The basic ontology's {@code (false)}. */
public record FalseProposition() implements Predicate {
}
