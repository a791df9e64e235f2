package io.concord.sim.maps;

import io.concord.agents.map.Area;
import io.concord.agents.map.Door;
import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.MapException;
import io.concord.agents.map.Node;
import io.concord.agents.map.Point;
import io.concord.sim.render.HospitalPicture;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.WorldDoor;

import org.junit.jupiter.api.Test;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Generated hospitals, seed after seed: each is read by the map reader without a problem, has the
 * shape it was asked for (node count, wards, ring or not, wings, bottleneck, parking places,
 * every kind of door), can be driven (no {@link io.concord.agents.map.HospitalMap#warnings() warnings}), and is the same for the same
 * seed. {@code -Dconcord.maps.seeds=N} checks N seeds a preset (200 by default),
 * {@code -Dconcord.maps.first=S} starts at seed S.
 */
class MapGeneratorTest {
    private static final long FIRST = Long.getLong("concord.maps.first", 1);
    private static final int SEEDS = Integer.getInteger("concord.maps.seeds", 200);

    @Test
    void smallMapsHaveTheirShape() {
        everySeed(Shape.small());
    }

    @Test
    void mediumMapsHaveTheirShape() {
        everySeed(Shape.medium());
    }

    @Test
    void largeMapsHaveTheirShape() {
        everySeed(Shape.large());
    }

    @Test
    void otherShapesToo() {
        for (Shape s : List.of(Shape.small().withRing(true), Shape.large().withRing(false), Shape.medium().withNodes(90),
                new Shape("one ward", 30, 1, false, 1, true, 8), new Shape("one ring", 40, 1, true, 0, false, 10),
                new Shape("wide", 80, 4, true, 0, false, 20))) {
            everySeed(s, Math.max(1, SEEDS / 10));
        }
    }

    /** A depot (issue 47): the lobby, whose places are the first parking places, joins the corridor at one node; the map keeps every rule. */
    @Test
    void depotMapsHaveTheirShapeAndOneExit() {
        for (Shape s : List.of(Shape.small().withDepot(), Shape.medium().withDepot(), Shape.large().withDepot())) {
            everySeed(s, Math.max(1, SEEDS / 10));
            for (long seed = FIRST; seed < FIRST + Math.max(1, SEEDS / 10); seed++) {
                HospitalMap map = MapGenerator.map(seed, s);
                long exits = map.nodes().stream().filter(n -> "lobby".equals(n.area()))
                        .flatMap(n -> map.edgesAt(n.id()).stream().map(e -> map.node(e.other(n.id()))))
                        .filter(o -> !"lobby".equals(o.area()) && !o.area().startsWith("store")).count();
                assertEquals(1, exits, s.name() + " seed " + seed + ": one way out of the lobby");
                assertTrue("lobby".equals(map.node(map.parking().get(0)).area()), "the first parking place is in the depot");
            }
        }
    }

    /** A single-lane hospital (issue 47): every edge one lane, the same layout otherwise; the map keeps every rule. */
    @Test
    void oneLaneMapsHaveNoEdgeOfTwoLanes() {
        for (Shape s : List.of(Shape.medium().withOneLane(), Shape.medium().withDepot().withOneLane())) {
            everySeed(s, Math.max(1, SEEDS / 10));
            HospitalMap one = MapGenerator.map(FIRST, s);
            assertTrue(one.edges().stream().noneMatch(io.concord.agents.map.Edge::twoLanes), s.name() + ": an edge of two lanes");
            assertEquals(one.nodes().size(), MapGenerator.map(FIRST, s.name().contains("depot") ? Shape.medium().withDepot() : Shape.medium()).nodes().size(),
                    "the same layout as the shape with lanes");
        }
        assertTrue(MapGenerator.map(FIRST, Shape.medium()).edges().stream().anyMatch(io.concord.agents.map.Edge::twoLanes),
                "the shape with lanes has two-lane corridors (else this test shows nothing)");
    }

    @Test
    void theSameSeedGivesTheSameTextAndOtherSeedsOtherMaps() {
        for (Shape s : List.of(Shape.small(), Shape.medium(), Shape.large())) {
            Set<String> seen = new HashSet<>();
            for (long seed = FIRST; seed < FIRST + SEEDS; seed++) {
                String json = MapGenerator.generate(seed, s);
                assertEquals(json, MapGenerator.generate(seed, s), s.name() + " seed " + seed + " twice");
                assertTrue(seen.add(json), s.name() + " seed " + seed + " gave the same map as an earlier seed");
            }
        }
        assertNotEquals(MapGenerator.generate(1, Shape.small()), MapGenerator.generate(1, Shape.medium()));
    }

    @Test
    void aShapeThatCannotBeBuiltIsRefusedSayingWhy() {
        var e = assertThrows(IllegalArgumentException.class,
                () -> MapGenerator.generate(1, new Shape("crowded", 24, 6, true, 3, true, 8)));
        assertTrue(e.getMessage().contains("crowded") && e.getMessage().contains("24 nodes"), e.getMessage());
        var p = assertThrows(IllegalArgumentException.class, () -> new Shape("p", 30, 2, false, 0, true, 11));
        assertTrue(p.getMessage().contains("parking"), p.getMessage());
    }

    /**
     * A chair on every node, each turning on the spot, every door opening: nothing touches. The
     * physical form of the drivability rules (nodes clear of walls, of each other and of the
     * leaves), in the simulation the fleet runs in.
     */
    @Test
    void chairsTurningOnEveryNodeWhileEveryDoorOpensTouchNothing() {
        for (Shape s : List.of(Shape.small(), Shape.medium(), Shape.large())) {
            HospitalMap map = MapGenerator.map(3, s);
            HospitalWorld world = HospitalWorld.builder(map).seed(3).build();
            for (Node n : map.nodes()) {
                world.addChair("c" + n.id(), ChairConfig.standard().noiseless(), world.poseAt(n.id(), 37 * n.id()))
                        .drive(n.id() % 2 == 0 ? 40 : -40, n.id() % 2 == 0 ? -40 : 40);
            }
            for (WorldDoor d : world.doors()) {
                d.open();
            }
            world.run(6);
            assertEquals(List.of(), world.collisions(), s.name() + ": " + map);
            for (WorldDoor d : world.doors()) {
                assertTrue(d.isOpen(), s.name() + ": " + d);
            }
        }
    }

    @Test
    void picturesOfOneMapOfEachPreset() throws Exception {
        for (Shape s : List.of(Shape.small(), Shape.medium(), Shape.large())) {
            Path png = Path.of("target", "pictures", "generated-" + s.name() + ".png");
            HospitalPicture.write(MapGenerator.map(1, s), png);
            BufferedImage img = ImageIO.read(png.toFile());
            assertTrue(img.getWidth() > 800 && img.getHeight() > 400, s.name() + ": " + img.getWidth() + "x" + img.getHeight());
        }
    }

    // ---- what every map of a shape is checked for -----------------------------------------------

    private static void everySeed(Shape shape) {
        everySeed(shape, SEEDS);
    }

    private static void everySeed(Shape shape, int seeds) {
        List<String> failures = new ArrayList<>();
        for (long seed = FIRST; seed < FIRST + seeds && failures.size() < 20; seed++) {
            String json = MapGenerator.generate(seed, shape);
            HospitalMap map;
            try {
                map = HospitalMap.parse(json, MapGenerator.source(seed, shape));
            } catch (MapException e) {
                failures.add(e.getMessage());
                continue;
            }
            for (String p : shapeProblems(map, shape)) {
                failures.add(shape.name() + " seed " + seed + ": " + p);
            }
            for (String p : map.warnings()) {
                failures.add(shape.name() + " seed " + seed + ": " + p);
            }
        }
        assertEquals(List.of(), failures, shape.name() + ": " + failures.size() + " problems in seeds " + FIRST + " to "
                + (FIRST + seeds - 1));
    }

    /** What the map lacks of the shape asked for. */
    static List<String> shapeProblems(HospitalMap map, Shape shape) {
        List<String> out = new ArrayList<>();
        int n = map.nodes().size();
        if (Math.abs(n - shape.nodes()) > MapGenerator.NODE_TOLERANCE * shape.nodes()) {
            out.add(n + " nodes, asked for " + shape.nodes());
        }
        if (map.parking().size() != shape.parking()) {
            out.add(map.parking().size() + " parking places, asked for " + shape.parking());
        }
        long wards = map.areas().stream().filter(a -> a.kind() == Area.Kind.WARD).count();
        if (wards != shape.wards() + shape.wings()) {
            out.add(wards + " wards, asked for " + shape.wards() + " and " + shape.wings() + " wings");
        }
        if (map.areas().stream().noneMatch(a -> a.kind() == Area.Kind.HALL)) {
            out.add("no hall (lobby)");
        }
        // Doors: every kind; hinged doors with both hinges and both swings.
        Set<Door.Kind> kinds = EnumSet.noneOf(Door.Kind.class);
        Set<String> hinged = new TreeSet<>();
        for (Door d : map.doors()) {
            kinds.add(d.kind());
            if (d.kind() == Door.Kind.HINGED) {
                hinged.add(d.hinge().toString());
                hinged.add(d.swing().toString());
            }
        }
        // A revolving door stands at a wing's entrance or where a plain ward meets a link: a lone ring
        // without wings, or a lone ward behind the bottleneck, has no place for one.
        boolean revolvingFits = shape.wings() > 0 || shape.wards() > (shape.ring() ? 1 : 0) && !(shape.wards() == 1 && shape.bottleneck());
        if (kinds.size() != 3 && revolvingFits) {
            out.add("door kinds " + kinds + ", not all three");
        }
        if (!hinged.equals(Set.of("FROM", "TO", "LEFT", "RIGHT"))) {
            out.add("hinged doors only with " + hinged);
        }
        Map<Integer, List<Integer>> next = neighbours(map);
        Set<Integer> rooms = new HashSet<>(map.roomNodes());
        // Dead ends: rooms with one way in; corridors a chair must turn round at the end of.
        if (rooms.stream().noneMatch(r -> next.get(r).size() == 1)) {
            out.add("no dead-end room");
        }
        boolean corridorEnd = false;
        boolean wingEnd = false;
        for (Node node : map.nodes()) {
            if (!rooms.contains(node.id()) && next.get(node.id()).stream().filter(x -> !rooms.contains(x)).count() == 1) {
                corridorEnd = true;
                wingEnd |= next.get(node.id()).size() == 1 && kind(map, node) == Area.Kind.CORRIDOR;
            }
        }
        if (!corridorEnd) {
            out.add("no dead-end corridor");
        }
        if (shape.wings() > 0 && !wingEnd) {
            out.add("no corridor ending in a wall with a node at its end (a wing's)");
        }
        // A ring: the corridor nodes have a loop, round at least eight of them; without one, none.
        Set<Integer> loop = loopOfCorridors(map, next);
        if (shape.ring() && loop.size() < 8) {
            out.add("no ring: the corridors' loop has " + loop.size() + " nodes");
        }
        if (!shape.ring() && !loop.isEmpty()) {
            out.add("a loop of corridors " + loop + " where the shape has no ring");
        }
        if (shape.bottleneck()) {
            String b = bottleneck(map, next);
            if (b != null) {
                out.add(b);
            }
        }
        // Parking places: corridor or hall nodes, none where a room is.
        for (int p : map.parking()) {
            Area.Kind k = kind(map, map.node(p));
            if (k != Area.Kind.CORRIDOR && k != Area.Kind.HALL) {
                out.add("parking node " + p + " is in a " + k);
            }
        }
        return out;
    }

    private static Area.Kind kind(HospitalMap map, Node n) {
        return n.area() == null ? null : map.area(n.area()).kind();
    }

    static Map<Integer, List<Integer>> neighbours(HospitalMap map) {
        Map<Integer, List<Integer>> next = new HashMap<>();
        for (Node n : map.nodes()) {
            next.put(n.id(), new ArrayList<>());
        }
        for (Edge e : map.edges()) {
            next.get(e.a()).add(e.b());
            next.get(e.b()).add(e.a());
        }
        return next;
    }

    /** The corridor nodes left when those with fewer than two corridor neighbours are peeled off, again and again. */
    private static Set<Integer> loopOfCorridors(HospitalMap map, Map<Integer, List<Integer>> next) {
        Set<Integer> core = new HashSet<>();
        for (Node n : map.nodes()) {
            if (kind(map, n) == Area.Kind.CORRIDOR) {
                core.add(n.id());
            }
        }
        boolean peeled = true;
        while (peeled) {
            peeled = false;
            for (int id : new ArrayList<>(core)) {
                if (next.get(id).stream().filter(core::contains).count() < 2) {
                    core.remove(id);
                    peeled = true;
                }
            }
        }
        return new TreeSet<>(core);
    }

    /** Null if a corridor at most 2.2 m wide is the only way between two parts, each a fifth of the map or more. */
    private static String bottleneck(HospitalMap map, Map<Integer, List<Integer>> next) {
        for (Area a : map.areas()) {
            if (a.kind() != Area.Kind.CORRIDOR) {
                continue;
            }
            double minX = Double.MAX_VALUE;
            double maxX = -Double.MAX_VALUE;
            double minY = Double.MAX_VALUE;
            double maxY = -Double.MAX_VALUE;
            for (Point p : a.polygon()) {
                minX = Math.min(minX, p.x());
                maxX = Math.max(maxX, p.x());
                minY = Math.min(minY, p.y());
                maxY = Math.max(maxY, p.y());
            }
            if (Math.min(maxX - minX, maxY - minY) > 2.2) {
                continue;
            }
            for (Edge e : map.edges()) {
                if (!a.id().equals(map.node(e.a()).area()) || !a.id().equals(map.node(e.b()).area())) {
                    continue;
                }
                Set<Integer> side = reach(next, e.a(), e);
                if (side.contains(e.b())) {
                    continue;
                }
                int all = map.nodes().size();
                if (side.size() >= all / 5 && all - side.size() >= all / 5) {
                    return null;
                }
            }
        }
        return "no narrow corridor (2.2 m or less) that is the only way between two parts of a fifth of the nodes or more";
    }

    private static Set<Integer> reach(Map<Integer, List<Integer>> next, int from, Edge without) {
        Set<Integer> seen = new HashSet<>(List.of(from));
        ArrayDeque<Integer> todo = new ArrayDeque<>(List.of(from));
        while (!todo.isEmpty()) {
            int n = todo.poll();
            for (int m : next.get(n)) {
                boolean cut = n == without.a() && m == without.b() || n == without.b() && m == without.a();
                if (!cut && seen.add(m)) {
                    todo.add(m);
                }
            }
        }
        return seen;
    }
}
