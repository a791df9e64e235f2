package io.concord.core.layer;

import java.util.List;
import java.util.function.Supplier;

/**
 * Supplies the default stack of agents whose runtime names none, found with
 * {@link java.util.ServiceLoader}: the {@code concord-layers} module provides the EN 50159 class-7
 * stack, so that every agent carries the safety layers without configuration.
 */
public interface StackProvider {

    /** The factory of default stacks (one new stack per agent), top first. */
    Supplier<List<Layer>> defaultStack();
}
