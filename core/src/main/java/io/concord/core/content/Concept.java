package io.concord.core.content;

/**
 * A thing in the domain, written with named slots: {@code (Book :title "X")}. A class or record that implements it can be added to a {@link BeanOntology}.
 */
public interface Concept {
}
