package io.concord.agents.plan;

import java.util.List;

/**
 * A route on the map's graph: the nodes in order, the doors passed (in order), and its length.
 *
 * @param nodes   node ids, start first
 * @param doors   door ids in the order they are passed
 * @param lengthM metres along the edges
 */
public record Route(List<Integer> nodes, List<String> doors, double lengthM) {

    /** Copies the lists. */
    public Route {
        nodes = List.copyOf(nodes);
        doors = List.copyOf(doors);
    }

    /** The first node. */
    public int start() {
        return nodes.get(0);
    }

    /** The last node. */
    public int goal() {
        return nodes.get(nodes.size() - 1);
    }
}
