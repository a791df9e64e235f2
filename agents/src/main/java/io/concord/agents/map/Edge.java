package io.concord.agents.map;

/**
 * An edge of the route graph, drivable both ways on a straight line between two nodes.
 *
 * @param a    one node's id
 * @param b    the other's
 * @param door the id of the door the edge passes through, or null
 */
public record Edge(int a, int b, String door) {

    /** The length in metres, in a map. */
    public double length(HospitalMap map) {
        return map.node(a).at().distanceTo(map.node(b).at());
    }

    /** The node at the other end from {@code id}. */
    public int other(int id) {
        return id == a ? b : a;
    }

    @Override
    public String toString() {
        return a + "-" + b + (door == null ? "" : " (door " + door + ")");
    }
}
