package io.concord.sim.maps;

/**
 * What a generated hospital is to contain ({@link MapGenerator#generate(long, Shape)}).
 *
 * @param name       what the shape is called, in the map's name and in messages ("medium")
 * @param nodes      how many route nodes the map has: the generator sizes its wards to this
 *                   count (within {@link MapGenerator#NODE_TOLERANCE} of it)
 * @param wards      how many wards lie along the main corridor, the ring ward among them
 * @param ring       whether one of those wards is a ring: a loop of corridors round a block of
 *                   rooms, so that there are two ways round
 * @param wings      how many dead-end wings (a ward on a corridor that leads nowhere else) branch
 *                   off the main corridor
 * @param bottleneck whether two parts of the hospital are joined only by a narrow corridor
 *                   (2 m wide, one chair's lane)
 * @param parking    how many parking places (corridor and hall nodes where chairs start and
 *                   stand idle) the map names
 * @param depot      whether the lobby (whose nodes are the first parking places) is a depot: its
 *                   grid joins the corridor at one node only, so that the chairs parked there all
 *                   leave through one exit (issue 47)
 * @param oneLane    whether every edge is one lane: chairs never pass each other anywhere, however
 *                   wide the corridor (without it the generator gives every corridor edge two lanes
 *                   where the map checker finds them clear of walls, leaves and pivots)
 */
public record Shape(String name, int nodes, int wards, boolean ring, int wings, boolean bottleneck, int parking, boolean depot,
                    boolean oneLane) {

    /** A shape with two lanes on its corridors where they fit. */
    public Shape(String name, int nodes, int wards, boolean ring, int wings, boolean bottleneck, int parking, boolean depot) {
        this(name, nodes, wards, ring, wings, bottleneck, parking, depot, false);
    }

    /** A shape whose lobby is open to its corridor at every column (no depot). */
    public Shape(String name, int nodes, int wards, boolean ring, int wings, boolean bottleneck, int parking) {
        this(name, nodes, wards, ring, wings, bottleneck, parking, false);
    }

    /** Checks the numbers, naming the wrong one. */
    public Shape {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("a shape needs a name");
        }
        if (nodes < 20 || nodes > 400) {
            throw new IllegalArgumentException("shape " + name + ": nodes must be 20 to 400, got " + nodes);
        }
        if (wards < 1 || wards > 12) {
            throw new IllegalArgumentException("shape " + name + ": wards must be 1 to 12, got " + wards);
        }
        if (wings < 0 || wings > wards + 1) {
            throw new IllegalArgumentException("shape " + name + ": wings must be 0 to wards + 1 (" + (wards + 1) + "), got " + wings);
        }
        if (parking < 1 || parking > nodes / 3) {
            throw new IllegalArgumentException("shape " + name + ": parking must be 1 to a third of the nodes (" + nodes / 3
                    + "), got " + parking);
        }
    }

    /** About 30 nodes: two wards joined by a narrow corridor, a lobby, 10 parking places; no ring, no wing. */
    public static Shape small() {
        return new Shape("small", 30, 2, false, 0, true, 10);
    }

    /** About 60 nodes: a ring ward and a plain ward joined by a narrow corridor, a lobby, a wing, 20 parking places. */
    public static Shape medium() {
        return new Shape("medium", 60, 2, true, 1, true, 20);
    }

    /** About 120 nodes: a ring ward and two plain wards, a narrow corridor, a lobby, two wings, 30 parking places. */
    public static Shape large() {
        return new Shape("large", 120, 3, true, 2, true, 30);
    }

    /** The same shape with or without a ring ward. */
    public Shape withRing(boolean ring) {
        return new Shape(name + (ring ? "+ring" : "-ring"), nodes, wards, ring, wings, bottleneck, parking, depot, oneLane);
    }

    /** The same shape with another node count (and as many parking places, if they still fit). */
    public Shape withNodes(int nodes) {
        return new Shape(name + "@" + nodes, nodes, wards, ring, wings, bottleneck, Math.min(parking, nodes / 3), depot, oneLane);
    }

    /** The same shape with another number of parking places. */
    public Shape withParking(int parking) {
        return new Shape(name, nodes, wards, ring, wings, bottleneck, parking, depot, oneLane);
    }

    /**
     * The same shape with its lobby a depot: the lobby's grid of parking places joins the corridor
     * at one node, the only way in or out for the chairs parked there.
     */
    public Shape withDepot() {
        return new Shape(name + "+depot", nodes, wards, ring, wings, bottleneck, parking, true, oneLane);
    }

    /**
     * The same shape with one lane on every edge: a single-lane hospital, where a chair coming the
     * other way, or a slower one ahead, can only be waited for (issue 47: the corridor that saturates).
     */
    public Shape withOneLane() {
        return new Shape(name + "+one-lane", nodes, wards, ring, wings, bottleneck, parking, depot, true);
    }
}
