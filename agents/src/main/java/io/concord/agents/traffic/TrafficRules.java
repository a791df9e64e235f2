package io.concord.agents.traffic;

/**
 * How the traffic agent keeps chairs apart on the route graph (docs/design.md, "Reservations in
 * order"). Fixed when the agent is made: nothing switches a running traffic agent's rules.
 */
public enum TrafficRules {
    /**
     * The default: a chair is granted its route at once unless a chair that will not drive on
     * stands on it, and joins the queue of each node of it behind the chairs already granted that
     * node; it drives into a node only when it is first in that node's queue (it is told how far it
     * may drive, and told again as the chairs ahead leave). Chairs follow each other down a
     * corridor in the same direction; a chair waits only where another is still ahead of it.
     */
    IN_ORDER,
    /**
     * A chair drives a route only once nobody else holds any node of it (the rules before issue 37:
     * a corridor carries one chair at a time). Kept to compare with in {@code bench/run quick fleet}.
     */
    WHOLE_ROUTES,
    /**
     * For tests only: every route is granted at once whoever holds its nodes; the chairs keep apart
     * by their range sensors alone. Shows what the reservations do.
     */
    NONE
}
