package io.concord.core.content;

import java.util.Objects;

/**
 * An SL variable, written {@code ?name}.
 *
 * @param name the variable's name without the question mark
 */
public record AbsVariable(String name) implements AbsObject {
    /** Checks the name is not empty. */
    public AbsVariable {
        Objects.requireNonNull(name, "name");
        if (name.isEmpty()) {
            throw new IllegalArgumentException("empty variable name");
        }
    }
}
