package io.concord.bench.harness;

import io.concord.agents.door.DoorDriver;
import io.concord.agents.chair.PoseController;
import io.concord.core.agent.AgentRuntime;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.sim.internal.EngineBaseline;
import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Point;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.SimChair;
import io.concord.sim.world.WorldDoor;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * Steps a second of the default hospital on the test kit's virtual clock, with chairs that drive
 * (every sensor on) from node to node at random, and doors that open as a chair comes near and
 * close when it has gone. Measured in windows of wall time, each with the bytes allocated a step
 * and the heap after a collection, so that a long run shows any growth; beside it, the bare
 * physics engine with the same walls and as many boxes, in the same run.
 */
public final class SimHarness {
    /** Nodes the chairs start from, far enough apart. */

    public record Window(double stepsPerS, double bytesPerStep, double heapMb) {
    }

    public record Outcome(int chairs, double stepsPerS, double engineStepsPerS, List<Window> windows, long collisions,
                   double metresDriven, long doorMoves, long resets, double worldSeconds) {
        public double realtimeX() {
            return stepsPerS / 60;
        }
    }

    private SimHarness() {
    }

    /** A chair's walk: to a random neighbour of the node it reached, turning back only at dead ends. */
    private static final class Walker {
        final SimChair chair;
        final SplittableRandom random;
        int at;
        int to;
        double lastProgressM;
        long lastProgressStep;
        boolean turnedBack;
        long resets;

        Walker(SimChair chair, int start, SplittableRandom random) {
            this.chair = chair;
            this.random = random;
            this.at = start;
            this.to = start;
        }
    }

    public static Outcome run(int chairs, double seconds, int windows, java.nio.file.Path picture) {
        HospitalMap map = HospitalMap.defaultHospital();
        double engine = EngineBaseline.stepsPerSecond(map, chairs, Math.min(5, seconds / 4));
        try (Simulation sim = new Simulation(chairs, FaultPlan.NONE)) {
            AgentRuntime rt = sim.newRuntime("bench");
            HospitalWorld world = HospitalWorld.builder(map).seed(chairs).build();
            List<Walker> walkers = new ArrayList<>();
            SplittableRandom random = new SplittableRandom(7);
            for (int i = 0; i < chairs; i++) {
                int start = map.parking().get(i);
                SimChair c = world.addChair("chair" + (i + 1), ChairConfig.standard(), world.poseAt(start, 90));
                walkers.add(new Walker(c, start, random.split()));
            }
            PoseController control = PoseController.standard();
            long[] doorMoves = {0};
            world.addStepHook(() -> {
                for (Walker w : walkers) {
                    drive(world, map, control, w);
                }
                if (world.stepCount() % 15 == 0) {
                    doorMoves[0] += doors(world, walkers);
                }
                // Hours of world time empty a 500 Wh battery (5 km): the chairs are kept charged.
                if (world.stepCount() % 3600 == 0) {
                    for (Walker w : walkers) {
                        w.chair.setBatteryUsed(0);
                    }
                }
            });
            world.attach(rt);
            com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
            // Warm-up: a quarter of the run, for the JIT.
            long warmEnd = System.nanoTime() + (long) (seconds / 4 * 1e9);
            while (System.nanoTime() < warmEnd) {
                sim.runFor(1_000);
            }
            List<Window> out = new ArrayList<>();
            long totalSteps = 0;
            double totalNs = 0;
            double windowS = seconds / windows;
            for (int k = 0; k < windows; k++) {
                long steps0 = world.stepCount();
                long bytes0 = threads.getCurrentThreadAllocatedBytes();
                long t0 = System.nanoTime();
                long end = t0 + (long) (windowS * 1e9);
                long t;
                do {
                    sim.runFor(1_000);
                    t = System.nanoTime();
                } while (t < end);
                long steps = world.stepCount() - steps0;
                long bytes = threads.getCurrentThreadAllocatedBytes() - bytes0;
                totalSteps += steps;
                totalNs += t - t0;
                System.gc();
                var heap = ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
                out.add(new Window(steps / ((t - t0) / 1e9), (double) bytes / steps, heap / 1048576.0));
            }
            double metres = 0;
            long resets = 0;
            for (Walker w : walkers) {
                metres += w.chair.distanceTravelled();
                resets += w.resets;
            }
            if (picture != null) {
                io.concord.sim.render.HospitalPicture.write(world, picture, String.format(Locale.ROOT,
                        "bench sim, %d chairs: %.0f s of world time, %.0f m driven", chairs, world.worldTimeNs() / 1e9, metres));
            }
            return new Outcome(chairs, totalSteps / (totalNs / 1e9), engine, out, world.collisionCount(), metres, doorMoves[0],
                    resets, world.worldTimeNs() / 1e9);
        }
    }

    private static void drive(HospitalWorld world, HospitalMap map, PoseController control, Walker w) {
        var pose = w.chair.truePose();
        Point target = map.node(w.to).at();
        if (control.reached(pose, target.x(), target.y())) {
            List<Edge> edges = map.edgesAt(w.to);
            int from = w.at;
            w.at = w.to;
            int next = edges.get(w.random.nextInt(edges.size())).other(w.at);
            if (next == from && edges.size() > 1) {
                next = edges.get(w.random.nextInt(edges.size())).other(w.at);
            }
            w.to = next;
            target = map.node(w.to).at();
        }
        // A chair that has not moved 0.2 m in 5 s (another chair in its way) turns back.
        double d = w.chair.distanceTravelled();
        if (d - w.lastProgressM > 0.2) {
            w.lastProgressM = d;
            w.lastProgressStep = world.stepCount();
            w.turnedBack = false;
        } else if (world.stepCount() - w.lastProgressStep > 600) {
            // Wedged for 10 s (a chair half through a door that met it, two chairs nose to nose):
            // a workload keeps its chairs driving, so it is lifted back onto the node it came from.
            w.chair.place(world.poseAt(w.at, w.random.nextInt(360)));
            w.to = w.at;
            w.lastProgressStep = world.stepCount();
            w.resets++;
            target = map.node(w.to).at();
        } else if (world.stepCount() - w.lastProgressStep > 300 && !w.turnedBack) {
            int back = w.at;
            w.at = w.to;
            w.to = back;
            w.turnedBack = true;
            target = map.node(w.to).at();
        }
        PoseController.Powers p = control.toPoint(pose, target.x(), target.y());
        w.chair.drive(p.left(), p.right());
    }

    /** Opens a door with a chair within 3 m of it, closes one with none: returns the commands given. */
    private static int doors(HospitalWorld world, List<Walker> walkers) {
        int moves = 0;
        for (WorldDoor door : world.doors()) {
            Point c = door.spec().centre();
            boolean near = false;
            for (Walker w : walkers) {
                near |= w.chair.truePose().distanceTo(c.x(), c.y()) < 3;
            }
            if (near && door.motion() != DoorDriver.Motion.OPENING && !door.isOpen()) {
                door.open();
                moves++;
            } else if (!near && door.motion() != DoorDriver.Motion.CLOSING && !door.isClosed() && !door.doorwayOccupied()) {
                door.close();
                moves++;
            }
        }
        return moves;
    }

    public static String describe(Outcome o) {
        return String.format(Locale.ROOT, "RESULT sim %d steps_per_s=%.0f realtime_x=%.0f engine_steps_per_s=%.0f "
                        + "engine_share=%.2f speed_mps=%.2f resets=%d bytes_per_step=%.0f heap_mb_first=%.1f heap_mb_last=%.1f",
                o.chairs(), o.stepsPerS(), o.realtimeX(), o.engineStepsPerS(), o.stepsPerS() / o.engineStepsPerS(),
                o.metresDriven() / o.worldSeconds() / o.chairs(), o.resets(),
                o.windows().get(o.windows().size() - 1).bytesPerStep(), o.windows().get(0).heapMb(),
                o.windows().get(o.windows().size() - 1).heapMb());
    }
}
