package io.concord.agents.map;


import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.function.ToDoubleFunction;

/**
 * Whether a map that the reader accepts can also be driven: a chair 1.2 m long and 0.7 m wide
 * drives straight along the edges, turns on the spot at the nodes (sweeping a circle of about
 * 0.7 m), finds its way again at the nodes (floor markers), and waits beside a door while it
 * opens. The reader's checks keep nodes and edges out of the walls; these keep the chair clear of
 * them, and of the doors' leaves.
 *
 * <ul>
 *   <li>An edge may be of any length: one longer than {@link HospitalMap#OPEN_LOOP_M} m has floor
 *       markers along it ({@link HospitalMap#edgeMarkers()}), since odometry drifts with the
 *       distance, and a chair 0.5 m off its line at the end of a 10 m edge turned into a wall.</li>
 *   <li>A node is at least {@value #NODE_WALL_M} m from every wall's face (a chair turning there
 *       reaches {@value #TURN_REACH_M} m); an edge at least {@value #EDGE_WALL_M} m (half the
 *       chair's width and 0.1 m).</li>
 *   <li>Two nodes are at least {@value #NODE_SPACING_M} m apart: two chairs turning on them keep
 *       clear of each other.</li>
 *   <li>The two nodes of an edge through a door are at least {@value #DOOR_WAIT_M} m from its
 *       opening ({@value #SLIDING_WAIT_M} m for a sliding door, whose leaf keeps to the wall's line):
 *       a chair waits there while the door opens.</li>
 *   <li>A hinged door: no node within {@value #TURN_REACH_M} m of the quarter circle its leaf sweeps
 *       (radius the door's width, from the hinge jamb, on its swing side); no other edge within
 *       {@value #HALF_WIDTH_M} m of it; its own edge {@value #LEAF_CLEARANCE_M} m from the open
 *       leaf; no wall in the sweep.</li>
 *   <li>A revolving door: no node within half its width plus {@value #TURN_REACH_M} m of its pivot;
 *       no other edge within half its width plus {@value #HALF_WIDTH_M} m; its own edge through one
 *       lane, {@value #LEAF_CLEARANCE_M} m from the open leaf; no wall in its circle.</li>
 *   <li>A sliding door: a wall in line past its {@code hinge} jamb at least as long as the opening,
 *       the pocket its leaf slides into.</li>
 *   <li>Two lanes ({@link HospitalMap#laneAxis}): each lane's point keeps the rules of a node (from
 *       walls, swings and pivots: a chair stopped in its lane may turn there), and each line a
 *       chair in a lane drives (along the corridor, and the turns to and from rooms on its right)
 *       those of an edge.</li>
 * </ul>
 *
 * <p>Each problem is a sentence naming the element, as the reader's are; {@link HospitalMap#warnings()}
 * gives them. The default hospital passes; so does every generated map.
 */
final class Drivability {
    /** The least distance from a node to a wall's face, metres. */
    static final double NODE_WALL_M = 0.8;
    /** The least distance from an edge to a wall's face, metres. */
    static final double EDGE_WALL_M = 0.45;
    /** The least distance between two nodes, metres. */
    static final double NODE_SPACING_M = 1.5;
    /** The least distance from a hinged or revolving door's opening to the nodes of an edge through it, metres. */
    static final double DOOR_WAIT_M = 1.5;
    /**
     * The same for a sliding door, whose leaf keeps to the wall's line: the chair's half length and
     * 0.4 m, so that its nose stays clear of the opening while it waits.
     */
    static final double SLIDING_WAIT_M = 1.0;
    /** How far a chair turning on the spot reaches from its node: half its diagonal, rounded up. */
    static final double TURN_REACH_M = 0.7;
    /** Half a chair's width. */
    static final double HALF_WIDTH_M = 0.35;
    /** The least distance from an edge through a hinged or revolving door to where its open leaf stands. */
    static final double LEAF_CLEARANCE_M = 0.45;
    /** How far off a door's line a wall may be and still be in line with it. */
    private static final double IN_LINE_M = 0.02;

    private Drivability() {
    }

    /** Every problem found, each naming its element; empty if the map can be driven. */
    static List<String> problems(HospitalMap map) {
        List<String> out = new ArrayList<>();
        for (Place n : places(map)) {
            Wall w = nearest(map.walls(), x -> face(n.at(), x));
            if (w != null && face(n.at(), w) < NODE_WALL_M) {
                out.add(n + " is " + m(face(n.at(), w)) + " m from the face of wall '" + w.id()
                        + "'; a chair turning on the spot there reaches " + m(TURN_REACH_M) + " m: keep " + m(NODE_WALL_M) + " m"
                        + n.orOneLane());
            }
        }
        for (Edge e : map.edges()) {
            Point a = map.node(e.a()).at();
            Point b = map.node(e.b()).at();
            Wall w = nearest(map.walls(), x -> segmentToSegment(a, b, x.from(), x.to()) - x.thicknessM() / 2);
            double d = w == null ? Double.MAX_VALUE : segmentToSegment(a, b, w.from(), w.to()) - w.thicknessM() / 2;
            if (d < EDGE_WALL_M) {
                out.add("edge " + e.a() + "-" + e.b() + " passes " + m(d) + " m from the face of wall '" + w.id() + "'; a chair "
                        + m(2 * HALF_WIDTH_M) + " m wide driving it needs " + m(EDGE_WALL_M) + " m");
            }
        }
        for (Edge e : map.edges()) {
            List<Point[]> lines = driven(map, e);
            for (Point[] lane : lines.subList(1, lines.size())) {
                Wall w = nearest(map.walls(), x -> segmentToSegment(lane[0], lane[1], x.from(), x.to()) - x.thicknessM() / 2);
                double d = w == null ? Double.MAX_VALUE : segmentToSegment(lane[0], lane[1], w.from(), w.to()) - w.thicknessM() / 2;
                if (d < EDGE_WALL_M) {
                    out.add("edge " + e.a() + "-" + e.b() + "'s lane from " + lane[0] + " to " + lane[1]
                            + " passes " + m(d) + " m from the face of wall '" + w.id() + "'; a chair in it needs "
                            + m(EDGE_WALL_M) + " m: give the corridor's edges one lane, or the corridor "
                            + m(2 * (HospitalMap.LANE_OFFSET_M + NODE_WALL_M)) + " m of width");
                    break;
                }
            }
        }
        List<Node> nodes = map.nodes();
        for (int i = 0; i < nodes.size(); i++) {
            for (int j = i + 1; j < nodes.size(); j++) {
                double d = nodes.get(i).at().distanceTo(nodes.get(j).at());
                if (d < NODE_SPACING_M) {
                    out.add("nodes " + nodes.get(i).id() + " and " + nodes.get(j).id() + " are " + m(d) + " m apart; two chairs "
                            + "turning on them need " + m(NODE_SPACING_M) + " m");
                }
            }
        }
        for (Edge e : map.edges()) {
            if (e.door() == null) {
                continue;
            }
            Door d = map.door(e.door());
            double wait = d.kind() == Door.Kind.SLIDING ? SLIDING_WAIT_M : DOOR_WAIT_M;
            for (int id : new int[] {e.a(), e.b()}) {
                double dist = pointToSegment(map.node(id).at(), d.from(), d.to());
                if (dist < wait) {
                    out.add("node " + id + " is " + m(dist) + " m from the opening of door '" + d.id() + "' (edge " + e.a() + "-"
                            + e.b() + "); a chair waiting there for the door needs " + m(wait) + " m");
                }
            }
        }
        for (Door d : map.doors()) {
            switch (d.kind()) {
                case HINGED -> hinged(map, d, out);
                case ROTATING -> rotating(map, d, out);
                case SLIDING -> sliding(map, d, out);
                default -> throw new IllegalStateException(d.kind().toString());
            }
        }
        return out;
    }

    private static void hinged(HospitalMap map, Door d, List<String> out) {
        Point h = d.hingePoint();
        Point f = d.freePoint();
        double w = d.width();
        double ux = (f.x() - h.x()) / w;
        double uy = (f.y() - h.y()) / w;
        // The leaf opens a quarter turn counter-clockwise when the swing side is left of its line from the hinge.
        boolean ccw = (d.hinge() == Door.End.FROM) == (d.swing() == Door.Side.LEFT);
        double vx = ccw ? -uy : uy;
        double vy = ccw ? ux : -ux;
        Point open = new Point(h.x() + w * vx, h.y() + w * vy);
        ToDoubleFunction<Point> sweep = p -> {
            double qx = p.x() - h.x();
            double qy = p.y() - h.y();
            if (qx * ux + qy * uy >= 0 && qx * vx + qy * vy >= 0) {
                return Math.max(0, Math.hypot(qx, qy) - w);
            }
            return Math.min(pointToSegment(p, h, f), pointToSegment(p, h, open));
        };
        String what = "the swing of door '" + d.id() + "' (a quarter circle of " + m(w) + " m from its hinge at " + h + ")";
        for (Place n : places(map)) {
            double dist = sweep.applyAsDouble(n.at());
            if (dist < TURN_REACH_M) {
                out.add(n + (dist == 0 ? " is in " : " is " + m(dist) + " m from ") + what
                        + "; a chair there would meet the leaf: keep " + m(TURN_REACH_M) + " m out of it" + n.orOneLane());
            }
        }
        for (Edge e : map.edges()) {
            Point a = map.node(e.a()).at();
            Point b = map.node(e.b()).at();
            if (d.id().equals(e.door())) {
                for (Point[] line : driven(map, e)) {
                    double dist = segmentToSegment(line[0], line[1], h, open);
                    if (dist < LEAF_CLEARANCE_M) {
                        out.add("edge " + e.a() + "-" + e.b() + (line[0] == a && line[1] == b ? "" : "'s lane") + " passes " + m(dist)
                                + " m from the open leaf of door '" + d.id() + "'; keep " + m(LEAF_CLEARANCE_M)
                                + " m (drive through the middle of the opening)");
                        break;
                    }
                }
            } else {
                for (Point[] line : driven(map, e)) {
                    if (pointToSegment(h, line[0], line[1]) < w + HALF_WIDTH_M) {
                        double dist = minOnSegment(line[0], line[1], sweep);
                        if (dist < HALF_WIDTH_M) {
                            out.add("edge " + e.a() + "-" + e.b() + (line[0] == a && line[1] == b ? "" : "'s lane") + " passes " + m(dist) + " m from "
                                    + what + "; a chair driving it needs " + m(HALF_WIDTH_M) + " m");
                            break;
                        }
                    }
                }
            }
        }
        for (Wall x : map.walls()) {
            if (inLine(d, x) || pointToSegment(h, x.from(), x.to()) > w + x.thicknessM()) {
                continue;
            }
            if (minOnSegment(x.from(), x.to(), sweep) < x.thicknessM() / 2) {
                out.add("door '" + d.id() + "': wall '" + x.id() + "' stands in the swing of its leaf");
            }
        }
    }

    /** Where a chair may stand and turn: a node, or a lane's point at a node with lanes. */
    private record Place(String what, Point at, boolean lane) {
        @Override
        public String toString() {
            return what + " at " + at;
        }

        /** What else to do when a lane's point breaks a rule: the corridor may carry one lane there. */
        String orOneLane() {
            return lane ? "; or give the corridor's edges at that node one lane (leave out \"lanes\")" : "";
        }
    }

    /** Every node, then every lane point (a chair stopped in its lane may be told to turn back there). */
    private static List<Place> places(HospitalMap map) {
        List<Place> out = new ArrayList<>();
        for (Node n : map.nodes()) {
            out.add(new Place("node " + n.id(), n.at(), false));
        }
        for (Node n : map.nodes()) {
            if (map.laned(n.id())) {
                for (int lane = 0; lane < 2; lane++) {
                    out.add(new Place("lane " + lane + " of node " + n.id(), map.lanePoint(n.id(), lane), true));
                }
            }
        }
        return out;
    }

    /**
     * The lines chairs drive along an edge: its own first, then those from or to a lane's point at
     * an end with lanes (along the corridor, and turning off it to the right or onto it from the
     * right: {@link HospitalMap#lane}).
     */
    private static List<Point[]> driven(HospitalMap map, Edge e) {
        List<Point[]> out = new ArrayList<>();
        Point a = map.node(e.a()).at();
        Point b = map.node(e.b()).at();
        out.add(new Point[] {a, b});
        for (Point p : points(map, e.a(), e.b())) {
            for (Point q : points(map, e.b(), e.a())) {
                if (p != a || q != b) {
                    out.add(new Point[] {p, q});
                }
            }
        }
        return out;
    }

    /** Where a chair on the edge from {@code n} to {@code other} may pass {@code n}: the node, then the lanes' points it may use. */
    private static List<Point> points(HospitalMap map, int n, int other) {
        List<Point> out = new ArrayList<>(List.of(map.node(n).at()));
        int[] axis = map.laneAxis(n);
        if (axis == null) {
            return out;
        }
        boolean along = other == axis[0] || other == axis[1];
        for (int lane = 0; lane < 2; lane++) {
            int from = lane == 0 ? axis[0] : axis[1];
            int to = lane == 0 ? axis[1] : axis[0];
            if (along || map.lane(from, n, other) == lane || map.lane(other, n, to) == lane) {
                out.add(map.lanePoint(n, lane));
            }
        }
        return out;
    }

    private static void rotating(HospitalMap map, Door d, List<String> out) {
        Point c = d.centre();
        double r = d.width() / 2;
        double nx = -(d.to().y() - d.from().y()) / d.width();
        double ny = (d.to().x() - d.from().x()) / d.width();
        Point leafA = new Point(c.x() + r * nx, c.y() + r * ny);
        Point leafB = new Point(c.x() - r * nx, c.y() - r * ny);
        for (Place n : places(map)) {
            double dist = n.at().distanceTo(c);
            if (dist < r + TURN_REACH_M) {
                out.add(n + " is " + m(dist) + " m from the pivot of revolving door '" + d.id()
                        + "'; its leaf sweeps " + m(r) + " m round it and a chair turning there reaches " + m(TURN_REACH_M)
                        + " m: keep " + m(r + TURN_REACH_M) + " m" + n.orOneLane());
            }
        }
        for (Edge e : map.edges()) {
            Point a = map.node(e.a()).at();
            Point b = map.node(e.b()).at();
            if (d.id().equals(e.door())) {
                double dist = segmentToSegment(a, b, leafA, leafB);
                if (dist < LEAF_CLEARANCE_M) {
                    out.add("edge " + e.a() + "-" + e.b() + " passes " + m(dist) + " m from the open leaf of revolving door '"
                            + d.id() + "'; drive through one lane, about a quarter of the opening from the pivot, "
                            + m(LEAF_CLEARANCE_M) + " m clear of the leaf");
                }
            } else {
                for (Point[] line : driven(map, e)) {
                    double dist = pointToSegment(c, line[0], line[1]);
                    if (dist < r + HALF_WIDTH_M) {
                        out.add("edge " + e.a() + "-" + e.b() + (line[0] == a && line[1] == b ? "" : "'s lane") + " passes " + m(dist)
                                + " m from the pivot of revolving door '" + d.id() + "', through the circle its leaf sweeps; keep "
                                + m(r + HALF_WIDTH_M) + " m");
                        break;
                    }
                }
            }
        }
        for (Wall x : map.walls()) {
            if (!inLine(d, x) && pointToSegment(c, x.from(), x.to()) - x.thicknessM() / 2 < r) {
                out.add("door '" + d.id() + "': wall '" + x.id() + "' stands in the circle its revolving leaf sweeps");
            }
        }
    }

    /** A sliding leaf runs past its hinge jamb into a pocket: walls in line there, as long as the opening. */
    private static void sliding(HospitalMap map, Door d, List<String> out) {
        Point h = d.hingePoint();
        Point f = d.freePoint();
        double w = d.width();
        double gx = (h.x() - f.x()) / w;
        double gy = (h.y() - f.y()) / w;
        List<double[]> spans = new ArrayList<>();
        for (Wall x : map.walls()) {
            if (inLine(d, x)) {
                double s1 = (x.from().x() - h.x()) * gx + (x.from().y() - h.y()) * gy;
                double s2 = (x.to().x() - h.x()) * gx + (x.to().y() - h.y()) * gy;
                spans.add(new double[] {Math.min(s1, s2), Math.max(s1, s2)});
            }
        }
        spans.sort(Comparator.comparingDouble(s -> s[0]));
        double reach = 0;
        for (double[] s : spans) {
            if (s[0] <= reach + IN_LINE_M && s[1] > reach) {
                reach = s[1];
            }
        }
        if (reach < w - IN_LINE_M) {
            out.add("sliding door '" + d.id() + "' runs past its jamb at " + h + " into " + m(reach) + " m of wall; its leaf is "
                    + m(w) + " m long and needs a wall in line that long to slide into");
        }
    }

    // ---- geometry -------------------------------------------------------------------------------

    private static boolean inLine(Door d, Wall x) {
        double len = d.width();
        return Math.abs(cross(d.from(), d.to(), x.from())) / len <= IN_LINE_M
                && Math.abs(cross(d.from(), d.to(), x.to())) / len <= IN_LINE_M;
    }

    private static Wall nearest(List<Wall> walls, ToDoubleFunction<Wall> distance) {
        Wall best = null;
        double min = Double.MAX_VALUE;
        for (Wall w : walls) {
            double d = distance.applyAsDouble(w);
            if (d < min) {
                min = d;
                best = w;
            }
        }
        return best;
    }

    private static double face(Point p, Wall w) {
        return pointToSegment(p, w.from(), w.to()) - w.thicknessM() / 2;
    }

    /** The least of a convex function of the point along a segment (a distance to a convex set is one). */
    private static double minOnSegment(Point a, Point b, ToDoubleFunction<Point> f) {
        double lo = 0;
        double hi = 1;
        for (int i = 0; i < 80; i++) {
            double m1 = lo + (hi - lo) / 3;
            double m2 = hi - (hi - lo) / 3;
            if (f.applyAsDouble(lerp(a, b, m1)) <= f.applyAsDouble(lerp(a, b, m2))) {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        return Math.min(f.applyAsDouble(lerp(a, b, (lo + hi) / 2)), Math.min(f.applyAsDouble(a), f.applyAsDouble(b)));
    }

    private static Point lerp(Point a, Point b, double t) {
        return new Point(a.x() + (b.x() - a.x()) * t, a.y() + (b.y() - a.y()) * t);
    }

    static double pointToSegment(Point p, Point a, Point b) {
        double dx = b.x() - a.x();
        double dy = b.y() - a.y();
        double len2 = dx * dx + dy * dy;
        double t = len2 == 0 ? 0 : ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / len2;
        t = Math.max(0, Math.min(1, t));
        return Math.hypot(a.x() + t * dx - p.x(), a.y() + t * dy - p.y());
    }

    static double segmentToSegment(Point p1, Point p2, Point q1, Point q2) {
        if (crosses(p1, p2, q1, q2)) {
            return 0;
        }
        return Math.min(Math.min(pointToSegment(p1, q1, q2), pointToSegment(p2, q1, q2)),
                Math.min(pointToSegment(q1, p1, p2), pointToSegment(q2, p1, p2)));
    }

    private static boolean crosses(Point p1, Point p2, Point q1, Point q2) {
        double d1 = cross(q1, q2, p1);
        double d2 = cross(q1, q2, p2);
        double d3 = cross(p1, p2, q1);
        double d4 = cross(p1, p2, q2);
        return (d1 > 0 && d2 < 0 || d1 < 0 && d2 > 0) && (d3 > 0 && d4 < 0 || d3 < 0 && d4 > 0);
    }

    private static double cross(Point a, Point b, Point c) {
        return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    }

    private static String m(double v) {
        String s = String.format(Locale.ROOT, "%.2f", v);
        s = s.replaceAll("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }
}
