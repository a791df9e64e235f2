package io.concord.sim.world;

import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Pose;
import io.concord.agents.chair.PoseController;
import io.concord.agents.map.HospitalMap;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A chair in the default hospital: driving, turning, go-to, walls, sensors, reports. */
class ChairTest {
    private final HospitalWorld world = HospitalWorld.builder(HospitalMap.defaultHospital()).seed(7).build();

    private SimChair chair(Pose at) {
        return world.addChair("chair1", ChairConfig.standard().noiseless(), at);
    }

    @Test
    void drivingStraightKeepsTheLineAndReachesTheSpeedThePowerGives() {
        SimChair c = chair(new Pose(3, 10.8, 0));
        c.drive(50, 50);
        world.run(4);
        Pose p = c.truePose();
        assertEquals(10.8, p.y(), 1e-3, "no sideways drift: " + p);
        assertEquals(0, p.heading(), Math.toRadians(0.1), "no turn: " + p);
        assertEquals(0.75, c.forwardSpeed(), 0.01, "50 % of 1.5 m/s");
        // 0.75 s of ramp at 1 m/s² (0.28 m), then 3.25 s at 0.75 m/s.
        assertEquals(3 + 0.28 + 3.25 * 0.75, p.x(), 0.05, "distance: " + p);
    }

    @Test
    void turningOnTheSpotStaysInPlace() {
        SimChair c = chair(new Pose(24, 6, 0));
        c.drive(-30, 30);
        world.run(2);
        Pose p = c.truePose();
        assertEquals(24, p.x(), 0.02, "" + p);
        assertEquals(6, p.y(), 0.02, "" + p);
        assertTrue(p.heading() > Math.toRadians(90), "counter-clockwise with the right wheel forward: " + p);
    }

    @Test
    void goToByMotorPowersReachesThePoseWithinTolerance() {
        SimChair c = chair(world.poseAt(19, 90));
        PoseController control = PoseController.standard();
        Pose target = new Pose(26.5, 7.5, Math.toRadians(180));
        world.addStepHook(() -> {
            PoseController.Powers pw = control.toPose(c.truePose(), target);
            c.drive(pw.left(), pw.right());
        });
        world.run(20);
        Pose p = c.truePose();
        assertTrue(p.distanceTo(target) <= 0.08, "within 8 cm: " + p + " for " + target);
        assertTrue(Math.abs(Pose.normalize(p.heading() - target.heading())) <= Math.toRadians(4), "within 4°: " + p);
        assertEquals(0, c.bumps(), "touched nothing");
    }

    @Test
    void aChairDrivenIntoAWallStopsAtTheWallAndReportsTheBump() {
        SimChair c = chair(new Pose(10, 10.8, Math.toRadians(-90)));
        List<ChairReadings> reports = new ArrayList<>();
        c.setListener(reports::add);
        c.drive(80, 80);
        world.run(5);
        Pose p = c.truePose();
        // The wall's face is at 9.075 and the chair's front 0.6 m ahead of its centre.
        assertEquals(9.075 + 0.6, p.y(), 0.03, "stands at the wall: " + p);
        assertTrue(c.touching());
        assertTrue(reports.get(reports.size() - 1).bumper(), "the bumper reports the contact");
        assertTrue(reports.get(0).bumper() == false, "not before");
        Collision first = world.collisions().get(0);
        assertEquals("chair1", first.chair());
        assertEquals("wall 'a-south-3'", first.other());
        assertEquals(9.075, first.at().y(), 0.02);
        // The wheels stall: the encoders stop counting once the chair stands at the wall.
        long ticks = c.latest().leftTicks();
        world.run(1);
        assertEquals(ticks, c.latest().leftTicks(), 2);
    }

    @Test
    void sonarReadsTheDistanceToAWallWithinItsNoise() {
        SimChair c = world.addChair("chair1", ChairConfig.standard(), new Pose(10, 10.8, 0));
        int left = c.layout().sensorIndex("left");
        // The sonar sits 0.35 m left of the centre; the wall's face is at 12.525.
        double truth = 12.525 - 11.15;
        double sum = 0;
        double sq = 0;
        int n = 0;
        for (int i = 0; i < 60; i++) {
            world.run(0.1);
            double d = c.latest().range(left);
            sum += d;
            sq += d * d;
            n++;
        }
        double mean = sum / n;
        double sd = Math.sqrt(sq / n - mean * mean);
        double sigma = 0.01 + 0.01 * truth;
        assertEquals(truth, mean, 3 * sigma / Math.sqrt(n) + 0.002, "mean reading");
        assertTrue(sd > sigma * 0.6 && sd < sigma * 1.4, "spread " + sd + " against the configured " + sigma);
    }

    @Test
    void infraredReadsTheDistanceToAWallWithinItsNoise() {
        // Facing the south wall of the corridor, the front 0.5 m from its face.
        SimChair c = world.addChair("chair1", ChairConfig.standard(), new Pose(10, 9.075 + 0.5 + 0.6, Math.toRadians(-90)));
        world.run(0.5);
        int ir = c.layout().sensorIndex("ir-front-left");
        double sigma = 0.01 + 0.01 * 0.5;
        assertEquals(0.5, c.latest().range(ir), 4 * sigma);
        int corner = c.layout().sensorIndex("ir-corner-left");
        assertTrue(c.latest().range(corner) > 0.5, "the 45° ray meets the wall further away");
    }

    @Test
    void aSensorThatSeesNothingReadsItsMaximumRange() {
        SimChair c = chair(new Pose(10, 10.8, 0));
        world.run(0.5);
        assertEquals(3.0, c.latest().range(c.layout().sensorIndex("front")), 0.0, "9 m of empty corridor ahead");
        assertEquals(0.8, c.latest().range(c.layout().sensorIndex("ir-front-left")), 0.0);
    }

    @Test
    void sensorsSeeOtherChairsAndDoorLeaves() {
        SimChair c = chair(new Pose(10, 10.8, 0));
        world.addChair("chair2", ChairConfig.standard().noiseless(), new Pose(12.6, 10.8, 0));
        world.run(0.5);
        // Front of chair1 at 10.6, back of chair2 at 12.0.
        assertEquals(1.4, c.latest().range(c.layout().sensorIndex("front")), 0.005);
    }

    @Test
    void reportsArriveAtTheConfiguredRateWithRisingSequenceNumbers() {
        SimChair c = chair(new Pose(10, 10.8, 0));
        List<ChairReadings> reports = new ArrayList<>();
        c.setListener(reports::add);
        world.run(2);
        assertEquals(40, reports.size(), "20 a second");
        for (int i = 0; i < reports.size(); i++) {
            assertEquals(i, reports.get(i).seq());
        }
        assertEquals(c.layout().sensors().size(), reports.get(0).rangeCount());
        assertTrue(reports.get(0).batteryVolts() > 25);
    }

    @Test
    void theEmergencyStopAndAFailedMotorStopTheWheels() {
        SimChair c = chair(new Pose(3, 10.8, 0));
        c.drive(60, 60);
        world.run(1);
        c.emergencyStop(true);
        world.run(1);
        assertEquals(0, c.forwardSpeed(), 1e-3);
        assertTrue(c.latest().emergencyStop());
        c.emergencyStop(false);
        c.injectFault(io.concord.agents.chair.ChairFault.MOTOR_LEFT);
        double before = c.truePose().heading();
        world.run(1);
        assertTrue(c.truePose().heading() > before + 0.3, "only the right wheel drives: the chair turns left");
        assertTrue(c.latest().faults().contains(io.concord.agents.chair.ChairFault.MOTOR_LEFT));
    }

    @Test
    void aChairCannotStartInsideAWall() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> world.addChair("chair1", ChairConfig.standard(), new Pose(10, 9.2, 0)));
        assertTrue(e.getMessage().contains("wall 'a-south-3'"), e.getMessage());
        assertFalse(world.chairs().iterator().hasNext(), "nothing half-added");
    }

    @Test
    void twoChairsCollideAndNeitherPassesThroughTheOther() {
        SimChair a = chair(new Pose(8, 10.8, 0));
        SimChair b = world.addChair("chair2", ChairConfig.standard().noiseless(), new Pose(13, 10.8, Math.PI));
        a.drive(60, 60);
        b.drive(60, 60);
        world.run(6);
        assertTrue(b.truePose().x() - a.truePose().x() >= 1.2 - 0.02, "a: " + a.truePose() + " b: " + b.truePose());
        assertTrue(world.collisions().stream().anyMatch(c -> c.chair().equals("chair1") && c.other().equals("chair2")));
    }

    @Test
    void aFloorMarkerAtANodeGivesAFixAndNowhereElse() {
        SimChair c = world.addChair("chair1", ChairConfig.standard(), world.poseAt(19, 90));
        world.run(0.2);
        Pose fix = c.latest().fix();
        assertTrue(fix != null && fix.distanceTo(24, 4) < 0.05, "at node 19: " + fix);
        SimChair away = world.addChair("chair2", ChairConfig.standard(), new Pose(25, 6, 0));
        world.run(0.2);
        assertEquals(null, away.latest().fix(), "no marker 1 m from any node");
        SimChair blind = world.addChair("chair3", ChairConfig.standard().withMarkerFixes(false), world.poseAt(23, 90));
        world.run(0.2);
        assertEquals(null, blind.latest().fix(), "markers off");
    }

    @Test
    void theWatchdogStopsAChairItsHostStoppedCommanding() {
        SimChair c = world.addChair("chair1", ChairConfig.standard().noiseless().withWatchdog(0.3), new Pose(3, 10.8, 0));
        c.drive(50, 50);
        world.run(0.2);
        assertTrue(c.forwardSpeed() > 0.1, "moving while commanded");
        world.run(1.5);
        assertEquals(0, c.forwardSpeed(), 1e-3, "stopped 0.3 s after the last command");
        assertTrue(c.latest().faults().contains(io.concord.agents.chair.ChairFault.WATCHDOG));
        c.drive(50, 50);
        world.run(0.2);
        assertFalse(c.latest().faults().contains(io.concord.agents.chair.ChairFault.WATCHDOG), "a command clears it");
    }

    @Test
    void aBrakedChairHoldsWithItsTyresAgainstAPushItsMotorsCouldNotHold() {
        // A braked chair's motors hold 300 N; its tyres 785 N. A 200 kg chair pushes with 600 N.
        SimChair braked = chair(new Pose(10, 10.8, 0));
        SimChair pusher = world.addChair("pusher", ChairConfig.standard().noiseless().withMassKg(200), new Pose(8.5, 10.8, 0));
        pusher.drive(100, 100);
        world.run(6);
        assertTrue(pusher.touching() || world.collisions().stream().anyMatch(c -> c.other().equals("chair1")), "they met");
        assertEquals(10, braked.truePose().x(), 0.1, "the braked chair held: " + braked.truePose());
    }

    @Test
    void aListenerThatThrowsDoesNotStopTheWorld() {
        SimChair bad = chair(new Pose(3, 10.8, 0));
        SimChair good = world.addChair("chair2", ChairConfig.standard(), new Pose(10, 10.8, 0));
        bad.setListener(r -> {
            throw new IllegalStateException("a dead agent's code");
        });
        List<ChairReadings> reports = new ArrayList<>();
        good.setListener(reports::add);
        world.run(1);
        assertEquals(20, reports.size(), "the other chair still reports");
        assertEquals(20, bad.listenerFailures(), "every failure counted");
        assertEquals(60, world.stepCount());
    }
}
