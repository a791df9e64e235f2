package io.concord.agents.map;

/**
 * An edge of the route graph, drivable both ways on a straight line between two nodes.
 *
 * @param a     one node's id
 * @param b     the other's
 * @param door  the id of the door the edge passes through, or null
 * @param lanes 1, or 2 for a corridor wide enough for two chairs to pass each other: each keeps
 *              {@link HospitalMap#LANE_OFFSET_M} to the right of the line (docs/hospital-map.md)
 */
public record Edge(int a, int b, String door, int lanes) {

    /** A one-lane edge. */
    public Edge(int a, int b, String door) {
        this(a, b, door, 1);
    }

    /** Whether two chairs may pass each other on it, one in each lane. */
    public boolean twoLanes() {
        return lanes == 2;
    }

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
        return a + "-" + b + (door == null ? "" : " (door " + door + ")") + (lanes == 2 ? " (two lanes)" : "");
    }
}
