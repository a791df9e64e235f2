package io.concord.core.content;

/**
 * An action an agent can be asked to do, written with named slots inside {@code (action actor (Sell :book ...))}. A class or record that implements it can be added to a {@link BeanOntology}.
 */
public interface AgentAction extends Concept {
}
