package io.concord.agents.map;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * A hospital floor: walls, named areas (wards, rooms, corridors, halls), doors in gaps of the
 * walls, and the route graph (nodes and edges, each edge naming the door it passes through).
 * Read from the JSON format of {@code docs/hospital-map.md}, checked whole, immutable.
 *
 * <pre>{@code
 * HospitalMap map = HospitalMap.defaultHospital();
 * HospitalMap mine = HospitalMap.load(Path.of("floor2.json"));   // MapException if anything is wrong
 * }</pre>
 */
public final class HospitalMap {
    /** The resource of the default hospital. */
    public static final String DEFAULT_RESOURCE = "/io/concord/agents/map/hospital.json";

    private final String name;
    private final double clearanceM;
    private final List<Wall> walls;
    private final List<Area> areas;
    private final Map<String, Door> doors;
    private final List<Door> doorList;
    private final Map<Integer, Node> nodes;
    private final List<Node> nodeList;
    private final List<Edge> edges;
    private final Map<Integer, List<Edge>> adjacency;
    private final List<Integer> parking;
    /** node -> its two neighbours along a two-lane corridor through it, lower id first (see {@link #laneAxis}). */
    private final Map<Integer, int[]> laneAxes;
    private List<String> warnings;

    HospitalMap(String name, double clearanceM, List<Wall> walls, List<Area> areas, List<Door> doors, List<Node> nodes,
                List<Edge> edges, List<Integer> parking) {
        this.name = name;
        this.parking = List.copyOf(parking);
        this.clearanceM = clearanceM;
        this.walls = List.copyOf(walls);
        this.areas = List.copyOf(areas);
        Map<String, Door> d = new LinkedHashMap<>();
        for (Door door : doors) {
            d.put(door.id(), door);
        }
        this.doors = Collections.unmodifiableMap(d);
        this.doorList = List.copyOf(d.values());
        Map<Integer, Node> n = new LinkedHashMap<>();
        for (Node node : nodes) {
            n.put(node.id(), node);
        }
        this.nodes = Collections.unmodifiableMap(n);
        this.nodeList = List.copyOf(n.values());
        this.edges = List.copyOf(edges);
        Map<Integer, List<Edge>> adj = new HashMap<>();
        for (Node node : nodes) {
            adj.put(node.id(), new ArrayList<>());
        }
        for (Edge e : edges) {
            adj.get(e.a()).add(e);
            adj.get(e.b()).add(e);
        }
        adj.replaceAll((k, v) -> List.copyOf(v));
        this.adjacency = Collections.unmodifiableMap(adj);
        Map<Integer, int[]> axes = new HashMap<>();
        for (Node node : nodes) {
            int[] axis = axis(node.id());
            if (axis != null) {
                axes.put(node.id(), axis);
            }
        }
        this.laneAxes = Collections.unmodifiableMap(axes);
    }

    /** The two two-lane edges at a node that run on in line (turning at most {@link #LANE_TURN_DEG}), or null. */
    private int[] axis(int id) {
        List<Edge> two = new ArrayList<>();
        for (Edge e : adjacency.get(id)) {
            if (e.twoLanes()) {
                two.add(e);
            }
        }
        if (two.size() != 2) {
            return null;
        }
        int x = Math.min(two.get(0).other(id), two.get(1).other(id));
        int y = Math.max(two.get(0).other(id), two.get(1).other(id));
        Point p = nodes.get(x).at();
        Point c = nodes.get(id).at();
        Point q = nodes.get(y).at();
        double turn = Math.abs(Math.atan2((c.x() - p.x()) * (q.y() - c.y()) - (c.y() - p.y()) * (q.x() - c.x()),
                (c.x() - p.x()) * (q.x() - c.x()) + (c.y() - p.y()) * (q.y() - c.y())));
        return Math.toDegrees(turn) <= LANE_TURN_DEG ? new int[] {x, y} : null;
    }

    // ---- lanes ------------------------------------------------------------------------------------

    /**
     * How far right of a two-lane edge's line a chair drives: chairs in the two lanes keep 1.6 m
     * between centres, so that two turning on the spot at a node's two lane points at once (0.7 m
     * reach each) keep 0.2 m apart (at 1.2 m, two chairs turning into rooms on either side of a
     * ring corridor touched: seed 37 of the large generated map). A node with lanes has a floor
     * marker at each lane's point ({@link #markers()}).
     */
    public static final double LANE_OFFSET_M = 0.8;
    /**
     * The least distance from a lane's point to the opening of a door a chair turns to there: it
     * waits there for the door, facing it, its nose 0.6 m ahead (a hinged leaf's swing keeps
     * clear of every lane's point by the map's rules, as of every node). A room door in the wall
     * of a 3.6 m corridor is 1 m from the lane's point on its side.
     */
    static final double LANE_DOOR_WAIT_M = 0.95;
    /** The most a two-lane corridor may turn at a node for chairs to keep their lanes through it. */
    public static final double LANE_TURN_DEG = 30;

    /**
     * A node chairs may pass through in lanes: the two neighbours of the two-lane corridor running
     * through it in line, lower id first, or null. A chair driving from the first to the second is
     * in lane 0, the other way in lane 1, and so is one turning off the corridor to its right or
     * onto it from its right, which crosses no other lane ({@link #lane}); any other way through
     * the node (turning across the other lane, starting, ending or turning back there) takes the
     * whole node.
     */
    public int[] laneAxis(int node) {
        int[] a = laneAxes.get(node);
        return a == null ? null : a.clone();
    }

    /**
     * The longest a chair drives on its odometry alone: an edge up to this long has floor markers
     * at its ends only; a longer one has markers along it too ({@link #edgeMarkers()}).
     */
    public static final double OPEN_LOOP_M = 6.0;
    /** The most two floor markers along a long edge are apart. */
    public static final double EDGE_MARKER_SPACING_M = 3.0;

    /**
     * Where the floor markers are, which a chair reads to find its place again: every node, at a
     * node with lanes each lane's point too, and along every edge longer than {@link #OPEN_LOOP_M}
     * ({@link #edgeMarkers()}).
     */
    public List<Point> markers() {
        List<Point> out = nodeMarkers();
        out.addAll(edgeMarkers());
        return out;
    }

    /** The markers at the nodes and their lanes' points. */
    public List<Point> nodeMarkers() {
        List<Point> out = new ArrayList<>();
        for (Node n : nodeList) {
            out.add(n.at());
        }
        for (Node n : nodeList) {
            if (laned(n.id())) {
                out.add(lanePoint(n.id(), 0));
                out.add(lanePoint(n.id(), 1));
            }
        }
        return out;
    }

    /**
     * The markers along the edges longer than {@link #OPEN_LOOP_M}, so that no chair drives more
     * than {@link #EDGE_MARKER_SPACING_M} between two: evenly spaced, on the edge's line (and on
     * both lanes' lines, {@link #LANE_OFFSET_M} either side, on an edge of two lanes). Odometry's
     * heading drift grows the error off the line with the square of the distance driven; the
     * markers bound that distance. On a real floor, put a marker at each.
     */
    public List<Point> edgeMarkers() {
        List<Point> out = new ArrayList<>();
        for (Edge e : edges()) {
            double len = e.length(this);
            if (len <= OPEN_LOOP_M + 1e-9) {
                continue;
            }
            Point a = node(e.a()).at();
            Point b = node(e.b()).at();
            double ux = (b.x() - a.x()) / len;
            double uy = (b.y() - a.y()) / len;
            int n = (int) Math.ceil(len / EDGE_MARKER_SPACING_M - 1e-9);
            for (int k = 1; k < n; k++) {
                double x = a.x() + ux * len * k / n;
                double y = a.y() + uy * len * k / n;
                if (e.lanes() == 2) {
                    out.add(new Point(x - uy * LANE_OFFSET_M, y + ux * LANE_OFFSET_M));
                    out.add(new Point(x + uy * LANE_OFFSET_M, y - ux * LANE_OFFSET_M));
                } else {
                    out.add(new Point(x, y));
                }
            }
        }
        return out;
    }

    /** Whether chairs may pass through {@code node} in lanes. */
    public boolean laned(int node) {
        return laneAxes.containsKey(node);
    }

    /**
     * The lane a chair driving from {@code prev} through {@code node} on to {@code next} keeps
     * there: 0 or 1, or -1 if it takes the whole node (prev or next -1: it starts or ends there).
     * Straight on along the corridor, its lane; turning off it to the right, or onto it from the
     * right, the lane it drives in on the corridor, if it waits there far enough from the door
     * the turn goes through and in line with its middle (not a revolving one); any other way,
     * the whole node.
     */
    public int lane(int prev, int node, int next) {
        int[] a = laneAxes.get(node);
        if (a == null || prev < 0 || next < 0 || prev == next) {
            return -1;
        }
        boolean inP = prev == a[0] || prev == a[1];
        boolean inN = next == a[0] || next == a[1];
        if (inP && inN) {
            return prev == a[0] ? 0 : 1;
        }
        if (inP) {
            int lane = prev == a[0] ? 0 : 1;
            return turnsRight(node, lane, next) ? lane : -1;
        }
        if (inN) {
            int lane = next == a[1] ? 0 : 1;
            return turnsRight(node, lane, prev) ? lane : -1;
        }
        return -1;
    }

    /** Whether {@code branch} lies right of {@code lane} at {@code node}, and a chair in the lane may wait there for its door. */
    private boolean turnsRight(int node, int lane, int branch) {
        int[] a = laneAxes.get(node);
        Point c = nodes.get(node).at();
        Point from = nodes.get(lane == 0 ? a[0] : a[1]).at();
        Point to = nodes.get(lane == 0 ? a[1] : a[0]).at();
        Point b = nodes.get(branch).at();
        double dx = to.x() - from.x();
        double dy = to.y() - from.y();
        if (dx * (b.y() - c.y()) - dy * (b.x() - c.x()) >= 0) {
            return false; // on the left, or straight ahead: across the other lane
        }
        Edge e = edge(node, branch).orElseThrow();
        if (e.door() == null) {
            return true;
        }
        Door d = door(e.door());
        if (d.kind() == Door.Kind.ROTATING) {
            return false;
        }
        Point lp = lanePoint(node, lane);
        // Square on through the middle of the opening, as an edge through a door runs: a lane's
        // point 0.1 m to one side (a corridor bending at the node) left 0.15 m to the jamb, and a
        // chair met it (seed 2 of the generated maps' soak, the large map).
        double along = ((lp.x() - d.centre().x()) * (d.to().x() - d.from().x()) + (lp.y() - d.centre().y()) * (d.to().y() - d.from().y()))
                / d.width();
        return Math.abs(along) <= LANE_DOOR_OFF_MIDDLE_M && Geometry.pointToSegment(lp, d.from(), d.to()) >= LANE_DOOR_WAIT_M;
    }

    /** How far a lane's point may be from the line through the middle of the door a chair turns to from it. */
    static final double LANE_DOOR_OFF_MIDDLE_M = 0.05;

    /**
     * Where a chair driving {@code prev} -> {@code node} -> {@code next} passes the node: the node
     * itself, or its lane's point {@link #LANE_OFFSET_M} to the right of the corridor's line.
     */
    public Point waypoint(int prev, int node, int next) {
        int lane = lane(prev, node, next);
        return lane < 0 ? node(node).at() : lanePoint(node, lane);
    }

    /** The point of a laned node's lane: right of the way a chair in that lane drives, where the lane's floor marker is. */
    public Point lanePoint(int node, int lane) {
        int[] a = laneAxes.get(node);
        if (a == null) {
            throw new IllegalArgumentException("node " + node + " of map '" + name + "' has no lanes");
        }
        Point p = nodes.get(lane == 0 ? a[0] : a[1]).at();
        Point c = nodes.get(node).at();
        Point q = nodes.get(lane == 0 ? a[1] : a[0]).at();
        double ux = (c.x() - p.x()) / c.distanceTo(p) + (q.x() - c.x()) / q.distanceTo(c);
        double uy = (c.y() - p.y()) / c.distanceTo(p) + (q.y() - c.y()) / q.distanceTo(c);
        double len = Math.hypot(ux, uy);
        // Right of the heading (ux, uy) is (uy, -ux).
        return new Point(c.x() + LANE_OFFSET_M * uy / len, c.y() - LANE_OFFSET_M * ux / len);
    }

    /** The default hospital shipped with Concord: two wards joined by a corridor and a lobby. */
    public static HospitalMap defaultHospital() {
        try (InputStream in = HospitalMap.class.getResourceAsStream(DEFAULT_RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException("the default hospital " + DEFAULT_RESOURCE + " is missing from the class path");
            }
            return parse(new String(in.readAllBytes(), StandardCharsets.UTF_8), "resource " + DEFAULT_RESOURCE);
        } catch (IOException e) {
            throw new IllegalStateException("cannot read " + DEFAULT_RESOURCE, e);
        }
    }

    /**
     * Reads a map file.
     *
     * @throws MapException if the file is missing, unreadable, malformed or inconsistent
     */
    public static HospitalMap load(Path file) {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new MapException(file.toString(), List.of("no such file; give the path of a map in the format of docs/hospital-map.md"));
        } catch (IOException e) {
            throw new MapException(file.toString(), List.of("cannot be read: " + e));
        }
        return parse(text, file.toString());
    }

    /**
     * Reads a map from its JSON text.
     *
     * @param source where it came from, for messages
     * @throws MapException if it is malformed or inconsistent
     */
    public static HospitalMap parse(String json, String source) {
        return new MapReader(source).read(json);
    }

    /** The map's name. */
    public String name() {
        return name;
    }

    /** The least distance in metres a node keeps from a wall's face. */
    public double clearanceM() {
        return clearanceM;
    }

    /** Every wall. */
    public List<Wall> walls() {
        return walls;
    }

    /** Every area. */
    public List<Area> areas() {
        return areas;
    }

    /** Every door, in map order. */
    public List<Door> doors() {
        return doorList;
    }

    /** The door with this id. */
    public Door door(String id) {
        Door d = doors.get(id);
        if (d == null) {
            throw new IllegalArgumentException("map '" + name + "' has no door '" + id + "'");
        }
        return d;
    }

    /**
     * What a chair could not drive on this map, though the reader accepts it: an edge too long for
     * the odometry's drift, a node where a chair turning on the spot would reach a wall, a node in a
     * door leaf's swing or too near a door to wait, and the like (docs/hospital-map.md, "What a chair
     * needs"). Each names its element and what to do; empty for a map chairs can drive.
     */
    public synchronized List<String> warnings() {
        if (warnings == null) {
            warnings = List.copyOf(Drivability.problems(this));
        }
        return warnings;
    }

    /**
     * The places where chairs start and stand idle (the map's {@code parking}), in the order chairs
     * take them: the first chair at the first. Empty if the map names none.
     */
    public List<Integer> parking() {
        return parking;
    }

    /** Whether a node lies in a patient's room (an area of kind {@code room}): where a patient is fetched or taken, never where a chair parks or steps aside. */
    public boolean inRoom(int node) {
        String area = node(node).area();
        return area != null && area(area).kind() == Area.Kind.ROOM;
    }

    /** The nodes in patients' rooms, in map order. */
    public List<Integer> roomNodes() {
        return nodes().stream().map(Node::id).filter(this::inRoom).toList();
    }

    /** Every node, in map order. */
    public List<Node> nodes() {
        return nodeList;
    }

    /** True if the map has a node with this id. */
    public boolean hasNode(int id) {
        return nodes.containsKey(id);
    }

    /**
     * The node a person names: a node's number ({@code 3}), or a patient's room by its name
     * ({@code A2}, {@code Room A2}, {@code a2}: the room's name, with or without its first word,
     * or its id, in any case), which gives the room's first node in map order.
     *
     * @throws IllegalArgumentException naming the map's rooms, for a name that is no node nor room
     */
    public int nodeNamed(String nodeOrRoom) {
        String t = nodeOrRoom == null ? "" : nodeOrRoom.trim();
        if (t.matches("\\d{1,9}")) {
            int id = Integer.parseInt(t);
            if (!hasNode(id)) {
                throw new IllegalArgumentException("no node " + id + " in " + name);
            }
            return id;
        }
        List<String> rooms = roomNames();
        for (Area a : areas) {
            if (a.kind() != Area.Kind.ROOM) {
                continue;
            }
            String short_ = shortName(a);
            if (t.equalsIgnoreCase(a.name()) || t.equalsIgnoreCase(short_) || t.equalsIgnoreCase(a.id())) {
                for (Node n : nodeList) {
                    if (a.id().equals(n.area())) {
                        return n.id();
                    }
                }
                throw new IllegalArgumentException(a.name() + " has no node of the route graph in " + name);
            }
        }
        throw new IllegalArgumentException("no node or room '" + t + "' in " + name + (rooms.isEmpty() ? " (it has no rooms)"
                : "; rooms: " + String.join(", ", rooms)) + "; or a node's number");
    }

    /** The patients' rooms by the short names {@link #nodeNamed} takes ({@code A2}, {@code B7}), in map order. */
    public List<String> roomNames() {
        List<String> rooms = new ArrayList<>();
        for (Area a : areas) {
            if (a.kind() == Area.Kind.ROOM) {
                rooms.add(shortName(a));
            }
        }
        return rooms;
    }

    private static String shortName(Area a) {
        return a.name().contains(" ") ? a.name().substring(a.name().indexOf(' ') + 1) : a.name();
    }

    /** The node with this id. */
    public Node node(int id) {
        Node n = nodes.get(id);
        if (n == null) {
            throw new IllegalArgumentException("map '" + name + "' has no node " + id);
        }
        return n;
    }

    /** Every edge. */
    public List<Edge> edges() {
        return edges;
    }

    /** The edges at a node. */
    public List<Edge> edgesAt(int node) {
        List<Edge> e = adjacency.get(node);
        if (e == null) {
            throw new IllegalArgumentException("map '" + name + "' has no node " + node);
        }
        return e;
    }

    /** The edge between two nodes, if any. */
    public Optional<Edge> edge(int a, int b) {
        for (Edge e : edgesAt(a)) {
            if (e.other(a) == b) {
                return Optional.of(e);
            }
        }
        return Optional.empty();
    }

    /** The area with this id. */
    public Area area(String id) {
        for (Area a : areas) {
            if (a.id().equals(id)) {
                return a;
            }
        }
        throw new IllegalArgumentException("map '" + name + "' has no area '" + id + "'");
    }

    /** The smallest area (room before ward) containing the point, if any. */
    public Optional<Area> areaAt(Point p) {
        Area best = null;
        for (Area a : areas) {
            if (a.contains(p) && (best == null || a.kind() != Area.Kind.WARD)) {
                best = a;
            }
        }
        return Optional.ofNullable(best);
    }

    /** The ward a point lies in, if any. */
    public Optional<Area> wardAt(Point p) {
        for (Area a : areas) {
            if (a.kind() == Area.Kind.WARD && a.contains(p)) {
                return Optional.of(a);
            }
        }
        return Optional.empty();
    }

    /** The bounding box of the walls: {minX, minY, maxX, maxY}. */
    public double[] bounds() {
        double minX = Double.MAX_VALUE;
        double minY = Double.MAX_VALUE;
        double maxX = -Double.MAX_VALUE;
        double maxY = -Double.MAX_VALUE;
        for (Wall w : walls) {
            for (Point p : List.of(w.from(), w.to())) {
                minX = Math.min(minX, p.x());
                minY = Math.min(minY, p.y());
                maxX = Math.max(maxX, p.x());
                maxY = Math.max(maxY, p.y());
            }
        }
        for (Node n : nodes.values()) {
            minX = Math.min(minX, n.at().x());
            minY = Math.min(minY, n.at().y());
            maxX = Math.max(maxX, n.at().x());
            maxY = Math.max(maxY, n.at().y());
        }
        return new double[] {minX, minY, maxX, maxY};
    }

    @Override
    public String toString() {
        return "HospitalMap[" + name + ": " + walls.size() + " walls, " + areas.size() + " areas, " + doors.size()
                + " doors, " + nodes.size() + " nodes, " + edges.size() + " edges]";
    }
}
