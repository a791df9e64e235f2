package io.concord.sim.world;

import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.PoseController;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.TickerBehaviour;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Point;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The world and the agents on one clock: inside the test kit's simulation the world steps on the
 * runtime's loop at virtual time, agents drive chairs and talk about what they sense, and the
 * same seed gives the same run, physics and messages together, bit for bit.
 */
class OneClockTest {
    private static final HospitalMap MAP = HospitalMap.defaultHospital();

    /** Drives its chair round the lobby's nodes on its odometry, and tells a logger what it senses. */
    static final class Pilot extends Agent {
        private final SimChair chair;
        private final AID logger;
        private final List<Point> round;
        private int next;
        int reports;

        Pilot(SimChair chair, AID logger, List<Point> round) {
            this.chair = chair;
            this.logger = logger;
            this.round = round;
        }

        @Override
        protected void setup() {
            PoseController control = PoseController.standard();
            addBehaviour(new TickerBehaviour(this, 50) {
                @Override
                protected void onTick() {
                    ChairReadings r = chair.latest();
                    if (r == null) {
                        return;
                    }
                    Point p = round.get(next);
                    if (control.reached(r.odometry(), p.x(), p.y())) {
                        next = (next + 1) % round.size();
                        p = round.get(next);
                    }
                    PoseController.Powers pw = control.toPoint(r.odometry(), p.x(), p.y());
                    chair.drive(pw.left(), pw.right());
                    if (getTickCount() % 10 == 0) {
                        AclMessage m = new AclMessage(Performative.INFORM);
                        m.addReceiver(logger);
                        m.setContent(String.format(Locale.ROOT, "front %.4f at %s", r.range(0), r.odometry()));
                        send(m);
                        reports++;
                    }
                }
            });
        }
    }

    /** Confirms every report. */
    static final class Logger extends Agent {
        int heard;

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    AclMessage m = receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    heard++;
                    AclMessage r = m.createReply();
                    r.setPerformative(Performative.CONFIRM);
                    send(r);
                }
            });
        }
    }

    private record Run(long trace, long poses, long steps, int heard, double travelled) {
    }

    private static Run run(long seed, double seconds) {
        try (Simulation sim = new Simulation(seed, FaultPlan.lossy(0.05, 0.02, 0.02, 0.0))) {
            AgentRuntime rt = sim.newRuntime("host");
            HospitalWorld world = HospitalWorld.builder(MAP).seed(sim.seed()).build();
            SimChair a = world.addChair("chair1", ChairConfig.standard(), world.poseAt(23, 90));
            SimChair b = world.addChair("chair2", ChairConfig.standard(), world.poseAt(24, 90));
            world.attach(rt);
            Logger logger = new Logger();
            AID log = rt.startAgent("logger", logger);
            rt.startAgent("pilot1", new Pilot(a, log, List.of(new Point(22, 7.2), new Point(22, 4))));
            rt.startAgent("pilot2", new Pilot(b, log, List.of(new Point(26, 7.2), new Point(26, 4))));
            sim.runFor((long) (seconds * 1000));
            return new Run(sim.trace().hash(), world.poseHash(), world.stepCount(), logger.heard,
                    a.distanceTravelled() + b.distanceTravelled());
        }
    }

    @Test
    void theSameSeedGivesTheSameRunBitForBit() {
        Run first = run(42, 30);
        Run second = run(42, 30);
        assertEquals(first, second);
        assertTrue(first.travelled() > 10, "the chairs drove: " + first);
        assertTrue(first.heard() > 20, "the agents talked: " + first);
    }

    @Test
    void anotherSeedGivesAnotherRun() {
        Run a = run(42, 30);
        Run b = run(43, 30);
        assertNotEquals(a.trace(), b.trace());
        assertNotEquals(a.poses(), b.poses(), "the noise differs, so the chairs do");
    }

    @Test
    void theWorldStepsAtItsRateOnThePlatformClock() {
        try (Simulation sim = new Simulation(1, FaultPlan.NONE)) {
            AgentRuntime rt = sim.newRuntime("host");
            HospitalWorld world = HospitalWorld.builder(MAP).build();
            HospitalWorld fast = HospitalWorld.builder(MAP).build();
            world.attach(rt);
            HospitalWorld.Attachment f = fast.attach(rt, 10);
            sim.runFor(2_000);
            assertEquals(120, world.stepCount(), "60 Hz for 2 s of platform time");
            assertEquals(1200, fast.stepCount(), "ten times faster when asked");
            assertEquals(0, f.lostSteps());
            f.detach();
            sim.runFor(1_000);
            assertEquals(1200, fast.stepCount(), "detached: no more steps");
            assertEquals(180, world.stepCount());
        }
    }

    @Test
    void readingsCarryTheChairsClockWhichIsWorldTime() {
        try (Simulation sim = new Simulation(1, FaultPlan.NONE)) {
            AgentRuntime rt = sim.newRuntime("host");
            sim.runFor(500);
            HospitalWorld world = HospitalWorld.builder(MAP).build();
            SimChair c = world.addChair("chair1", ChairConfig.standard(), world.poseAt(19, 0));
            world.attach(rt, 4);
            sim.runFor(1_000);
            // Four times faster: 4 s of world time in 1 s of platform time, as a board's own clock would count.
            long t = c.latest().timeNs();
            assertTrue(t <= world.worldTimeNs() && t > world.worldTimeNs() - 60_000_000L, "a report of the last 50 ms of world time: " + t);
            assertEquals(240, world.stepCount());
        }
    }

    /**
     * Once attached to a runtime that runs on a thread of its own, the world is that loop's: a
     * change from another thread (the README's snippet once added a box from the main thread, and
     * jbox2d threw inside its step) is refused with what to do, and the same change on the loop
     * is made.
     */
    @Test
    void aChangeFromAnotherThreadThanTheLoopIsRefusedWithWhatToDo() throws Exception {
        HospitalWorld world = HospitalWorld.builder(HospitalMap.defaultHospital()).seed(1).build();
        world.addBox("before", new Point(15, 6.2), 1.0, 0.5, 0);   // before attach: anyone may build it
        try (AgentRuntime rt = AgentRuntime.builder().build().start()) {
            world.attach(rt);
            IllegalStateException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalStateException.class,
                    () -> world.addBox("bed", new Point(15, 8.2), 2.0, 0.9, 0));
            assertTrue(e.getMessage().startsWith("addBox: the world steps on its runtime's loop since attach(); change it there"),
                    e.getMessage());
            org.junit.jupiter.api.Assertions.assertThrows(IllegalStateException.class, () -> world.door("WA").open());
            java.util.concurrent.CompletableFuture<String> onLoop = new java.util.concurrent.CompletableFuture<>();
            rt.execute(() -> {
                world.addBox("bed", new Point(15, 8.2), 2.0, 0.9, 0);
                world.door("WA").open();
                onLoop.complete(world.door("WA").motion().toString());
            });
            assertEquals("OPENING", onLoop.get(30, java.util.concurrent.TimeUnit.SECONDS));
        }
    }
}
