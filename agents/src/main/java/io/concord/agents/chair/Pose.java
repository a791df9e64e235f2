package io.concord.agents.chair;

/**
 * A position on the floor and a heading: metres in the map's frame (x east, y north), heading in
 * radians counter-clockwise from east, kept in (-pi, pi].
 *
 * @param x       metres
 * @param y       metres
 * @param heading radians
 */
public record Pose(double x, double y, double heading) {

    /** A pose, with the heading brought into (-pi, pi]. */
    public Pose {
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(heading)) {
            throw new IllegalArgumentException("a pose needs finite numbers, got (" + x + ", " + y + ", " + heading + ")");
        }
        heading = normalize(heading);
    }

    /** The distance in metres to another pose's position. */
    public double distanceTo(Pose other) {
        return Math.hypot(other.x - x, other.y - y);
    }

    /** The distance in metres to a point. */
    public double distanceTo(double px, double py) {
        return Math.hypot(px - x, py - y);
    }

    /** An angle brought into (-pi, pi]. */
    public static double normalize(double angle) {
        double a = Math.IEEEremainder(angle, 2 * Math.PI);
        return a <= -Math.PI ? a + 2 * Math.PI : a;
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "(%.3f, %.3f, %.1f°)", x, y, Math.toDegrees(heading));
    }
}
