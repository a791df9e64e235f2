package io.concord.sim.world;

import io.concord.agents.chair.Pose;
import io.concord.agents.map.HospitalMap;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Odometry drifts as configured: not at all with perfect wheels, more the further the chair
 * goes, and more with larger wheel errors. Mean over seeds, so the check is on the model, not
 * on one draw; each seed replays exactly.
 */
class OdometryDriftTest {
    /** An empty hall, 60 m by 12 m, to drive straight in. */
    static final HospitalMap HALL = HospitalMap.parse("""
            {"format": "concord-hospital-map/1", "name": "hall",
             "walls": [{"id": "outer", "path": [[0, 0], [60, 0], [60, 12], [0, 12], [0, 0]]}]}
            """, "hall");
    private static final int SEEDS = 12;

    /** Mean error of the odometry's position at 5, 10 and 20 m down the hall. */
    private static double[] meanDrift(double wheelScaleSigma, double slipSigma) {
        double[] sum = new double[3];
        for (int seed = 1; seed <= SEEDS; seed++) {
            HospitalWorld w = HospitalWorld.builder(HALL).seed(seed).build();
            SimChair c = w.addChair("c", ChairConfig.standard().withWheelErrors(wheelScaleSigma, slipSigma),
                    new Pose(2, 6, 0));
            // Drive on the odometry's belief, as a control agent would: straight along y = 6.
            w.addStepHook(() -> {
                Pose o = c.odometryPose();
                double steer = -8 * (o.y() - 6) - 40 * o.heading();
                c.drive(60 - steer, 60 + steer);
            });
            double[] marks = {5, 10, 20};
            for (int k = 0; k < marks.length; k++) {
                while (c.odometry() < marks[k]) {
                    w.step();
                }
                sum[k] += c.truePose().distanceTo(c.odometryPose());
            }
        }
        for (int k = 0; k < 3; k++) {
            sum[k] /= SEEDS;
        }
        return sum;
    }

    @Test
    void perfectWheelsDoNotDrift() {
        double[] d = meanDrift(0, 0);
        assertTrue(d[2] < 0.01, "under 1 cm after 20 m: " + d[2]);
    }

    @Test
    void driftGrowsWithDistance() {
        double[] d = meanDrift(0.005, 0.004);
        assertTrue(d[0] < d[1] && d[1] < d[2], "5 m " + d[0] + ", 10 m " + d[1] + ", 20 m " + d[2]);
        assertTrue(d[2] > 0.05, "a real drift after 20 m: " + d[2]);
    }

    @Test
    void driftGrowsWithTheConfiguredNoise() {
        double small = meanDrift(0.001, 0.001)[2];
        double large = meanDrift(0.01, 0.005)[2];
        assertTrue(large > 2 * small, "0.1 %: " + small + " m, 1 %: " + large + " m after 20 m");
    }
}
