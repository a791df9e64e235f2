package io.concord.agents.map;

/**
 * A node of the route graph: a place a chair can stand and plan from.
 *
 * @param id   the node's number (the dissertation's scenario uses 3, 9 and 19)
 * @param at   where it is
 * @param name what it is, or null ("patient room 3")
 * @param area the id of the area it lies in, or null if none
 */
public record Node(int id, Point at, String name, String area) {
}
