package io.concord.core.layer;

/**
 * A control event on the stack's separate path (a peer suspected, a membership change, a key
 * rotated): data messages never travel as events, events never as messages.
 *
 * @param type    what happened, e.g. {@code "suspect"}
 * @param payload details, or {@code null}
 * @param up      true if travelling towards the agent, false towards the network
 */
public record StackEvent(String type, Object payload, boolean up) {
}
