package io.concord.sim;

import io.concord.agents.door.DoorDriver;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Pose;
import io.concord.agents.chair.PoseController;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.testkit.FaultPlan;
import io.concord.core.testkit.Simulation;
import io.concord.agents.map.Area;
import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.MapException;
import io.concord.agents.map.Node;
import io.concord.agents.map.Point;
import io.concord.sim.render.HospitalPicture;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.SimChair;
import io.concord.sim.world.WorldDoor;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * The hospital world demo: the dissertation's route (the chair waits at node 19, fetches the
 * patient from node 3 in Ward A and takes them to node 9 in Ward B) driven by a pilot agent on a
 * Concord runtime, with the world stepping on the runtime's clock, N times faster than real time
 * (or on the test kit's virtual clock, as fast as the CPU allows). A second chair crosses the
 * same corridor to room A8 and back, and a visitor walks up and down Ward B's corridor. The
 * pilot opens each door on its route as it comes near, keeps right in corridors, and stops for
 * anything its front sonar or infrared sees close ahead. A picture of the run is written at the
 * end. The wheelchair agents (control, planner, doors, medical staff) replace the pilot in a
 * later issue.
 */
public final class HospitalDemo {
    private static final PrintStream OUT = System.out;

    private HospitalDemo() {
    }

    /** Settings of a run. */
    record Options(long seed, double speedup, boolean virtual, Path map, Path picture, double maxSeconds) {
    }

    public static void main(String[] args) throws Exception {
        Options o;
        try {
            o = parse(args);
        } catch (IllegalArgumentException e) {
            System.err.println(e.getMessage());
            System.err.println("usage: java -jar concord-demo.jar hospital [--seed N] [--speedup X | --virtual] [--map file.json]"
                    + " [--picture file.png] [--max-seconds S]");
            System.exit(2);
            return;
        }
        HospitalMap map;
        try {
            map = o.map() == null ? HospitalMap.defaultHospital() : HospitalMap.load(o.map());
        } catch (MapException e) {
            System.err.println(e.getMessage());
            System.exit(2);
            return;
        }
        System.exit(run(map, o) ? 0 : 1);
    }

    static Options parse(String[] args) {
        long seed = 2010;
        double speedup = 20;
        boolean virtual = false;
        Path map = null;
        Path picture = Path.of("target", "hospital-demo.png");
        double max = 600;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            String v = i + 1 < args.length ? args[i + 1] : null;
            switch (a) {
                case "--seed" -> seed = Long.parseLong(need(a, v));
                case "--speedup" -> speedup = Double.parseDouble(need(a, v));
                case "--virtual" -> {
                    virtual = true;
                    i--;
                }
                case "--map" -> map = Path.of(need(a, v));
                case "--picture" -> picture = Path.of(need(a, v));
                case "--max-seconds" -> max = Double.parseDouble(need(a, v));
                default -> throw new IllegalArgumentException("unknown option '" + a + "'");
            }
            i++;
        }
        if (!(speedup > 0 && speedup <= 1000)) {
            throw new IllegalArgumentException("--speedup must be in (0, 1000], got " + speedup);
        }
        return new Options(seed, speedup, virtual, map, picture, max);
    }

    private static String need(String option, String value) {
        if (value == null) {
            throw new IllegalArgumentException(option + " needs a value");
        }
        return value;
    }

    /** Runs the demo; true if the patient reached node 9. */
    static boolean run(HospitalMap map, Options o) throws InterruptedException {
        for (int n : new int[] {19, 3, 9}) {
            if (!map.hasNode(n)) {
                OUT.println("The map has no node " + n + "; the scenario needs nodes 19, 3 and 9.");
                return false;
            }
        }
        OUT.println("Concord hospital demo: " + map);
        OUT.println("The dissertation's scenario: chair1 waits at node 19, fetches the patient from node 3 ("
                + area(map, 3) + ") and takes them to node 9 (" + area(map, 9) + ").");
        OUT.println(o.virtual() ? "The world steps on the test kit's virtual clock, as fast as the CPU allows."
                : String.format(Locale.ROOT, "The world steps at 60 Hz on the runtime's clock, %.0f times faster than real time.",
                o.speedup()));
        HospitalWorld world = HospitalWorld.builder(map).seed(o.seed()).build();
        SimChair chair1 = world.addChair("chair1", ChairConfig.standard(), world.poseAt(19, 90));
        List<Pilot> pilots = new ArrayList<>();
        Pilot p1 = new Pilot(world, chair1, List.of(leg(map, 19, 3), leg(map, 3, 9)), 3.0);
        pilots.add(p1);
        if (map.hasNode(24) && map.hasNode(21)) {
            SimChair chair2 = world.addChair("chair2", ChairConfig.standard(), world.poseAt(24, 90));
            Pilot p2 = new Pilot(world, chair2, List.of(leg(map, 24, 21), leg(map, 21, 24)), 2.0);
            // The pilots know no right of way (the control agents will): chair2 lets chair1 go first.
            p2.pauseUntilNs = 6_000_000_000L;
            pilots.add(p2);
        }
        if (map.hasNode(11) && map.hasNode(13)) {
            Point a = map.node(11).at();
            Point b = map.node(13).at();
            world.addPerson("visitor", List.of(new Point(a.x(), a.y() + 0.7), new Point(b.x(), b.y() + 0.7)), 0.9, true);
        }
        CountDownLatch done = new CountDownLatch(1);
        long t0 = System.nanoTime();
        if (o.virtual()) {
            try (Simulation sim = new Simulation(o.seed(), FaultPlan.NONE)) {
                AgentRuntime rt = sim.newRuntime("hospital");
                world.attach(rt);
                for (Pilot p : pilots) {
                    rt.startAgent("pilot-" + p.chair.name(), p);
                }
                sim.runUntil(() -> pilots.stream().allMatch(Pilot::finished), (long) (o.maxSeconds() * 1000));
            }
        } else {
            try (AgentRuntime rt = AgentRuntime.builder().platformName("hospital").seed(o.seed()).build().start()) {
                world.attach(rt, o.speedup());
                for (Pilot p : pilots) {
                    p.onFinish = () -> {
                        if (pilots.stream().allMatch(Pilot::finished)) {
                            done.countDown();
                        }
                    };
                    rt.startAgent("pilot-" + p.chair.name(), p);
                }
                done.await((long) (o.maxSeconds() / o.speedup() * 1000) + 1000, TimeUnit.MILLISECONDS);
                CountDownLatch drawn = new CountDownLatch(1);
                rt.execute(() -> {
                    HospitalPicture.write(world, o.picture(), String.format(Locale.ROOT,
                            "%s: the scenario 19 -> 3 -> 9, seed %d, t = %.1f s", map.name(), o.seed(), world.worldTimeNs() / 1e9));
                    drawn.countDown();
                });
                drawn.await(10, TimeUnit.SECONDS);
            }
        }
        if (o.virtual()) {
            HospitalPicture.write(world, o.picture(), String.format(Locale.ROOT,
                    "%s: the scenario 19 -> 3 -> 9, seed %d, t = %.1f s", map.name(), o.seed(), world.worldTimeNs() / 1e9));
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        double simSeconds = world.worldTimeNs() / 1e9;
        OUT.println();
        OUT.printf(Locale.ROOT, "%.1f s of hospital in %.1f s of wall time (%.0f times real time); %d steps; "
                        + "chair1 drove %.1f m; %d collisions.%n", simSeconds, wall, simSeconds / wall, world.stepCount(),
                chair1.distanceTravelled(), world.collisionCount());
        OUT.println("Picture: " + o.picture().toAbsolutePath());
        if (!p1.finished()) {
            OUT.println("chair1 did not finish the scenario within " + o.maxSeconds() + " s of hospital time.");
            return false;
        }
        return true;
    }

    private static String area(HospitalMap map, int node) {
        Node n = map.node(node);
        String room = map.areaAt(n.at()).map(Area::name).orElse("no area");
        String ward = map.wardAt(n.at()).map(Area::name).orElse(null);
        return ward == null || ward.equals(room) ? room : room + ", " + ward;
    }

    /** The shortest path between two nodes by edge length (Dijkstra), as nodes. */
    static List<Integer> leg(HospitalMap map, int from, int to) {
        Map<Integer, Double> dist = new HashMap<>();
        Map<Integer, Integer> prev = new HashMap<>();
        PriorityQueue<double[]> q = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        dist.put(from, 0.0);
        q.add(new double[] {0, from});
        while (!q.isEmpty()) {
            double[] e = q.poll();
            int n = (int) e[1];
            if (e[0] > dist.get(n)) {
                continue;
            }
            if (n == to) {
                break;
            }
            for (Edge edge : map.edgesAt(n)) {
                int m = edge.other(n);
                double d = e[0] + edge.length(map);
                if (d < dist.getOrDefault(m, Double.MAX_VALUE)) {
                    dist.put(m, d);
                    prev.put(m, n);
                    q.add(new double[] {d, m});
                }
            }
        }
        if (!dist.containsKey(to)) {
            throw new IllegalArgumentException("no route from node " + from + " to node " + to);
        }
        List<Integer> path = new ArrayList<>();
        for (Integer n = to; n != null; n = prev.get(n)) {
            path.add(0, n);
        }
        return path;
    }

    /**
     * Drives one chair along its legs on every report of the chair (so at any speed-up): to each
     * node in turn, keeping 0.6 m right of the centre line on long corridor edges, opening the
     * door of an edge when 3.5 m from it and waiting until it is open, closing it behind, and
     * stopping while something is close ahead. It drives on the chair's true pose: localisation
     * is the control agent's job (a later issue).
     */
    static final class Pilot extends Agent implements ChairListener {
        private static final double KEEP_RIGHT_M = 0.6;
        final SimChair chair;
        private final HospitalWorld world;
        private final HospitalMap map;
        private final List<List<Integer>> legs;
        private final double pauseS;
        private final PoseController control = new PoseController(60, 30, 0.12, Math.toRadians(5));
        private int leg;
        private int index = 1;
        private long pauseUntilNs = -1;
        private boolean finished;
        private WorldDoor openedBehind;
        private String waitingFor;
        Runnable onFinish = () -> { };

        Pilot(HospitalWorld world, SimChair chair, List<List<Integer>> legs, double pauseS) {
            this.world = world;
            this.map = world.map();
            this.chair = chair;
            this.legs = legs;
            this.pauseS = pauseS;
        }

        boolean finished() {
            return finished;
        }

        @Override
        protected void setup() {
            chair.setListener(this);
            say("starts at node " + legs.get(0).get(0) + "; route " + legs);
        }

        private void say(String s) {
            OUT.printf(Locale.ROOT, "  t=%6.1f s  %s: %s%n", world.worldTimeNs() / 1e9, chair.name(), s);
        }

        @Override
        public void onReadings(ChairReadings r) {
            if (finished) {
                return;
            }
            long now = world.worldTimeNs();
            if (now < pauseUntilNs) {
                chair.stop();
                return;
            }
            List<Integer> route = legs.get(leg);
            int fromId = route.get(index - 1);
            int toId = route.get(index);
            Edge edge = map.edge(fromId, toId).orElseThrow();
            Pose pose = chair.truePose();
            Point target = waypoint(edge, fromId, toId);
            if (control.reached(pose, target.x(), target.y())) {
                closeBehind();
                if (edge.door() != null) {
                    openedBehind = world.door(edge.door());
                }
                index++;
                if (index == route.size()) {
                    leg++;
                    index = 1;
                    chair.stop();
                    if (leg == legs.size()) {
                        finished = true;
                        say("arrived at node " + toId + (chair.name().equals("chair1") ? ": the patient is delivered" : ""));
                        closeBehind();
                        onFinish.run();
                        return;
                    }
                    say("at node " + toId + (chair.name().equals("chair1") ? ": the patient gets on" : "")
                            + String.format(Locale.ROOT, " (%.0f s)", pauseS));
                    pauseUntilNs = now + (long) (pauseS * 1e9);
                }
                return;
            }
            // The door of this edge: open it on approach, wait in front of it until it is open.
            if (edge.door() != null) {
                WorldDoor door = world.door(edge.door());
                Point c = door.spec().centre();
                double d = pose.distanceTo(c.x(), c.y());
                boolean ahead = d < map.node(fromId).at().distanceTo(c) + 0.3 && d < 3.5;
                if (ahead && !door.isOpen() && door.motion() != DoorDriver.Motion.OPENING) {
                    door.open();
                    say("opens door " + door.id() + " (" + door.spec().kind().toString().toLowerCase(Locale.ROOT) + ")");
                }
                if (ahead && !door.isOpen() && d < 2.2) {
                    waiting("door " + door.id());
                    chair.stop();
                    return;
                }
            }
            // The stop zone, whatever the plan: something within 0.45 m ahead, or 0.3 m on an infrared.
            double front = r.range(chair.layout().sensorIndex("front"));
            double irl = r.range(chair.layout().sensorIndex("ir-front-left"));
            double irr = r.range(chair.layout().sensorIndex("ir-front-right"));
            if (front < 0.45 || irl < 0.3 || irr < 0.3) {
                waiting("something ahead (" + String.format(Locale.ROOT, "%.2f m", Math.min(front, Math.min(irl, irr))) + ")");
                chair.stop();
                return;
            }
            if (waitingFor != null) {
                waitingFor = null;
            }
            PoseController.Powers p = control.toPoint(pose, target.x(), target.y());
            // The slow-down zone: under 1.2 m, at most a third of the power.
            double scale = front < 1.2 ? 0.35 : 1;
            chair.drive(p.left() * scale, p.right() * scale);
        }

        private void waiting(String what) {
            if (!what.equals(waitingFor) && !(waitingFor != null && waitingFor.startsWith("something") && what.startsWith("something"))) {
                say("waits for " + what);
            }
            waitingFor = what;
        }

        private void closeBehind() {
            if (openedBehind != null) {
                Point c = openedBehind.spec().centre();
                if (chair.truePose().distanceTo(c.x(), c.y()) > 1.5 && !openedBehind.doorwayOccupied()) {
                    openedBehind.close();
                    openedBehind = null;
                }
            }
        }

        /** The node to drive to, moved right of the edge's line on long corridor edges with no door. */
        private Point waypoint(Edge edge, int fromId, int toId) {
            Point a = map.node(fromId).at();
            Point b = map.node(toId).at();
            double len = a.distanceTo(b);
            Area ka = map.areaAt(a).orElse(null);
            Area kb = map.areaAt(b).orElse(null);
            boolean corridor = edge.door() == null && len > 2.5 && ka != null && kb != null
                    && ka.kind() != Area.Kind.ROOM && kb.kind() != Area.Kind.ROOM;
            if (!corridor) {
                return b;
            }
            double rx = (b.y() - a.y()) / len * KEEP_RIGHT_M;
            double ry = -(b.x() - a.x()) / len * KEEP_RIGHT_M;
            return new Point(b.x() + rx, b.y() + ry);
        }

        @Override
        public String toString() {
            return "Pilot[" + chair.name() + " leg " + leg + " " + Arrays.toString(legs.toArray()) + "]";
        }
    }
}
