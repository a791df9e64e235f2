package io.concord.core.content;

/** The basic ontology's {@code (true)}, the answer to a request that needs no other. */
public record TrueProposition() implements Predicate {
}
