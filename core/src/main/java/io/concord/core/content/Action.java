package io.concord.core.content;

import io.concord.core.acl.AID;

import java.util.Objects;

/**
 * The basic ontology's {@code (action actor act)}: an agent doing an action.
 *
 * @param actor  the agent that does it
 * @param action what it does, an {@link AgentAction} (or any concept of the ontology)
 */
public record Action(AID actor, Object action) {
    /** Both parts are required. */
    public Action {
        Objects.requireNonNull(actor, "actor");
        Objects.requireNonNull(action, "action");
    }
}
