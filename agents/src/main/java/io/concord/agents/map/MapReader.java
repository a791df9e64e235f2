package io.concord.agents.map;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * Reads the JSON map format and checks it whole: every problem is collected with the element it
 * concerns, and the map is refused if there is any. Structure first (fields, types, ids), then
 * consistency (geometry and graph) on what parsed.
 */
final class MapReader {
    static final String FORMAT = "concord-hospital-map/1";
    /** Two nodes closer than this are one place written twice. */
    static final double MIN_NODE_SPACING_M = 0.25;
    /**
     * An edge passes at least this far from every node but its ends: a chair standing at a node
     * (0.7 m wide) and one driving by (0.7 m wide) keep clear of each other only past it.
     */
    static final double EDGE_NODE_CLEARANCE_M = 0.7;
    /** How far a jamb may be from the end of its wall, and how far off the door's line. */
    static final double JAMB_TOLERANCE_M = 0.02;
    private static final int MAX_PROBLEMS = 50;
    private static final ObjectMapper JSON = new ObjectMapper();

    private final String source;
    private final List<String> problems = new ArrayList<>();

    MapReader(String source) {
        this.source = source;
    }

    HospitalMap read(String text) {
        JsonNode root;
        try {
            root = JSON.readTree(text);
        } catch (JsonProcessingException e) {
            var loc = e.getLocation();
            throw new MapException(source, List.of("not valid JSON" + (loc == null ? "" : " at line " + loc.getLineNr()
                    + ", column " + loc.getColumnNr()) + ": " + e.getOriginalMessage()));
        }
        if (root == null || !root.isObject()) {
            throw new MapException(source, List.of("the map must be one JSON object {\"format\": \"" + FORMAT + "\", ...}"));
        }
        known(root, "the map", "format", "name", "clearance", "wallThickness", "walls", "areas", "doors", "nodes", "edges", "parking");
        String format = text(root, "format", "the map", true);
        if (format != null && !format.equals(FORMAT)) {
            problem("the map: format is '" + format + "', this reader knows '" + FORMAT + "'");
        }
        String name = text(root, "name", "the map", true);
        double clearance = number(root, "clearance", "the map", 0.4);
        if (!(clearance >= 0)) {
            problem("the map: clearance must be 0 or more metres, got " + clearance);
        }
        double defaultThickness = number(root, "wallThickness", "the map", 0.15);
        if (!(defaultThickness > 0)) {
            problem("the map: wallThickness must be positive, got " + defaultThickness);
        }
        List<Wall> walls = walls(root.get("walls"), defaultThickness);
        List<Area> areas = areas(root.get("areas"));
        List<Door> doors = doors(root.get("doors"));
        List<Node> nodes = nodes(root.get("nodes"), areas);
        List<Edge> edges = edges(root.get("edges"));
        List<Integer> parking = parking(root.get("parking"));
        if (problems.isEmpty()) {
            check(walls, doors, nodes, edges, areas, clearance);
            checkParking(parking, nodes, areas);
        }
        if (!problems.isEmpty()) {
            throw new MapException(source, problems);
        }
        return new HospitalMap(name, clearance, walls, areas, doors, nodes, edges, parking);
    }

    // ---- structure ------------------------------------------------------------------------------

    private List<Wall> walls(JsonNode arr, double defaultThickness) {
        List<Wall> out = new ArrayList<>();
        Set<String> ids = new HashSet<>();
        int i = 0;
        for (JsonNode w : array(arr, "walls")) {
            i++;
            String what = "wall #" + i;
            if (!w.isObject()) {
                problem(what + ": must be an object {\"id\", \"from\", \"to\"} or {\"id\", \"path\"}");
                continue;
            }
            String id = w.hasNonNull("id") && w.get("id").isTextual() ? w.get("id").asText() : "#" + i;
            what = "wall '" + id + "'";
            known(w, what, "id", "from", "to", "path", "thickness");
            if (w.has("id") && !ids.add(id)) {
                problem(what + ": the id is used by another wall");
            }
            double t = number(w, "thickness", what, defaultThickness);
            if (!(t > 0)) {
                problem(what + ": thickness must be positive, got " + t);
                continue;
            }
            if (w.has("path")) {
                if (w.has("from") || w.has("to")) {
                    problem(what + ": give either \"path\" or \"from\" and \"to\", not both");
                    continue;
                }
                List<Point> pts = points(w.get("path"), what + " path");
                if (pts == null) {
                    continue;
                }
                if (pts.size() < 2) {
                    problem(what + ": a path needs at least two points");
                    continue;
                }
                for (int k = 1; k < pts.size(); k++) {
                    out.add(new Wall(id + "." + k, pts.get(k - 1), pts.get(k), t));
                }
            } else {
                Point from = point(w.get("from"), what + " from");
                Point to = point(w.get("to"), what + " to");
                if (from != null && to != null) {
                    out.add(new Wall(id, from, to, t));
                }
            }
        }
        return out;
    }

    private List<Area> areas(JsonNode arr) {
        List<Area> out = new ArrayList<>();
        Set<String> ids = new HashSet<>();
        int i = 0;
        for (JsonNode a : array(arr, "areas")) {
            i++;
            String what = "area #" + i;
            if (!a.isObject()) {
                problem(what + ": must be an object {\"id\", \"kind\", \"name\", \"polygon\"}");
                continue;
            }
            String id = text(a, "id", what, true);
            if (id == null) {
                continue;
            }
            what = "area '" + id + "'";
            known(a, what, "id", "kind", "name", "ward", "polygon");
            if (!ids.add(id)) {
                problem(what + ": the id is used by another area");
            }
            Area.Kind kind = enumOf(Area.Kind.class, text(a, "kind", what, true), what, "kind");
            String name = text(a, "name", what, false);
            String ward = text(a, "ward", what, false);
            List<Point> poly = points(a.get("polygon"), what + " polygon");
            if (poly != null && poly.size() < 3) {
                problem(what + ": a polygon needs at least three corners, got " + poly.size());
                continue;
            }
            if (kind != null && poly != null) {
                out.add(new Area(id, kind, name == null ? id : name, ward, poly));
            }
        }
        return out;
    }

    private List<Door> doors(JsonNode arr) {
        List<Door> out = new ArrayList<>();
        Set<String> ids = new HashSet<>();
        int i = 0;
        for (JsonNode d : array(arr, "doors")) {
            i++;
            String what = "door #" + i;
            if (!d.isObject()) {
                problem(what + ": must be an object {\"id\", \"kind\", \"from\", \"to\", ...}");
                continue;
            }
            String id = text(d, "id", what, true);
            if (id == null) {
                continue;
            }
            what = "door '" + id + "'";
            known(d, what, "id", "kind", "from", "to", "hinge", "swing");
            if (!ids.add(id)) {
                problem(what + ": the id is used by another door");
            }
            Door.Kind kind = enumOf(Door.Kind.class, text(d, "kind", what, true), what, "kind");
            Point from = point(d.get("from"), what + " from");
            Point to = point(d.get("to"), what + " to");
            Door.End hinge = Door.End.FROM;
            Door.Side swing = Door.Side.LEFT;
            if (kind == Door.Kind.HINGED || kind == Door.Kind.SLIDING) {
                hinge = enumOf(Door.End.class, text(d, "hinge", what, true), what, "hinge");
            }
            if (kind == Door.Kind.HINGED) {
                swing = enumOf(Door.Side.class, text(d, "swing", what, true), what, "swing");
            } else if (d.has("swing")) {
                problem(what + ": only a hinged door swings; remove \"swing\"");
            }
            if (kind == Door.Kind.ROTATING && d.has("hinge")) {
                problem(what + ": a rotating door turns on its centre; remove \"hinge\"");
            }
            if (kind != null && from != null && to != null && hinge != null && swing != null) {
                if (from.distanceTo(to) < 0.5) {
                    problem(what + ": the opening from " + from + " to " + to + " is " + Point.trim(from.distanceTo(to))
                            + " m wide; a door needs at least 0.5 m");
                    continue;
                }
                out.add(new Door(id, kind, from, to, hinge, swing));
            }
        }
        return out;
    }

    private List<Node> nodes(JsonNode arr, List<Area> areas) {
        List<Node> out = new ArrayList<>();
        Set<Integer> ids = new HashSet<>();
        int i = 0;
        for (JsonNode n : array(arr, "nodes")) {
            i++;
            String what = "node #" + i;
            if (!n.isObject()) {
                problem(what + ": must be an object {\"id\", \"at\"}");
                continue;
            }
            JsonNode idn = n.get("id");
            if (idn == null || !idn.canConvertToInt() || !idn.isIntegralNumber()) {
                problem(what + ": \"id\" must be a whole number");
                continue;
            }
            int id = idn.asInt();
            what = "node " + id;
            known(n, what, "id", "at", "name");
            if (!ids.add(id)) {
                problem(what + ": the id is used by another node");
                continue;
            }
            Point at = point(n.get("at"), what + " at");
            String name = text(n, "name", what, false);
            if (at != null) {
                String area = null;
                for (Area a : areas) {
                    if (a.contains(at) && (area == null || a.kind() != Area.Kind.WARD)) {
                        area = a.id();
                    }
                }
                out.add(new Node(id, at, name, area));
            }
        }
        return out;
    }

    private List<Edge> edges(JsonNode arr) {
        List<Edge> out = new ArrayList<>();
        int i = 0;
        for (JsonNode e : array(arr, "edges")) {
            i++;
            String what = "edge #" + i;
            if (!e.isObject()) {
                problem(what + ": must be an object {\"from\", \"to\", \"door\"?, \"lanes\"?}");
                continue;
            }
            known(e, what, "from", "to", "door", "lanes");
            JsonNode a = e.get("from");
            JsonNode b = e.get("to");
            if (a == null || !a.isIntegralNumber() || b == null || !b.isIntegralNumber()) {
                problem(what + ": \"from\" and \"to\" must be node ids (whole numbers)");
                continue;
            }
            String door = text(e, "door", what, false);
            JsonNode l = e.get("lanes");
            int lanes = 1;
            if (l != null) {
                if (!l.isIntegralNumber() || (l.asInt() != 1 && l.asInt() != 2)) {
                    problem(what + " (" + a.asInt() + "-" + b.asInt() + "): \"lanes\" must be 1 or 2 (2: a corridor two chairs can pass each other in)");
                    continue;
                }
                lanes = l.asInt();
            }
            if (lanes == 2 && door != null) {
                problem(what + " (" + a.asInt() + "-" + b.asInt() + "): a door's opening passes one chair at a time; give an edge through door '" + door
                        + "' one lane (leave out \"lanes\")");
                continue;
            }
            out.add(new Edge(a.asInt(), b.asInt(), door, lanes));
        }
        return out;
    }

    private List<Integer> parking(JsonNode arr) {
        List<Integer> out = new ArrayList<>();
        int i = 0;
        for (JsonNode n : array(arr, "parking")) {
            i++;
            if (!n.isIntegralNumber() || !n.canConvertToInt()) {
                problem("parking #" + i + ": must be a node id (a whole number), got " + n);
                continue;
            }
            out.add(n.asInt());
        }
        return out;
    }

    // ---- consistency ----------------------------------------------------------------------------

    /** Parking places are known nodes, each named once, none in a room (a patient's room is no place to wait). */
    private void checkParking(List<Integer> parking, List<Node> nodes, List<Area> areas) {
        Map<Integer, Node> byId = new HashMap<>();
        for (Node n : nodes) {
            byId.put(n.id(), n);
        }
        Map<String, Area> areaById = new HashMap<>();
        for (Area a : areas) {
            areaById.put(a.id(), a);
        }
        Set<Integer> seen = new HashSet<>();
        for (int id : parking) {
            Node n = byId.get(id);
            if (n == null) {
                problem("parking: no node " + id + " in the map");
            } else if (!seen.add(id)) {
                problem("parking: node " + id + " is named twice");
            } else if (n.area() != null && areaById.get(n.area()).kind() == Area.Kind.ROOM) {
                problem("parking: node " + id + " is in room '" + n.area() + "'; chairs park and wait in corridors or halls,"
                        + " never in a patient's room");
            }
        }
    }

    private void check(List<Wall> walls, List<Door> doors, List<Node> nodes, List<Edge> edges, List<Area> areas,
                       double clearance) {
        Map<String, Area> areaById = new HashMap<>();
        for (Area a : areas) {
            areaById.put(a.id(), a);
        }
        for (Area a : areas) {
            if (a.ward() != null) {
                Area w = areaById.get(a.ward());
                if (w == null || w.kind() != Area.Kind.WARD) {
                    problem("area '" + a.id() + "': ward '" + a.ward() + "' is not a ward of this map");
                }
            }
        }
        for (Wall w : walls) {
            if (w.length() < 1e-6) {
                problem("wall '" + w.id() + "' has zero length: it starts and ends at " + w.from());
            }
        }
        Map<String, Door> doorById = new HashMap<>();
        for (Door d : doors) {
            doorById.put(d.id(), d);
            checkGap(d, walls);
        }
        Map<Integer, Node> nodeById = new HashMap<>();
        for (Node n : nodes) {
            nodeById.put(n.id(), n);
            for (Wall w : walls) {
                double centre = Geometry.pointToSegment(n.at(), w.from(), w.to());
                double face = centre - w.thicknessM() / 2;
                if (face < 0) {
                    problem("node " + n.id() + " at " + n.at() + " is inside wall '" + w.id() + "' (" + w.from() + " to "
                            + w.to() + ")");
                } else if (face < clearance) {
                    problem("node " + n.id() + " at " + n.at() + " is " + Point.trim(face) + " m from the face of wall '"
                            + w.id() + "'; a node keeps at least the map's clearance of " + Point.trim(clearance) + " m");
                }
            }
        }
        for (int i = 0; i < nodes.size(); i++) {
            for (int j = i + 1; j < nodes.size(); j++) {
                double d = nodes.get(i).at().distanceTo(nodes.get(j).at());
                if (d < MIN_NODE_SPACING_M) {
                    problem("nodes " + nodes.get(i).id() + " and " + nodes.get(j).id() + " overlap: " + Point.trim(d)
                            + " m apart at " + nodes.get(i).at() + "; nodes must be at least " + MIN_NODE_SPACING_M + " m apart");
                }
            }
        }
        Set<Long> seen = new HashSet<>();
        for (Edge e : edges) {
            String what = "edge " + e.a() + "-" + e.b();
            Node a = nodeById.get(e.a());
            Node b = nodeById.get(e.b());
            if (a == null || b == null) {
                problem(what + ": no node " + (a == null ? e.a() : e.b()) + " in the map");
                continue;
            }
            if (e.a() == e.b()) {
                problem(what + ": an edge must join two different nodes");
                continue;
            }
            long key = ((long) Math.min(e.a(), e.b()) << 32) | (Math.max(e.a(), e.b()) & 0xffffffffL);
            if (!seen.add(key)) {
                problem(what + ": the two nodes are joined twice (edges are both ways already)");
            }
            Door named = null;
            if (e.door() != null) {
                named = doorById.get(e.door());
                if (named == null) {
                    problem(what + ": no door '" + e.door() + "' in the map");
                } else if (!Geometry.segmentsIntersect(a.at(), b.at(), named.from(), named.to())) {
                    problem(what + ": names door '" + named.id() + "' but does not pass through its opening " + named.from()
                            + " to " + named.to());
                }
            }
            for (Door d : doors) {
                if (d != named && Geometry.segmentsIntersect(a.at(), b.at(), d.from(), d.to())) {
                    problem(what + ": passes through door '" + d.id() + "' without naming it; add \"door\": \"" + d.id() + "\"");
                }
            }
            for (Wall w : walls) {
                if (Geometry.segmentToSegment(a.at(), b.at(), w.from(), w.to()) < w.thicknessM() / 2) {
                    problem(what + ": runs through wall '" + w.id() + "' (" + w.from() + " to " + w.to() + ")");
                }
            }
            for (Node n : nodes) {
                double off = n == a || n == b ? Double.MAX_VALUE : Geometry.pointToSegment(n.at(), a.at(), b.at());
                if (off < EDGE_NODE_CLEARANCE_M) {
                    // A chair standing at the node stands in the way of every chair on the edge, and
                    // the traffic agent, which reserves nodes, does not know: the fleet froze there.
                    problem(what + ": passes " + Point.trim(off) + " m from node " + n.id() + " at " + n.at()
                            + ", which is not one of its ends; a chair standing at node " + n.id() + " would block it."
                            + " Join the edge through the node (" + e.a() + "-" + n.id() + " and " + n.id() + "-" + e.b()
                            + ") or keep it " + EDGE_NODE_CLEARANCE_M + " m from the node");
                }
            }
        }
        checkConnected(nodes, edges, nodeById);
    }

    /**
     * Every node can be reached from every other along the edges: the planner routes only on the
     * graph, so a node off it is a room no chair can ever be sent to (or a chair parked there can
     * never leave), found only when a transport fails.
     */
    private void checkConnected(List<Node> nodes, List<Edge> edges, Map<Integer, Node> nodeById) {
        if (nodes.size() < 2) {
            return;
        }
        Map<Integer, List<Integer>> next = new HashMap<>();
        for (Edge e : edges) {
            if (nodeById.containsKey(e.a()) && nodeById.containsKey(e.b())) {
                next.computeIfAbsent(e.a(), k -> new ArrayList<>()).add(e.b());
                next.computeIfAbsent(e.b(), k -> new ArrayList<>()).add(e.a());
            }
        }
        int first = nodes.get(0).id();
        Set<Integer> reached = new HashSet<>(List.of(first));
        ArrayDeque<Integer> todo = new ArrayDeque<>(List.of(first));
        while (!todo.isEmpty()) {
            for (int n : next.getOrDefault(todo.poll(), List.of())) {
                if (reached.add(n)) {
                    todo.add(n);
                }
            }
        }
        List<Integer> off = new ArrayList<>();
        for (Node n : nodes) {
            if (!reached.contains(n.id())) {
                off.add(n.id());
            }
        }
        if (!off.isEmpty()) {
            problem((off.size() == 1 ? "node " + off.get(0) + " is" : "nodes " + off + " are")
                    + " not connected to node " + first + " by any path of edges: no chair could be routed there;"
                    + " add an edge (with its door, if it passes one) or remove the node");
        }
    }

    /** A door's jambs must each be the end of a wall in line with the opening, and nothing may cross it. */
    private void checkGap(Door d, List<Wall> walls) {
        for (Point jamb : List.of(d.from(), d.to())) {
            Point other = jamb == d.from() ? d.to() : d.from();
            boolean found = false;
            for (Wall w : walls) {
                Point end = null;
                Point far = null;
                if (w.from().distanceTo(jamb) <= JAMB_TOLERANCE_M) {
                    end = w.from();
                    far = w.to();
                } else if (w.to().distanceTo(jamb) <= JAMB_TOLERANCE_M) {
                    end = w.to();
                    far = w.from();
                }
                if (end == null) {
                    continue;
                }
                double len = w.length();
                boolean inLine = len > 0 && Math.abs(Geometry.cross(jamb, other, far)) / jamb.distanceTo(other) <= JAMB_TOLERANCE_M;
                boolean away = (far.x() - jamb.x()) * (other.x() - jamb.x()) + (far.y() - jamb.y()) * (other.y() - jamb.y()) < 0;
                if (inLine && away) {
                    found = true;
                    break;
                }
            }
            if (!found) {
                problem("door '" + d.id() + "' is not on a wall gap: no wall ends at its jamb " + jamb
                        + " in line with the opening " + d.from() + " to " + d.to());
            }
        }
        double width = d.width();
        for (Wall w : walls) {
            double margin = w.thicknessM() / 2 + 0.01;
            if (width <= 2 * margin) {
                continue;
            }
            Point a = Geometry.lerp(d.from(), d.to(), margin / width);
            Point b = Geometry.lerp(d.from(), d.to(), 1 - margin / width);
            if (Geometry.segmentToSegment(a, b, w.from(), w.to()) < w.thicknessM() / 2) {
                problem("door '" + d.id() + "': wall '" + w.id() + "' (" + w.from() + " to " + w.to()
                        + ") blocks its opening; a door must sit in a gap");
            }
        }
    }

    // ---- field helpers --------------------------------------------------------------------------

    private void problem(String p) {
        if (problems.size() < MAX_PROBLEMS) {
            problems.add(p);
        } else if (problems.size() == MAX_PROBLEMS) {
            problems.add("... and more; fix these first");
        }
    }

    private Iterable<JsonNode> array(JsonNode arr, String field) {
        if (arr == null || arr.isNull()) {
            return List.of();
        }
        if (!arr.isArray()) {
            problem("the map: \"" + field + "\" must be an array");
            return List.of();
        }
        return arr;
    }

    private void known(JsonNode obj, String what, String... fields) {
        Set<String> ok = Set.of(fields);
        for (Iterator<String> it = ((ObjectNode) obj).fieldNames(); it.hasNext(); ) {
            String f = it.next();
            if (!ok.contains(f)) {
                problem(what + ": unknown field \"" + f + "\"; known: " + String.join(", ", fields));
            }
        }
    }

    private String text(JsonNode obj, String field, String what, boolean required) {
        JsonNode v = obj.get(field);
        if (v == null || v.isNull()) {
            if (required) {
                problem(what + ": \"" + field + "\" is missing");
            }
            return null;
        }
        if (!v.isTextual() || v.asText().isBlank()) {
            problem(what + ": \"" + field + "\" must be a non-empty string");
            return null;
        }
        return v.asText();
    }

    private double number(JsonNode obj, String field, String what, double dflt) {
        JsonNode v = obj.get(field);
        if (v == null || v.isNull()) {
            return dflt;
        }
        if (!v.isNumber()) {
            problem(what + ": \"" + field + "\" must be a number (metres)");
            return dflt;
        }
        return v.asDouble();
    }

    private <E extends Enum<E>> E enumOf(Class<E> type, String value, String what, String field) {
        if (value == null) {
            return null;
        }
        try {
            return Enum.valueOf(type, value.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            List<String> names = new ArrayList<>();
            for (E c : type.getEnumConstants()) {
                names.add(c.name().toLowerCase(Locale.ROOT));
            }
            problem(what + ": \"" + field + "\" is '" + value + "'; one of " + String.join(", ", names));
            return null;
        }
    }

    private Point point(JsonNode v, String what) {
        if (v == null || !v.isArray() || v.size() != 2 || !v.get(0).isNumber() || !v.get(1).isNumber()) {
            problem(what + ": must be a point [x, y] in metres");
            return null;
        }
        double x = v.get(0).asDouble();
        double y = v.get(1).asDouble();
        if (!Double.isFinite(x) || !Double.isFinite(y)) {
            problem(what + ": must be finite");
            return null;
        }
        return new Point(x, y);
    }

    private List<Point> points(JsonNode v, String what) {
        if (v == null || !v.isArray()) {
            problem(what + ": must be an array of points [[x, y], ...]");
            return null;
        }
        List<Point> out = new ArrayList<>();
        int k = 0;
        for (JsonNode p : v) {
            k++;
            Point pt = point(p, what + " point " + k);
            if (pt == null) {
                return null;
            }
            out.add(pt);
        }
        return out;
    }
}
