package io.concord.agents.map;

/** Plane geometry on segments, for the map's checks and the world's zones. */
final class Geometry {
    private Geometry() {
    }

    /** Distance from point p to the segment a-b. */
    public static double pointToSegment(Point p, Point a, Point b) {
        double dx = b.x() - a.x();
        double dy = b.y() - a.y();
        double len2 = dx * dx + dy * dy;
        double t = len2 == 0 ? 0 : ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / len2;
        t = Math.max(0, Math.min(1, t));
        return Math.hypot(a.x() + t * dx - p.x(), a.y() + t * dy - p.y());
    }

    /** True if the segments p1-p2 and q1-q2 cross or touch. */
    public static boolean segmentsIntersect(Point p1, Point p2, Point q1, Point q2) {
        double d1 = cross(q1, q2, p1);
        double d2 = cross(q1, q2, p2);
        double d3 = cross(p1, p2, q1);
        double d4 = cross(p1, p2, q2);
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
            return true;
        }
        return (d1 == 0 && onSegment(q1, q2, p1)) || (d2 == 0 && onSegment(q1, q2, p2))
                || (d3 == 0 && onSegment(p1, p2, q1)) || (d4 == 0 && onSegment(p1, p2, q2));
    }

    /** Distance between the segments p1-p2 and q1-q2 (0 if they cross). */
    public static double segmentToSegment(Point p1, Point p2, Point q1, Point q2) {
        if (segmentsIntersect(p1, p2, q1, q2)) {
            return 0;
        }
        return Math.min(Math.min(pointToSegment(p1, q1, q2), pointToSegment(p2, q1, q2)),
                Math.min(pointToSegment(q1, p1, p2), pointToSegment(q2, p1, p2)));
    }

    /** The z of (b - a) x (c - a): positive if c lies left of a-&gt;b. */
    public static double cross(Point a, Point b, Point c) {
        return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    }

    private static boolean onSegment(Point a, Point b, Point p) {
        return Math.min(a.x(), b.x()) <= p.x() && p.x() <= Math.max(a.x(), b.x())
                && Math.min(a.y(), b.y()) <= p.y() && p.y() <= Math.max(a.y(), b.y());
    }

    /** The point a fraction t of the way from a to b. */
    public static Point lerp(Point a, Point b, double t) {
        return new Point(a.x() + (b.x() - a.x()) * t, a.y() + (b.y() - a.y()) * t);
    }
}
