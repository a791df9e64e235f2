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
