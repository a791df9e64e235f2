package io.concord.core.content;

/**
 * A statement that is true or false, written with positional slots: {@code (Owns (Book :title X) (agent-identifier :name a@P))}, as JADE writes predicates. A class or record that implements it can be added to a {@link BeanOntology}.
 */
public interface Predicate {
}
