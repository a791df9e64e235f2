package io.concord.sim.maps;

import io.concord.agents.map.HospitalMap;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.TreeSet;

/**
 * Generates hospital floors from a seed, as JSON in the map format of {@code docs/hospital-map.md},
 * so that they go through the same reader and checks as a hand-written map. The same seed and
 * shape give the same text, byte for byte.
 *
 * <p>A generated hospital is a main corridor running east-west through wards and the links
 * between them:
 * <ul>
 *   <li>wards of patient rooms on both sides of a 3.6 m corridor, the rooms 5 m wide and 6 m deep,
 *       each behind a 1.2 m hinged or sliding door;</li>
 *   <li>in some maps a ring ward: a loop of corridors round two rows of rooms, rooms outside it
 *       too, so that there are two ways round;</li>
 *   <li>ward doors of 3.2 m across the corridor where a ward meets a link: sliding into a pocket in
 *       the wall, or revolving, its route through one lane 0.8 m beside the pivot (on the ward's
 *       side a 3 m vestibule, so that the node in the lane stands away from the rooms' doors);</li>
 *   <li>a lobby (a hall) open to a link, its nodes a grid, store rooms behind it whose hinged doors
 *       swing out into the lobby;</li>
 *   <li>dead-end wings: a corridor off a link with rooms on both sides, ending in a wall, its
 *       entrance open, sliding or revolving; a link at an end of the main corridor ends in a
 *       dead-end stub;</li>
 *   <li>a bottleneck: a corridor 2 m wide, the only way between two parts of the hospital, grown
 *       to two fifths of it or more on each side where the node count allows.</li>
 * </ul>
 * Rooms fill their rows: a room left out to hit the node count is taken in by its neighbour (a
 * double room), and the end rooms reach over vestibules and round a ring's corners. Node ids run
 * west to east; every node is named for what it is ("Ward B ring, north-east corner", "Room C4",
 * "Lobby, row 2, place 3"); parking places are the lobby's nodes, then the dead ends, then corridor
 * nodes taken from each part in turn, never where chairs wait for a ward door or in the bottleneck.
 *
 * <p>The geometry is made to be driven, not only to be legal ({@code HospitalMap.warnings()} checks it):
 * no edge longer than 6 m, every node at least 0.8 m from a wall's face, nodes out of the hinged
 * leaves' swing and away from the revolving doors' sweep, a node on each side of every door at
 * least 1.5 m from the opening where a chair can wait for it.
 *
 * <pre>{@code
 * String json = MapGenerator.generate(7, Shape.medium());
 * HospitalMap map = MapGenerator.map(7, Shape.medium());   // the same, read and checked
 * }</pre>
 */
public final class MapGenerator {
    /** How far a map's node count may be from its shape's, as a fraction (the generator aims at it exactly). */
    public static final double NODE_TOLERANCE = 0.1;

    // Every length is a whole number of decimetres; the JSON writes them as metres.
    private static final int CORRIDOR = 36;
    private static final int MID = 18;
    private static final int ROOM_W = 50;
    private static final int ROOM_D = 60;
    private static final int DOOR = 12;
    private static final int WARD_DOOR = 32;
    /** How far a revolving door's lane runs from its pivot: a quarter of the 3.2 m opening. */
    private static final int LANE = 8;
    /** How far from a ward door the nodes where chairs wait for it are. */
    private static final int WAIT = 24;
    /**
     * A stretch of a ward's corridor without rooms, on the ward's side of a revolving ward door: the
     * node in its lane stands there, away from the rooms' doors.
     */
    private static final int VESTIBULE = 30;
    /** The dead-end stub beyond the last node of a link at an end of the main corridor. */
    private static final int STUB = 40;
    private static final int NARROW_LO = 8;
    private static final int NARROW_HI = 28;
    private static final int RING_INNER = 2 * ROOM_D;
    private static final int WING_LINK = 136;
    private static final int WING_ROOM = 50;
    private static final int WING_TAIL = 40;
    private static final int LOBBY_LINK = 120;
    private static final int LOBBY_FIRST = 15;
    private static final int LOBBY_PITCH = 30;
    private static final int LOBBY_LAST = 25;
    private static final int STORE_W = 30;
    private static final int STORE_D = 40;
    private static final int LINK_PITCH = 40;
    private static final int NARROW_PITCH = 60;
    private static final int NARROW_END = 30;

    private final long seed;
    private final Shape shape;
    private final SplittableRandom rnd;
    private final long layoutSeed;
    private final int lobbyRows;

    private MapGenerator(long seed, Shape shape) {
        this.seed = seed;
        this.shape = shape;
        this.rnd = new SplittableRandom(seed);
        this.layoutSeed = rnd.nextLong();
        this.lobbyRows = shape.nodes() >= 100 ? 3 : shape.nodes() >= 50 ? 2 : 1;
    }

    /**
     * A hospital map of this shape, as JSON text in the format of {@code docs/hospital-map.md}.
     * The same seed and shape give the same text.
     *
     * @throws IllegalArgumentException if the shape cannot be built (too few nodes for what it asks)
     */
    public static String generate(long seed, Shape shape) {
        if (shape == null) {
            throw new IllegalArgumentException("a map needs a shape: Shape.small(), medium() or large()");
        }
        return new MapGenerator(seed, shape).build();
    }

    /** The generated map read and checked by {@link HospitalMap#parse}, as a hand-written one is. */
    public static HospitalMap map(long seed, Shape shape) {
        return HospitalMap.parse(generate(seed, shape), source(seed, shape));
    }

    /** What a generated map is called in the reader's messages. */
    public static String source(long seed, Shape shape) {
        return "generated " + shape.name() + " map, seed " + seed;
    }

    // ---- the plan: what lies along the main corridor, west to east ------------------------------

    private enum Entrance { OPEN, SLIDING, ROTATING }

    private enum Style { HINGED, SLIDING, MIXED }

    private enum Role { ROOM, CORRIDOR, HALL, LINK, NARROW, DEAD_END }

    /** A ward on the main corridor: plain (rooms both sides) or a ring. */
    private static final class Ward {
        final boolean ring;
        int columns;
        Style style;
        final Set<Integer> missing = new TreeSet<>();

        Ward(boolean ring, int columns, Style style) {
            this.ring = ring;
            this.columns = columns;
            this.style = style;
        }
    }

    /** A dead-end wing: a corridor off a link, rooms both sides, a wall at its end. */
    private static final class Wing {
        int pairs;
        Style style;
        Entrance entrance;
        int lane;
        final Set<Integer> missing = new TreeSet<>();
    }

    /** A stretch of corridor between wards; it may carry a lobby and a wing, or be the narrow bottleneck. */
    private static final class Link {
        final boolean narrow;
        int length;
        boolean lobby;
        boolean lobbyNorth;
        Wing wing;
        boolean wingNorth;

        Link(boolean narrow) {
            this.narrow = narrow;
        }
    }

    /** Where two segments meet: open, or a ward door across the corridor. */
    private static final class Boundary {
        Entrance kind = Entrance.OPEN;
        int lane;
        int pocket = -1;
    }

    private final List<Object> segments = new ArrayList<>();
    private final List<Boundary> boundaries = new ArrayList<>();
    private final List<Wing> wings = new ArrayList<>();

    private String build() {
        plan();
        size();
        Layout l = layout();
        if (Math.abs(l.nodes.size() - shape.nodes()) > NODE_TOLERANCE * shape.nodes()) {
            throw new IllegalArgumentException("shape " + shape.name() + " asks for " + shape.nodes() + " nodes; its wards, "
                    + "lobby, wings and links need at least " + l.nodes.size() + " (seed " + seed + ")");
        }
        List<int[]> walls = walls(l);
        List<Integer> parking = parking(l);
        if (!shape.oneLane()) {
            lanes(l, walls, parking);
        }
        return json(l, walls, parking);
    }

    /**
     * Two lanes on every corridor and link edge without a door, then one again on each edge a
     * lane of which the map checker finds too near a wall, a leaf's swing or a pivot (and on
     * both corridor edges at a node whose lane point is), until it finds none.
     */
    private void lanes(Layout l, List<int[]> walls, List<Integer> parking) {
        Map<Integer, Role> role = new HashMap<>();
        for (NodeSpec n : l.nodes) {
            role.put(n.id, n.role);
        }
        for (int i = 0; i < l.edges.size(); i++) {
            EdgeSpec e = l.edges.get(i);
            if (e.door == null && corridor(role.get(e.a)) && corridor(role.get(e.b))) {
                l.edges.set(i, new EdgeSpec(e.a, e.b, null, 2));
            }
        }
        for (int round = 0; round < 10; round++) {
            HospitalMap m = HospitalMap.parse(json(l, walls, parking), source(seed, shape));
            Set<Integer> narrow = new TreeSet<>();
            for (String w : m.warnings()) {
                java.util.regex.Matcher lane = LANE_WARNING.matcher(w);
                if (lane.find()) {
                    int node = Integer.parseInt(lane.group(1));
                    narrow.add(node);
                    for (int other : m.laneAxis(node)) {
                        narrow.add(other);
                    }
                } else if (w.contains("lane")) {
                    java.util.regex.Matcher edge = EDGE_WARNING.matcher(w);
                    if (edge.find()) {
                        narrow.add(Integer.parseInt(edge.group(1)));
                        narrow.add(Integer.parseInt(edge.group(2)));
                    }
                }
            }
            if (narrow.isEmpty()) {
                return;
            }
            // A turn's line (a lane's point to a room) too near a jamb: the corridor's lanes there go.
            for (int node : new ArrayList<>(narrow)) {
                if (m.laned(node)) {
                    for (int other : m.laneAxis(node)) {
                        narrow.add(other);
                    }
                }
            }
            for (int i = 0; i < l.edges.size(); i++) {
                EdgeSpec e = l.edges.get(i);
                if (e.lanes == 2 && narrow.contains(e.a) && narrow.contains(e.b)) {
                    l.edges.set(i, new EdgeSpec(e.a, e.b, null, 1));
                }
            }
        }
    }

    private static final java.util.regex.Pattern LANE_WARNING = java.util.regex.Pattern.compile("^lane [01] of node (-?\\d+)");
    private static final java.util.regex.Pattern EDGE_WARNING = java.util.regex.Pattern.compile("^edge (-?\\d+)-(-?\\d+)");

    private static boolean corridor(Role r) {
        return r == Role.CORRIDOR || r == Role.LINK;
    }

    private void plan() {
        int ringAt = shape.ring() ? rnd.nextInt(shape.wards()) : -1;
        List<Link> inner = new ArrayList<>();
        for (int i = 0; i < shape.wards(); i++) {
            if (i > 0) {
                Link k = new Link(false);
                inner.add(k);
                segments.add(k);
            }
            boolean ring = i == ringAt;
            boolean few = shape.nodes() < 50;
            segments.add(new Ward(ring, ring ? (few ? 1 : 2) : few ? 2 : 2 + rnd.nextInt(2), style()));
        }
        if (shape.bottleneck()) {
            if (!inner.isEmpty()) {
                Link k = inner.remove(rnd.nextInt(inner.size()));
                segments.set(segments.indexOf(k), new Link(true));
            } else {
                // One ward: the narrow corridor joins it to a link of its own at one end.
                Link end = new Link(false);
                inner.add(end);
                if (rnd.nextBoolean()) {
                    segments.add(0, new Link(true));
                    segments.add(0, end);
                } else {
                    segments.add(new Link(true));
                    segments.add(end);
                }
            }
        }
        // The lobby and the wings, each on a side of a link (never the narrow one).
        List<Link> links = new ArrayList<>(inner);
        Link lobby = placeable(links, false);
        lobby.lobby = true;
        lobby.lobbyNorth = rnd.nextInt(4) == 0;
        for (int w = 0; w < shape.wings(); w++) {
            Link k = placeable(links, true);
            Wing wing = new Wing();
            wing.pairs = 1 + rnd.nextInt(2);
            wing.style = style();
            wing.entrance = Entrance.values()[rnd.nextInt(3)];
            wing.lane = rnd.nextBoolean() ? 1 : -1;
            k.wing = wing;
            k.wingNorth = k.lobby ? !k.lobbyNorth : rnd.nextInt(3) > 0;
            wings.add(wing);
        }
        for (Object s : segments) {
            if (s instanceof Link k && !k.narrow) {
                k.length = k.wing != null ? WING_LINK : k.lobby ? LOBBY_LINK : 80 + 20 * rnd.nextInt(3);
            } else if (s instanceof Link k) {
                k.length = 100 + 20 * rnd.nextInt(3);
            }
        }
        for (int i = 0; i + 1 < segments.size(); i++) {
            Object a = segments.get(i);
            Object b = segments.get(i + 1);
            Boundary bd = new Boundary();
            boolean narrow = a instanceof Link ka && ka.narrow || b instanceof Link kb && kb.narrow;
            Ward ward = a instanceof Ward wa ? wa : b instanceof Ward wb ? wb : null;
            if (!narrow && ward != null) {
                int r = rnd.nextInt(10);
                // A ring's corner node is too near its end for a revolving door's lane: open or sliding.
                bd.kind = r < 2 ? Entrance.OPEN : r < 6 || ward.ring ? Entrance.SLIDING : Entrance.ROTATING;
                bd.lane = rnd.nextBoolean() ? 1 : -1;
                // A sliding ward door's leaf runs into the wall beside the corridor: a ring's
                // vertical corridor north of it, a plain ward's end rooms on either side.
                bd.pocket = ward.ring ? 1 : rnd.nextInt(2);
            }
            boundaries.add(bd);
        }
        everyKindOfDoor();
    }

    private Style style() {
        return Style.values()[rnd.nextInt(3)];
    }

    /** A link with a free side for the lobby or a wing, adding one at an end of the corridor if none is free. */
    private Link placeable(List<Link> links, boolean wing) {
        List<Link> free = new ArrayList<>();
        for (Link k : links) {
            if (wing ? k.wing == null : !k.lobby) {
                free.add(k);
            }
        }
        if (!free.isEmpty()) {
            return free.get(rnd.nextInt(free.size()));
        }
        Link k = new Link(false);
        // At an end of the corridor where a ward is, a plain ward's if it can (a revolving door fits there).
        int west = segments.get(0) instanceof Ward w ? (w.ring ? 1 : 2) : 0;
        int east = segments.get(segments.size() - 1) instanceof Ward w ? (w.ring ? 1 : 2) : 0;
        if (west == 0 && east == 0) {
            throw new IllegalArgumentException("shape " + shape.name() + ": no room along the corridor for " + shape.wings()
                    + " wings and a lobby; give it more wards");
        }
        if (west > east || west == east && rnd.nextBoolean()) {
            segments.add(0, k);
        } else {
            segments.add(k);
        }
        links.add(k);
        return k;
    }

    /** Makes sure a revolving, a sliding and a hinged door are there when the plan has room for them. */
    private void everyKindOfDoor() {
        List<Object> rotatable = new ArrayList<>();
        boolean rotating = false;
        for (int i = 0; i < boundaries.size(); i++) {
            Boundary b = boundaries.get(i);
            rotating |= b.kind == Entrance.ROTATING;
            Object a = segments.get(i);
            Object c = segments.get(i + 1);
            boolean narrow = a instanceof Link ka && ka.narrow || c instanceof Link kc && kc.narrow;
            Ward ward = a instanceof Ward wa ? wa : c instanceof Ward wc ? wc : null;
            if (!narrow && ward != null && !ward.ring) {
                rotatable.add(b);
            }
        }
        for (Wing w : wings) {
            rotating |= w.entrance == Entrance.ROTATING;
            rotatable.add(w);
        }
        // An open entrance rather than a sliding one, if there is one (the sliding door may be the only one).
        List<Object> open = new ArrayList<>();
        for (Object o : rotatable) {
            if ((o instanceof Boundary b ? b.kind : ((Wing) o).entrance) == Entrance.OPEN) {
                open.add(o);
            }
        }
        if (!open.isEmpty()) {
            rotatable = open;
        }
        if (!rotating && !rotatable.isEmpty()) {
            Object o = rotatable.get(rnd.nextInt(rotatable.size()));
            if (o instanceof Boundary b) {
                b.kind = Entrance.ROTATING;
            } else {
                ((Wing) o).entrance = Entrance.ROTATING;
            }
        }
        boolean sliding = boundaries.stream().anyMatch(b -> b.kind == Entrance.SLIDING)
                || wings.stream().anyMatch(w -> w.entrance == Entrance.SLIDING);
        List<Object> styled = new ArrayList<>();
        for (Object s : segments) {
            if (s instanceof Ward w) {
                styled.add(w);
            }
        }
        styled.addAll(wings);
        // A ward of hinged doors, so that (with four of them or more) both hinges and both swings are there.
        Object hingedWard = null;
        for (Object o : styled) {
            if (style(o) == Style.HINGED) {
                hingedWard = o;
                break;
            }
        }
        if (hingedWard == null) {
            hingedWard = styled.get(rnd.nextInt(styled.size()));
            setStyle(hingedWard, Style.HINGED);
        }
        for (Object o : styled) {
            // (A ward of mixed doors may draw none sliding.)
            sliding |= style(o) == Style.SLIDING;
        }
        if (!sliding && styled.size() > 1) {
            List<Object> others = new ArrayList<>(styled);
            others.remove(hingedWard);
            setStyle(others.get(rnd.nextInt(others.size())), Style.SLIDING);
        }
    }

    private static Style style(Object o) {
        return o instanceof Ward w ? w.style : ((Wing) o).style;
    }

    private static void setStyle(Object o, Style st) {
        if (o instanceof Ward w) {
            w.style = st;
        } else {
            ((Wing) o).style = st;
        }
    }

    /** Grows the wards and wings until the map has the shape's node count, then leaves out rooms to hit it. */
    private void size() {
        Layout first = layout();
        int count = first.nodes.size();
        List<Ward> wards = new ArrayList<>();
        // Which side of the bottleneck each ward and wing lies on (true: west), and how many nodes each side has.
        Map<Object, Boolean> west = new LinkedHashMap<>();
        int narrowAt = -1;
        for (int i = 0; i < segments.size(); i++) {
            if (segments.get(i) instanceof Link k && k.narrow) {
                narrowAt = i;
            }
        }
        for (int i = 0; i < segments.size(); i++) {
            if (segments.get(i) instanceof Ward w) {
                wards.add(w);
                west.put(w, i < narrowAt);
            } else if (segments.get(i) instanceof Link k && k.wing != null) {
                west.put(k.wing, i < narrowAt);
            }
        }
        int[] sides = new int[2];
        if (narrowAt >= 0) {
            int x = 0;
            for (NodeSpec n : first.nodes) {
                if (n.role == Role.NARROW) {
                    x = n.x;
                }
            }
            for (NodeSpec n : first.nodes) {
                if (n.role != Role.NARROW) {
                    sides[n.x < x ? 0 : 1]++;
                }
            }
        }
        while (count < shape.nodes()) {
            List<Object> options = new ArrayList<>();
            for (Ward w : wards) {
                if (w.ring ? w.columns < 6 : w.columns < 8) {
                    for (int k = 0; k < (w.ring ? 1 : 3); k++) {
                        options.add(w);
                    }
                }
            }
            for (Wing w : wings) {
                if (w.pairs < 5) {
                    options.add(w);
                    options.add(w);
                }
            }
            if (options.isEmpty()) {
                options.addAll(wards);
            }
            // A bottleneck joins two parts of a size: grow the smaller while it is under two fifths.
            if (narrowAt >= 0 && Math.min(sides[0], sides[1]) * 5 < 2 * (sides[0] + sides[1])) {
                boolean smallWest = sides[0] < sides[1];
                List<Object> small = new ArrayList<>();
                for (Object o : options) {
                    if (west.get(o) == smallWest) {
                        small.add(o);
                    }
                }
                if (small.isEmpty()) {
                    // Its wards are as long as they usually get: longer, then.
                    for (Map.Entry<Object, Boolean> e : west.entrySet()) {
                        if (e.getValue() == smallWest) {
                            small.add(e.getKey());
                        }
                    }
                }
                if (!small.isEmpty()) {
                    options = small;
                }
            }
            Object o = options.get(rnd.nextInt(options.size()));
            int delta;
            if (o instanceof Ward w) {
                w.columns++;
                delta = w.ring ? 6 : 3;
            } else {
                ((Wing) o).pairs++;
                delta = 3;
            }
            count += delta;
            sides[west.get(o) ? 0 : 1] += delta;
        }
        // Leave out rooms to hit the count: at most a third of a ward's, never two side by side,
        // never the only room of its row, never in a plain ward's end columns (its end rooms' walls
        // hold the ward doors' pockets). A room left out is taken in by its neighbour.
        List<int[]> spare = new ArrayList<>();
        List<Set<Integer>> owners = new ArrayList<>();
        List<Integer> limits = new ArrayList<>();
        for (Ward w : wards) {
            owners.add(w.missing);
            limits.add(w.columns * (w.ring ? 4 : 2) / 3);
            for (int row = 0; row < (w.ring ? 4 : 2); row++) {
                for (int c = w.ring ? 0 : 1; c < (w.ring ? w.columns : w.columns - 1) && w.columns > 1; c++) {
                    spare.add(new int[] {owners.size() - 1, row, c});
                }
            }
        }
        for (Wing w : wings) {
            owners.add(w.missing);
            limits.add(w.pairs * 2 / 3);
            for (int row = 0; row < 2; row++) {
                for (int c = 0; c < w.pairs && w.pairs > 1; c++) {
                    spare.add(new int[] {owners.size() - 1, row, c});
                }
            }
        }
        for (int excess = count - shape.nodes(); excess > 0 && !spare.isEmpty(); ) {
            int[] s = spare.remove(rnd.nextInt(spare.size()));
            Set<Integer> missing = owners.get(s[0]);
            int key = s[1] * 100 + s[2];
            if (missing.size() < limits.get(s[0]) && !missing.contains(key - 1) && !missing.contains(key + 1)) {
                missing.add(key);
                excess--;
            }
        }
    }

    // ---- the layout: rectangles, doors, nodes and edges, in decimetres ---------------------------

    /** An area: its outline as x, y, x, y... */
    private record AreaSpec(String id, String kind, String name, String ward, int[] outline) {
    }

    private record DoorSpec(String id, String kind, int fx, int fy, int tx, int ty, String hinge, String swing) {
    }

    private record NodeSpec(int id, int x, int y, String name, Role role, String group) {
    }

    private record EdgeSpec(int a, int b, String door, int lanes) {
        EdgeSpec(int a, int b, String door) {
            this(a, b, door, 1);
        }
    }

    /** Where a segment joins its neighbours: the nodes nearest its west and east ends, and its corridor's space. */
    private record Part(int west, int east, int space, int width) {
    }

    /** A side of a corridor 3.6 m wide lying from y = 0 to 3.6: what lies north or south of it, by distance from its wall. */
    private record Side(int base, int dir) {
        static final Side NORTH = new Side(CORRIDOR, 1);
        static final Side SOUTH = new Side(0, -1);

        int y(int d) {
            return base + dir * d;
        }
    }

    private static final class Layout {
        final SplittableRandom rnd;
        final List<int[]> paints = new ArrayList<>();
        final Set<Long> opens = new TreeSet<>();
        final List<AreaSpec> areas = new ArrayList<>();
        final List<DoorSpec> doors = new ArrayList<>();
        final List<NodeSpec> nodes = new ArrayList<>();
        final List<EdgeSpec> edges = new ArrayList<>();
        /** The nodes either side of a ward or wing door, where chairs wait for it: no place to park. */
        final Set<Integer> waiting = new TreeSet<>();
        final int hingedStart;
        int hinged;
        int spaces;
        int stores;
        int links;
        char letter = 'A';

        Layout(long seed) {
            rnd = new SplittableRandom(seed);
            hingedStart = rnd.nextInt(4);
        }

        int space() {
            return ++spaces;
        }

        void paint(int space, int x0, int y0, int x1, int y1) {
            paints.add(new int[] {Math.min(x0, x1), Math.min(y0, y1), Math.max(x0, x1), Math.max(y0, y1), space});
        }

        void open(int a, int b) {
            opens.add(key(a, b));
        }

        boolean isOpen(int a, int b) {
            return opens.contains(key(a, b));
        }

        private static long key(int a, int b) {
            return ((long) Math.min(a, b) << 32) | Math.max(a, b);
        }

        void area(String id, String kind, String name, String ward, int x0, int y0, int x1, int y1) {
            int ax = Math.min(x0, x1);
            int ay = Math.min(y0, y1);
            int bx = Math.max(x0, x1);
            int by = Math.max(y0, y1);
            areas.add(new AreaSpec(id, kind, name, ward, new int[] {ax, ay, bx, ay, bx, by, ax, by}));
        }

        void area(String id, String kind, String name, String ward, int[] outline) {
            areas.add(new AreaSpec(id, kind, name, ward, outline));
        }

        int node(int x, int y, String name, Role role, String group) {
            int id = nodes.size() + 1;
            nodes.add(new NodeSpec(id, x, y, name, role, group));
            return id;
        }

        void edge(int a, int b, String door) {
            edges.add(new EdgeSpec(a, b, door));
        }
    }

    private Layout layout() {
        Layout l = new Layout(layoutSeed);
        List<Part> parts = new ArrayList<>();
        int x = 0;
        int narrows = 0;
        for (int i = 0; i < segments.size(); i++) {
            int westLane = i > 0 ? lane(boundaries.get(i - 1)) : 0;
            int eastLane = i < boundaries.size() ? lane(boundaries.get(i)) : 0;
            Object s = segments.get(i);
            Part p;
            if (s instanceof Ward w) {
                char letter = l.letter++;
                p = w.ring ? ring(l, w, letter, x) : ward(l, w, letter, x, westLane, eastLane);
            } else {
                Link k = (Link) s;
                p = k.narrow ? narrow(l, k, x, ++narrows) : link(l, k, x, westLane, eastLane, i == 0, i == segments.size() - 1);
            }
            parts.add(p);
            x += p.width;
        }
        x = 0;
        for (int i = 0; i < boundaries.size(); i++) {
            Part a = parts.get(i);
            Part b = parts.get(i + 1);
            x += a.width;
            Boundary bd = boundaries.get(i);
            if (bd.kind == Entrance.OPEN) {
                l.open(a.space, b.space);
                l.edge(a.east, b.west, null);
                continue;
            }
            String id = wardDoorId(l, i);
            int[] south = {x, (CORRIDOR - WARD_DOOR) / 2};
            int[] north = {x, (CORRIDOR + WARD_DOOR) / 2};
            if (bd.kind == Entrance.SLIDING) {
                sliding(l, id, south, north, bd.pocket);
            } else {
                rotating(l, id, south, north);
            }
            l.edge(a.east, b.west, id);
            l.waiting.add(a.east);
            l.waiting.add(b.west);
        }
        return l;
    }

    private static int lane(Boundary b) {
        return b.kind == Entrance.ROTATING ? b.lane * LANE : 0;
    }

    /** "WA-E": the east door of ward A (a door between a ward and a link is the ward's). */
    private String wardDoorId(Layout l, int boundary) {
        char letter = 'A';
        for (int i = 0; i < segments.size(); i++) {
            if (i == boundary || i == boundary + 1) {
                if (segments.get(i) instanceof Ward) {
                    return "W" + letter + (i == boundary ? "-E" : "-W");
                }
            }
            if (segments.get(i) instanceof Ward) {
                letter++;
            }
            if (segments.get(i) instanceof Link k && k.wing != null) {
                letter++;
            }
        }
        throw new IllegalStateException("boundary " + boundary + " has no ward");
    }

    /** A plain ward: its corridor on the main line, a room north and south of each column. */
    private Part ward(Layout l, Ward w, char letter, int start, int westLane, int eastLane) {
        int n = w.columns;
        int x0 = start + (westLane != 0 ? VESTIBULE : 0);
        int end = x0 + n * ROOM_W + (eastLane != 0 ? VESTIBULE : 0);
        String lc = Character.toString(Character.toLowerCase(letter));
        String wardId = "ward-" + lc;
        int sc = l.space();
        l.paint(sc, start, 0, end, CORRIDOR);
        l.area(wardId, "ward", "Ward " + letter, null, start, -ROOM_D, end, CORRIDOR + ROOM_D);
        l.area("corridor-" + lc, "corridor", "Ward " + letter + " corridor", wardId, start, 0, end, CORRIDOR);
        int[][] number = numbers(w.missing, 2, n);
        // The rooms fill their rows, over the vestibules too: no empty ground between them.
        int[][] north = spans(number[0], start, end, x0, ROOM_W);
        int[][] south = spans(number[1], start, end, x0, ROOM_W);
        int first = 0;
        int prev = 0;
        for (int c = 0; c < n; c++) {
            int cx = x0 + c * ROOM_W + ROOM_W / 2;
            int id = l.node(cx, MID, "Ward " + letter + " corridor" + by(letter, number[0][c], number[1][c]),
                    Role.CORRIDOR, "ward " + letter);
            if (prev > 0) {
                l.edge(prev, id, null);
            } else {
                first = id;
            }
            prev = id;
            if (number[0][c] > 0) {
                room(l, letter, number[0][c], wardId, w.style, north[c][0], CORRIDOR, north[c][1], CORRIDOR + ROOM_D,
                        new int[] {cx - DOOR / 2, CORRIDOR}, new int[] {cx + DOOR / 2, CORRIDOR}, 0, 1, cx, CORRIDOR + ROOM_D / 2, id);
            }
            if (number[1][c] > 0) {
                room(l, letter, number[1][c], wardId, w.style, south[c][0], -ROOM_D, south[c][1], 0,
                        new int[] {cx - DOOR / 2, 0}, new int[] {cx + DOOR / 2, 0}, 0, -1, cx, -ROOM_D / 2, id);
            }
        }
        int west = first;
        int east = prev;
        String group = "ward " + letter;
        if (westLane != 0) {
            west = l.node(start + WAIT, MID + westLane, "Ward " + letter + ", west vestibule, in the revolving door's lane",
                    Role.CORRIDOR, group);
            l.edge(west, first, null);
        }
        if (eastLane != 0) {
            east = l.node(end - WAIT, MID + eastLane, "Ward " + letter + ", east vestibule, in the revolving door's lane",
                    Role.CORRIDOR, group);
            l.edge(prev, east, null);
        }
        return new Part(west, east, sc, end - start);
    }

    /**
     * Where the rooms of a row lie along it: slot c's room from [0] to [1], null where a room is
     * left out. A room left out is taken in by the room before it (after it, at the row's start),
     * and the first and last rooms reach the row's ends: the rooms fill the row.
     */
    private static int[][] spans(int[] numbers, int rowStart, int rowEnd, int slot0, int pitch) {
        int[][] out = new int[numbers.length][];
        int last = -1;
        for (int c = 0; c < numbers.length; c++) {
            if (numbers[c] > 0) {
                int lo = last < 0 ? rowStart : slot0 + c * pitch;
                if (last >= 0) {
                    out[last][1] = lo;
                }
                out[c] = new int[] {lo, 0};
                last = c;
            }
        }
        if (last >= 0) {
            out[last][1] = rowEnd;
        }
        return out;
    }

    /**
     * A ring ward: the main corridor is its south side; corridors up its west and east ends and
     * along its north side close the loop round two rows of rooms back to back, and rooms line
     * the outside of its north and south sides (the end ones reaching round the corners).
     */
    private Part ring(Layout l, Ward w, char letter, int x0) {
        int n = w.columns;
        int x1 = x0 + 2 * CORRIDOR + n * ROOM_W;
        int top = CORRIDOR + RING_INNER;
        String lc = Character.toString(Character.toLowerCase(letter));
        String wardId = "ward-" + lc;
        String ring = "Ward " + letter + " ring";
        int sc = l.space();
        l.paint(sc, x0, 0, x1, CORRIDOR);
        l.paint(sc, x0, CORRIDOR, x0 + CORRIDOR, top);
        l.paint(sc, x1 - CORRIDOR, CORRIDOR, x1, top);
        l.paint(sc, x0, top, x1, top + CORRIDOR);
        l.area(wardId, "ward", "Ward " + letter, null, x0, -ROOM_D, x1, top + CORRIDOR + ROOM_D);
        l.area("ring-" + lc + "-south", "corridor", ring + ", south", wardId, x0, 0, x1, CORRIDOR);
        l.area("ring-" + lc + "-west", "corridor", ring + ", west", wardId, x0, CORRIDOR, x0 + CORRIDOR, top);
        l.area("ring-" + lc + "-east", "corridor", ring + ", east", wardId, x1 - CORRIDOR, CORRIDOR, x1, top);
        l.area("ring-" + lc + "-north", "corridor", ring + ", north", wardId, x0, top, x1, top + CORRIDOR);
        // Rows of rooms: outside north, inside north, inside south, outside south.
        int[][] number = numbers(w.missing, 4, n);
        int slot0 = x0 + CORRIDOR;
        int[][][] span = {
            spans(number[0], x0, x1, slot0, ROOM_W), spans(number[1], slot0, x1 - CORRIDOR, slot0, ROOM_W),
            spans(number[2], slot0, x1 - CORRIDOR, slot0, ROOM_W), spans(number[3], x0, x1, slot0, ROOM_W)
        };
        int north = top + MID;
        int westX = x0 + MID;
        int eastX = x1 - MID;
        String group = "ward " + letter;
        int sw = l.node(westX, MID, ring + ", south-west corner", Role.CORRIDOR, group);
        int prev = sw;
        for (int c = 0; c < n; c++) {
            int cx = slot0 + c * ROOM_W + ROOM_W / 2;
            int id = l.node(cx, MID, ring + ", south" + by(letter, number[2][c], number[3][c]), Role.CORRIDOR, group);
            l.edge(prev, id, null);
            prev = id;
            if (number[2][c] > 0) {
                room(l, letter, number[2][c], wardId, w.style, span[2][c][0], CORRIDOR, span[2][c][1], CORRIDOR + ROOM_D,
                        new int[] {cx - DOOR / 2, CORRIDOR}, new int[] {cx + DOOR / 2, CORRIDOR}, 0, 1, cx, CORRIDOR + ROOM_D / 2, id);
            }
            if (number[3][c] > 0) {
                room(l, letter, number[3][c], wardId, w.style, span[3][c][0], -ROOM_D, span[3][c][1], 0,
                        new int[] {cx - DOOR / 2, 0}, new int[] {cx + DOOR / 2, 0}, 0, -1, cx, -ROOM_D / 2, id);
            }
        }
        int se = l.node(eastX, MID, ring + ", south-east corner", Role.CORRIDOR, group);
        l.edge(prev, se, null);
        prev = se;
        int step = (north - MID) / 3;
        for (int k = 1; k <= 2; k++) {
            int id = l.node(eastX, MID + k * step, ring + ", east side", Role.CORRIDOR, group);
            l.edge(prev, id, null);
            prev = id;
        }
        int ne = l.node(eastX, north, ring + ", north-east corner", Role.CORRIDOR, group);
        l.edge(prev, ne, null);
        prev = ne;
        for (int c = n - 1; c >= 0; c--) {
            int cx = slot0 + c * ROOM_W + ROOM_W / 2;
            int id = l.node(cx, north, ring + ", north" + by(letter, number[0][c], number[1][c]), Role.CORRIDOR, group);
            l.edge(prev, id, null);
            prev = id;
            if (number[0][c] > 0) {
                room(l, letter, number[0][c], wardId, w.style, span[0][c][0], top + CORRIDOR, span[0][c][1], top + CORRIDOR + ROOM_D,
                        new int[] {cx - DOOR / 2, top + CORRIDOR}, new int[] {cx + DOOR / 2, top + CORRIDOR}, 0, 1,
                        cx, top + CORRIDOR + ROOM_D / 2, id);
            }
            if (number[1][c] > 0) {
                room(l, letter, number[1][c], wardId, w.style, span[1][c][0], top - ROOM_D, span[1][c][1], top,
                        new int[] {cx - DOOR / 2, top}, new int[] {cx + DOOR / 2, top}, 0, -1, cx, top - ROOM_D / 2, id);
            }
        }
        int nw = l.node(westX, north, ring + ", north-west corner", Role.CORRIDOR, group);
        l.edge(prev, nw, null);
        prev = nw;
        for (int k = 2; k >= 1; k--) {
            int id = l.node(westX, MID + k * step, ring + ", west side", Role.CORRIDOR, group);
            l.edge(prev, id, null);
            prev = id;
        }
        l.edge(prev, sw, null);
        return new Part(sw, se, sc, x1 - x0);
    }

    /**
     * A link: a stretch of corridor, with its lobby and its wing if it has them; at an end of the
     * main corridor, a dead-end stub beyond its last node.
     */
    private Part link(Layout l, Link k, int start, int westLane, int eastLane, boolean westEnd, boolean eastEnd) {
        int length = k.length;
        int x0 = start + (westEnd ? STUB : 0);
        int width = length + (westEnd ? STUB : 0) + (eastEnd ? STUB : 0);
        int sc = l.space();
        l.paint(sc, start, 0, start + width, CORRIDOR);
        int number = ++l.links;
        String name = k.lobby ? "Entrance corridor" : "Link corridor " + number;
        String id = k.lobby ? "entrance" : "link-" + number;
        l.area(id, "corridor", name, null, start, 0, start + width, CORRIDOR);
        // The row of nodes along the link: one by each end, the wing's junction, more to keep edges short.
        List<int[]> row = new ArrayList<>();
        row.add(new int[] {x0 + WAIT, MID + westLane});
        int xc = x0 + length / 2;
        Side wingSide = k.wingNorth ? Side.NORTH : Side.SOUTH;
        if (k.wing != null) {
            boolean rotating = k.wing.entrance == Entrance.ROTATING;
            row.add(new int[] {rotating ? xc + LANE * k.wing.lane : xc, rotating ? wingSide.y(-WAIT) : MID});
        } else {
            int gap = length - 2 * WAIT;
            int steps = (gap + LINK_PITCH - 1) / LINK_PITCH;
            for (int s = 1; s < steps; s++) {
                row.add(new int[] {x0 + WAIT + gap * s / steps, MID});
            }
        }
        row.add(new int[] {x0 + length - WAIT, MID + eastLane});
        int[] ids = new int[row.size()];
        String group = "link " + number;
        for (int i = 0; i < row.size(); i++) {
            String what = i == 0 ? ", west end" : i == row.size() - 1 ? ", east end" : k.wing != null ? ", at the wing" : "";
            ids[i] = l.node(row.get(i)[0], row.get(i)[1], name + what, Role.LINK, group);
            if (i > 0) {
                l.edge(ids[i - 1], ids[i], null);
            }
        }
        int west = ids[0];
        int east = ids[ids.length - 1];
        if (westEnd) {
            west = l.node(start + STUB / 2, MID, name + ", dead end", Role.DEAD_END, group);
            l.edge(west, ids[0], null);
        }
        if (eastEnd) {
            east = l.node(start + width - STUB / 2, MID, name + ", dead end", Role.DEAD_END, group);
            l.edge(ids[ids.length - 1], east, null);
        }
        if (k.lobby) {
            lobby(l, k.lobbyNorth ? Side.NORTH : Side.SOUTH, x0, length, row, ids, sc);
        }
        if (k.wing != null) {
            wing(l, k.wing, wingSide, x0, length, ids[1], sc);
        }
        return new Part(west, east, sc, width);
    }

    /** The lobby: a hall open to its link, a grid of nodes, and store rooms behind it whose doors swing out into it. */
    private void lobby(Layout l, Side side, int x0, int length, List<int[]> row, int[] rowIds, int linkSpace) {
        int depth = LOBBY_FIRST + LOBBY_PITCH * (lobbyRows - 1) + LOBBY_LAST;
        int sh = l.space();
        l.paint(sh, x0, side.y(0), x0 + length, side.y(depth));
        l.open(linkSpace, sh);
        l.area("lobby", "hall", "Lobby", null, x0, side.y(0), x0 + length, side.y(depth));
        int cols = row.size();
        int[][] ids = new int[lobbyRows][cols];
        for (int r = 0; r < lobbyRows; r++) {
            for (int c = 0; c < cols; c++) {
                ids[r][c] = l.node(row.get(c)[0], side.y(LOBBY_FIRST + r * LOBBY_PITCH), "Lobby, row " + (r + 1) + ", place " + (c + 1),
                        Role.HALL, "lobby");
                // A depot joins the corridor at its middle column only: one exit for every chair parked in it.
                if (r > 0 || !shape.depot() || c == cols / 2) {
                    l.edge(r == 0 ? rowIds[c] : ids[r - 1][c], ids[r][c], null);
                }
                if (c > 0) {
                    l.edge(ids[r][c - 1], ids[r][c], null);
                }
            }
        }
        int first = l.rnd.nextInt(cols);
        List<Integer> stores = new ArrayList<>(List.of(first));
        if (cols >= 3 && lobbyRows > 1 && l.rnd.nextBoolean()) {
            int other = first + 2 < cols ? first + 2 : first - 2;
            if (other >= 0) {
                stores.add(other);
            }
        }
        stores.sort(null);
        for (int c : stores) {
            int n = ++l.stores;
            int cx = row.get(c)[0];
            int ss = l.space();
            l.paint(ss, cx - STORE_W / 2, side.y(depth), cx + STORE_W / 2, side.y(depth + STORE_D));
            l.area("store-" + n, "room", "Store room " + n, null, cx - STORE_W / 2, side.y(depth), cx + STORE_W / 2, side.y(depth + STORE_D));
            String door = "S" + n;
            hinged(l, door, new int[] {cx - DOOR / 2, side.y(depth)}, new int[] {cx + DOOR / 2, side.y(depth)}, 0, -side.dir);
            int id = l.node(cx, side.y(depth + STORE_D / 2), "Store room " + n, Role.ROOM, "lobby");
            l.edge(ids[lobbyRows - 1][c], id, door);
        }
    }

    /** A dead-end wing off a link: a corridor with rooms both sides, a wall at its end, maybe a door at its entrance. */
    private void wing(Layout l, Wing w, Side side, int x0, int length, int junction, int linkSpace) {
        char letter = l.letter++;
        String lc = Character.toString(Character.toLowerCase(letter));
        String wardId = "ward-" + lc;
        int xc = x0 + length / 2;
        int half = CORRIDOR / 2;
        // Behind a revolving entrance, a vestibule: the node in its lane stands away from the rooms' doors.
        int vestibule = w.entrance == Entrance.ROTATING ? VESTIBULE : 0;
        int end = vestibule + w.pairs * WING_ROOM + WING_TAIL;
        int sw = l.space();
        l.paint(sw, xc - half, side.y(0), xc + half, side.y(end));
        int rooms = vestibule + w.pairs * WING_ROOM;
        // The ward is its rooms and its corridor, whose tail runs on alone to the end wall: a T.
        l.area(wardId, "ward", "Ward " + letter + " (wing)", null, new int[] {
            x0, side.y(0), x0 + length, side.y(0), x0 + length, side.y(rooms), xc + half, side.y(rooms),
            xc + half, side.y(end), xc - half, side.y(end), xc - half, side.y(rooms), x0, side.y(rooms)});
        l.area("corridor-" + lc, "corridor", "Ward " + letter + " wing corridor", wardId, xc - half, side.y(0), xc + half, side.y(end));
        int[][] number = numbers(w.missing, 2, w.pairs);
        // The rooms fill both sides, over the vestibule too.
        int[][] westRooms = spans(number[0], 0, rooms, vestibule, WING_ROOM);
        int[][] eastRooms = spans(number[1], 0, rooms, vestibule, WING_ROOM);
        String group = "wing " + letter;
        String entrance = null;
        int laneX = xc;
        if (w.entrance == Entrance.OPEN) {
            l.open(linkSpace, sw);
        } else {
            entrance = "W" + letter;
            int[] a = {xc - WARD_DOOR / 2, side.base()};
            int[] b = {xc + WARD_DOOR / 2, side.base()};
            if (w.entrance == Entrance.SLIDING) {
                sliding(l, entrance, a, b, -1);
            } else {
                rotating(l, entrance, a, b);
                laneX = xc + LANE * w.lane;
            }
        }
        int prev = junction;
        if (vestibule > 0) {
            int id = l.node(laneX, side.y(WAIT), "Ward " + letter + " wing, vestibule, in the revolving door's lane", Role.CORRIDOR, group);
            l.edge(prev, id, entrance);
            l.waiting.add(prev);
            l.waiting.add(id);
            prev = id;
        }
        for (int j = 0; j < w.pairs; j++) {
            int d = vestibule + WING_ROOM * j + WING_ROOM / 2;
            int id = l.node(xc, side.y(d), "Ward " + letter + " wing corridor" + by(letter, number[0][j], number[1][j]),
                    Role.CORRIDOR, group);
            l.edge(prev, id, j == 0 && vestibule == 0 ? entrance : null);
            if (j == 0 && vestibule == 0 && entrance != null) {
                l.waiting.add(prev);
                l.waiting.add(id);
            }
            prev = id;
            int doorLo = side.y(d - DOOR / 2);
            int doorHi = side.y(d + DOOR / 2);
            if (number[0][j] > 0) {
                room(l, letter, number[0][j], wardId, w.style, x0, side.y(westRooms[j][0]), xc - half, side.y(westRooms[j][1]),
                        new int[] {xc - half, doorLo}, new int[] {xc - half, doorHi}, -1, 0, x0 + WING_ROOM / 2, side.y(d), id);
            }
            if (number[1][j] > 0) {
                room(l, letter, number[1][j], wardId, w.style, xc + half, side.y(eastRooms[j][0]), x0 + length, side.y(eastRooms[j][1]),
                        new int[] {xc + half, doorLo}, new int[] {xc + half, doorHi}, 1, 0, x0 + length - WING_ROOM / 2, side.y(d), id);
            }
        }
        int id = l.node(xc, side.y(end - WING_TAIL / 2), "Ward " + letter + " wing, dead end", Role.DEAD_END, group);
        l.edge(prev, id, null);
    }

    /** The bottleneck: a corridor 2 m wide, open at both ends, nothing on either side. */
    private Part narrow(Layout l, Link k, int x0, int count) {
        int sn = l.space();
        l.paint(sn, x0, NARROW_LO, x0 + k.length, NARROW_HI);
        l.area(count == 1 ? "bottleneck" : "bottleneck-" + count, "corridor", "Bottleneck corridor", null,
                x0, NARROW_LO, x0 + k.length, NARROW_HI);
        int gap = k.length - 2 * NARROW_END;
        int steps = (gap + NARROW_PITCH - 1) / NARROW_PITCH;
        int first = 0;
        int prev = 0;
        for (int s = 0; s <= steps; s++) {
            int id = l.node(x0 + NARROW_END + gap * s / steps, MID, "Bottleneck corridor, " + (s + 1) + " of " + (steps + 1),
                    Role.NARROW, "bottleneck");
            if (prev > 0) {
                l.edge(prev, id, null);
            } else {
                first = id;
            }
            prev = id;
        }
        return new Part(first, prev, sn, k.length);
    }

    /** Room numbers by row and column, 0 where the room is left out, counted row by row. */
    private static int[][] numbers(Set<Integer> missing, int rows, int cols) {
        int[][] number = new int[rows][cols];
        int k = 0;
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                number[r][c] = missing.contains(r * 100 + c) ? 0 : ++k;
            }
        }
        return number;
    }

    private static String by(char letter, int a, int b) {
        if (a > 0 && b > 0) {
            return ", by rooms " + letter + a + " and " + letter + b;
        }
        if (a > 0 || b > 0) {
            return ", by room " + letter + Math.max(a, b);
        }
        return "";
    }

    /**
     * A patient's room: its rectangle, its 1.2 m door in the wall it shares with the corridor
     * (hinged, swinging into the room, or sliding), its node in the middle, joined to the
     * corridor node through the door.
     */
    private void room(Layout l, char letter, int number, String wardId, Style style, int x0, int y0, int x1, int y1,
                      int[] jambA, int[] jambB, int intoX, int intoY, int nodeX, int nodeY, int corridorNode) {
        String id = Character.toString(letter) + number;
        int space = l.space();
        l.paint(space, x0, y0, x1, y1);
        l.area(id.toLowerCase(java.util.Locale.ROOT), "room", "Room " + id, wardId, x0, y0, x1, y1);
        boolean hinged = style == Style.HINGED || style == Style.MIXED && l.rnd.nextBoolean();
        if (hinged) {
            hinged(l, id, jambA, jambB, intoX, intoY);
        } else {
            sliding(l, id, jambA, jambB, -1);
        }
        int node = l.node(nodeX, nodeY, "Room " + id, Role.ROOM, "rooms");
        l.edge(corridorNode, node, id);
    }

    /**
     * A hinged door swinging toward (sx, sy). Successive hinged doors take the four ways of writing
     * one in turn (swinging left or right of the line from its first jamb to its second, the hinge
     * at either), so that every map has both hinges and both swings once it has four.
     */
    private static void hinged(Layout l, String id, int[] a, int[] b, int sx, int sy) {
        int combo = (l.hingedStart + l.hinged++) & 3;
        boolean left = (combo & 1) == 0;
        // From a to b, the side (sx, sy) is on the left if it is on the left of a->b: else write b first.
        boolean leftOfAb = -(b[1] - a[1]) * sx + (b[0] - a[0]) * sy > 0;
        int[] from = leftOfAb == left ? a : b;
        int[] to = from == a ? b : a;
        l.doors.add(new DoorSpec(id, "hinged", from[0], from[1], to[0], to[1], (combo & 2) == 0 ? "from" : "to",
                left ? "left" : "right"));
    }

    /** A sliding door whose leaf runs past jamb {@code pocket} (0: a, 1: b, -1: either) into the wall. */
    private static void sliding(Layout l, String id, int[] a, int[] b, int pocket) {
        boolean flip = l.rnd.nextBoolean();
        int p = pocket < 0 ? l.rnd.nextInt(2) : pocket;
        int[] from = flip ? b : a;
        int[] to = flip ? a : b;
        boolean pocketAtFrom = (p == 0) != flip;
        l.doors.add(new DoorSpec(id, "sliding", from[0], from[1], to[0], to[1], pocketAtFrom ? "from" : "to", null));
    }

    private static void rotating(Layout l, String id, int[] a, int[] b) {
        boolean flip = l.rnd.nextBoolean();
        l.doors.add(new DoorSpec(id, "rotating", flip ? b[0] : a[0], flip ? b[1] : a[1], flip ? a[0] : b[0], flip ? a[1] : b[1], null, null));
    }

    // ---- walls: wherever two different spaces meet, except in the doors' openings ---------------

    /**
     * The walls, as {x0, y0, x1, y1, thickness in centimetres}: the rectangles are painted on a
     * grid of their own coordinates, and a wall runs wherever two cells of different spaces (or a
     * space and the outside) meet, unless the two are open to each other or a door's opening is
     * there. Straight runs of the same thickness are one wall; a wall to the outside is 0.25 m thick.
     */
    private static List<int[]> walls(Layout l) {
        TreeSet<Integer> xset = new TreeSet<>();
        TreeSet<Integer> yset = new TreeSet<>();
        for (int[] p : l.paints) {
            xset.add(p[0]);
            xset.add(p[2]);
            yset.add(p[1]);
            yset.add(p[3]);
        }
        for (DoorSpec d : l.doors) {
            xset.add(d.fx);
            xset.add(d.tx);
            yset.add(d.fy);
            yset.add(d.ty);
        }
        int[] xs = xset.stream().mapToInt(Integer::intValue).toArray();
        int[] ys = yset.stream().mapToInt(Integer::intValue).toArray();
        int[][] cell = new int[xs.length + 1][ys.length + 1];
        for (int[] p : l.paints) {
            for (int i = Arrays.binarySearch(xs, p[0]); i < Arrays.binarySearch(xs, p[2]); i++) {
                for (int j = Arrays.binarySearch(ys, p[1]); j < Arrays.binarySearch(ys, p[3]); j++) {
                    cell[i + 1][j + 1] = p[4];
                }
            }
        }
        // Openings: vertical ones by (line index, cell row), horizontal by (line index, cell column).
        Set<Long> gapsV = new TreeSet<>();
        Set<Long> gapsH = new TreeSet<>();
        for (DoorSpec d : l.doors) {
            if (d.fx == d.tx) {
                int i = Arrays.binarySearch(xs, d.fx);
                for (int j = Arrays.binarySearch(ys, Math.min(d.fy, d.ty)); j < Arrays.binarySearch(ys, Math.max(d.fy, d.ty)); j++) {
                    requireBoundary(l, d, cell[i][j + 1], cell[i + 1][j + 1]);
                    gapsV.add((long) i << 32 | j);
                }
            } else {
                int j = Arrays.binarySearch(ys, d.fy);
                for (int i = Arrays.binarySearch(xs, Math.min(d.fx, d.tx)); i < Arrays.binarySearch(xs, Math.max(d.fx, d.tx)); i++) {
                    requireBoundary(l, d, cell[i + 1][j], cell[i + 1][j + 1]);
                    gapsH.add((long) j << 32 | i);
                }
            }
        }
        List<int[]> walls = new ArrayList<>();
        for (int j = 0; j < ys.length; j++) {
            int start = -1;
            int thick = 0;
            for (int i = 0; i <= xs.length - 1; i++) {
                int t = i < xs.length - 1 && !gapsH.contains((long) j << 32 | i) ? thickness(l, cell[i + 1][j], cell[i + 1][j + 1]) : 0;
                if (t != thick) {
                    if (thick > 0) {
                        walls.add(new int[] {xs[start], ys[j], xs[i], ys[j], thick});
                    }
                    start = i;
                    thick = t;
                }
            }
        }
        for (int i = 0; i < xs.length; i++) {
            int start = -1;
            int thick = 0;
            for (int j = 0; j <= ys.length - 1; j++) {
                int t = j < ys.length - 1 && !gapsV.contains((long) i << 32 | j) ? thickness(l, cell[i][j + 1], cell[i + 1][j + 1]) : 0;
                if (t != thick) {
                    if (thick > 0) {
                        walls.add(new int[] {xs[i], ys[start], xs[i], ys[j], thick});
                    }
                    start = j;
                    thick = t;
                }
            }
        }
        return walls;
    }

    /** 0 where no wall runs between two cells, else its thickness in centimetres. */
    private static int thickness(Layout l, int a, int b) {
        if (a == b || l.isOpen(a, b)) {
            return 0;
        }
        return a == 0 || b == 0 ? 25 : 15;
    }

    private static void requireBoundary(Layout l, DoorSpec d, int a, int b) {
        if (a == b || a == 0 || b == 0 || l.isOpen(a, b)) {
            throw new IllegalStateException("door " + d.id + " is not between two spaces (" + a + ", " + b + ")");
        }
    }

    // ---- parking -------------------------------------------------------------------------------

    /**
     * The parking places: the lobby's nodes, then the corridors' dead ends, then corridor and link
     * nodes taken from each part of the hospital in turn; never a room, never the bottleneck,
     * never where chairs wait for a ward door.
     */
    private List<Integer> parking(Layout l) {
        List<Integer> out = new ArrayList<>();
        Map<String, List<Integer>> groups = new LinkedHashMap<>();
        for (NodeSpec n : l.nodes) {
            if (n.role == Role.HALL) {
                out.add(n.id);
            }
        }
        for (NodeSpec n : l.nodes) {
            if (n.role == Role.DEAD_END) {
                out.add(n.id);
            }
        }
        for (NodeSpec n : l.nodes) {
            if ((n.role == Role.CORRIDOR || n.role == Role.LINK) && !l.waiting.contains(n.id)) {
                groups.computeIfAbsent(n.group, g -> new ArrayList<>()).add(n.id);
            }
        }
        Set<Integer> taken = new LinkedHashSet<>(out);
        for (int round = 0; taken.size() < shape.parking(); round++) {
            boolean any = false;
            for (List<Integer> g : groups.values()) {
                // Every other node first, so that neighbouring places are not both taken early.
                int k = round * 2 < g.size() ? round * 2 : 2 * (round - (g.size() + 1) / 2) + 1;
                if (k >= 0 && k < g.size()) {
                    any = true;
                    if (taken.size() < shape.parking()) {
                        taken.add(g.get(k));
                    }
                }
            }
            if (!any) {
                throw new IllegalArgumentException("shape " + shape.name() + " asks for " + shape.parking()
                        + " parking places; the map has " + taken.size() + " corridor and hall nodes to spare (seed " + seed + ")");
            }
        }
        return new ArrayList<>(taken).subList(0, shape.parking());
    }

    // ---- JSON ----------------------------------------------------------------------------------

    private String json(Layout l, List<int[]> walls, List<Integer> parking) {
        StringBuilder b = new StringBuilder(64 * 1024);
        b.append("{\n");
        b.append("  \"format\": \"concord-hospital-map/1\",\n");
        b.append("  \"name\": ").append(quote(name(l))).append(",\n");
        b.append("  \"clearance\": 0.4,\n");
        b.append("  \"wallThickness\": 0.15,\n");
        b.append("  \"walls\": [\n");
        for (int i = 0; i < walls.size(); i++) {
            int[] w = walls.get(i);
            b.append("    {\"id\": \"w").append(i + 1).append("\", \"from\": ").append(pt(w[0], w[1])).append(", \"to\": ")
                    .append(pt(w[2], w[3]));
            if (w[4] != 15) {
                b.append(", \"thickness\": ").append(w[4] / 100.0);
            }
            b.append('}').append(i + 1 < walls.size() ? ",\n" : "\n");
        }
        b.append("  ],\n");
        b.append("  \"areas\": [\n");
        for (int i = 0; i < l.areas.size(); i++) {
            AreaSpec a = l.areas.get(i);
            b.append("    {\"id\": ").append(quote(a.id)).append(", \"kind\": ").append(quote(a.kind)).append(", \"name\": ")
                    .append(quote(a.name));
            if (a.ward != null) {
                b.append(", \"ward\": ").append(quote(a.ward));
            }
            b.append(", \"polygon\": [");
            for (int k = 0; k < a.outline.length; k += 2) {
                b.append(k > 0 ? ", " : "").append(pt(a.outline[k], a.outline[k + 1]));
            }
            b.append("]}");
            b.append(i + 1 < l.areas.size() ? ",\n" : "\n");
        }
        b.append("  ],\n");
        b.append("  \"doors\": [\n");
        for (int i = 0; i < l.doors.size(); i++) {
            DoorSpec d = l.doors.get(i);
            b.append("    {\"id\": ").append(quote(d.id)).append(", \"kind\": ").append(quote(d.kind)).append(", \"from\": ")
                    .append(pt(d.fx, d.fy)).append(", \"to\": ").append(pt(d.tx, d.ty));
            if (d.hinge != null) {
                b.append(", \"hinge\": ").append(quote(d.hinge));
            }
            if (d.swing != null) {
                b.append(", \"swing\": ").append(quote(d.swing));
            }
            b.append('}').append(i + 1 < l.doors.size() ? ",\n" : "\n");
        }
        b.append("  ],\n");
        b.append("  \"nodes\": [\n");
        for (int i = 0; i < l.nodes.size(); i++) {
            NodeSpec n = l.nodes.get(i);
            b.append("    {\"id\": ").append(n.id).append(", \"at\": ").append(pt(n.x, n.y)).append(", \"name\": ")
                    .append(quote(n.name)).append('}').append(i + 1 < l.nodes.size() ? ",\n" : "\n");
        }
        b.append("  ],\n");
        b.append("  \"edges\": [\n");
        for (int i = 0; i < l.edges.size(); i++) {
            EdgeSpec e = l.edges.get(i);
            b.append("    {\"from\": ").append(e.a).append(", \"to\": ").append(e.b);
            if (e.door != null) {
                b.append(", \"door\": ").append(quote(e.door));
            }
            if (e.lanes == 2) {
                b.append(", \"lanes\": 2");
            }
            b.append('}').append(i + 1 < l.edges.size() ? ",\n" : "\n");
        }
        b.append("  ],\n");
        b.append("  \"parking\": [");
        for (int i = 0; i < parking.size(); i++) {
            b.append(i > 0 ? ", " : "").append(parking.get(i));
        }
        b.append("]\n}\n");
        return b.toString();
    }

    private String name(Layout l) {
        int wards = 0;
        boolean ring = false;
        for (Object s : segments) {
            if (s instanceof Ward w) {
                wards++;
                ring |= w.ring;
            }
        }
        return "Generated " + shape.name() + " hospital, seed " + seed + ": " + (wards + wings.size()) + " wards"
                + (ring ? ", a ring" : "") + (wings.isEmpty() ? "" : ", " + wings.size() + (wings.size() == 1 ? " wing" : " wings"))
                + (shape.bottleneck() ? ", a bottleneck" : "") + ", " + l.nodes.size() + " nodes";
    }

    /** A point in decimetres written in metres: 36 is 3.6, 120 is 12, -5 is -0.5. */
    private static String pt(int x, int y) {
        return "[" + metres(x) + ", " + metres(y) + "]";
    }

    private static String metres(int dm) {
        String sign = dm < 0 ? "-" : "";
        int a = Math.abs(dm);
        return sign + (a / 10) + (a % 10 == 0 ? "" : "." + (a % 10));
    }

    private static String quote(String s) {
        StringBuilder b = new StringBuilder("\"");
        for (char c : s.toCharArray()) {
            if (c == '"' || c == '\\') {
                b.append('\\');
            }
            b.append(c);
        }
        return b.append('"').toString();
    }
}
