package io.concord.agents.chair;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The chair port's arithmetic: odometry from ticks, the pose controller, the layout's checks. */
class ChairPortTest {
    private final ChairLayout layout = ChairLayout.standard();

    private long ticks(double metres) {
        return Math.round(metres / layout.metresPerTick());
    }

    @Test
    void equalTicksOnBothWheelsDriveStraight() {
        Odometry o = new Odometry(layout, new Pose(1, 2, Math.toRadians(90)));
        o.update(0, 0);
        Pose p = o.update(ticks(3), ticks(3));
        assertEquals(1, p.x(), 1e-3);
        assertEquals(5, p.y(), 1e-3);
        assertEquals(Math.toRadians(90), p.heading(), 1e-6);
        assertEquals(3, o.distanceM(), 1e-3);
    }

    @Test
    void oppositeTicksTurnOnTheSpot() {
        Odometry o = new Odometry(layout, new Pose(0, 0, 0));
        o.update(100, 100);
        // A quarter turn: each wheel runs a quarter of the circle of the track's diameter.
        double arc = Math.PI / 2 * layout.trackM() / 2;
        Pose p = o.update(100 - ticks(arc), 100 + ticks(arc));
        assertEquals(0, p.x(), 1e-3);
        assertEquals(0, p.y(), 1e-3);
        assertEquals(Math.PI / 2, p.heading(), 0.01);
    }

    @Test
    void anArcEndsWhereTheGeometrySays() {
        // Left wheel on a 1 m radius arc around a centre to the left: after half a turn the
        // chair stands 2 x (1 + track / 2) further left, facing back.
        Odometry o = new Odometry(layout, new Pose(0, 0, 0));
        o.update(0, 0);
        double r = 1.0;
        double half = layout.trackM() / 2;
        Pose p = null;
        for (int i = 1; i <= 100; i++) {
            double a = Math.PI * i / 100;
            p = o.update(ticks((r - half) * a), ticks((r + half) * a));
        }
        assertEquals(0, p.x(), 0.01);
        assertEquals(2 * r, p.y(), 0.01);
        assertEquals(Math.PI, Math.abs(p.heading()), 0.01);
    }

    @Test
    void theControllerTurnsFirstThenDrivesAndStopsWithinTolerance() {
        PoseController c = PoseController.standard();
        PoseController.Powers behind = c.toPoint(new Pose(0, 0, 0), -5, 0);
        assertEquals(-behind.left(), behind.right(), 1e-9, "on the spot");
        PoseController.Powers ahead = c.toPoint(new Pose(0, 0, 0), 5, 0.2);
        assertTrue(ahead.left() > 0 && ahead.right() > ahead.left(), "forward, bearing left: " + ahead);
        assertTrue(c.toPoint(new Pose(0, 0, 0), 0.03, 0).stopped());
        assertTrue(c.toPose(new Pose(0, 0, 0), new Pose(0.01, 0, Math.toRadians(2))).stopped());
        PoseController.Powers turn = c.toPose(new Pose(0, 0, 0), new Pose(0, 0, Math.toRadians(90)));
        assertTrue(turn.right() > 0 && turn.left() < 0, "counter-clockwise: " + turn);
    }

    @Test
    void aPoseKeepsItsHeadingInRange() {
        assertEquals(-Math.PI / 2, new Pose(0, 0, 3 * Math.PI / 2).heading(), 1e-12);
        assertEquals(Math.PI, new Pose(0, 0, -Math.PI).heading(), 1e-12);
        assertThrows(IllegalArgumentException.class, () -> new Pose(Double.NaN, 0, 0));
    }

    @Test
    void aWrongLayoutIsRefusedNamingTheSetting() {
        assertTrue(assertThrows(IllegalArgumentException.class,
                () -> new ChairLayout(1.2, 0.7, 0.17, 0.9, 2048, 1.5, List.of())).getMessage().contains("track"));
        assertTrue(assertThrows(IllegalArgumentException.class,
                () -> new ChairLayout(1.2, 0.7, 0.17, 0.56, 0, 1.5, List.of())).getMessage().contains("ticksPerRev"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new ChairLayout(1.2, 0.7, 0.17, 0.56, 2048, 1.5,
                List.of(SensorMount.infrared("a", 0, 0, 0, 1), SensorMount.infrared("a", 0, 0, 0, 1))))
                .getMessage().contains("two sensors are named 'a'"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> SensorMount.sonar("s", 0, 0, 0, 0, 3))
                .getMessage().contains("cone"));
        assertEquals(12, layout.sensors().size());
        assertEquals(7, layout.sensorIndex("rear"));
    }
}
