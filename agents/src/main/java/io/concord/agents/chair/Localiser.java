package io.concord.agents.chair;

/**
 * Where the chair is: its odometry, corrected by every position fix it reads (a floor marker at a
 * node). A fix sets the rigid transform that takes the odometry's pose to the fix; the odometry
 * between fixes carries on through it, so the drift is what accumulated since the last marker.
 */
public final class Localiser {
    private double dx;
    private double dy;
    private double dth;
    private Pose pose;
    private long fixes;

    /** The corrected pose for a report (its odometry, and its fix if it has one). */
    public Pose update(ChairReadings r) {
        Pose odo = r.odometry();
        if (r.fix() != null) {
            Pose f = r.fix();
            dth = f.heading() - odo.heading();
            double c = StrictMath.cos(dth);
            double s = StrictMath.sin(dth);
            dx = f.x() - (odo.x() * c - odo.y() * s);
            dy = f.y() - (odo.x() * s + odo.y() * c);
            fixes++;
        }
        double c = StrictMath.cos(dth);
        double s = StrictMath.sin(dth);
        pose = new Pose(odo.x() * c - odo.y() * s + dx, odo.x() * s + odo.y() * c + dy, odo.heading() + dth);
        return pose;
    }

    /** The last pose, or null before the first report. */
    public Pose pose() {
        return pose;
    }

    /** Fixes taken so far. */
    public long fixes() {
        return fixes;
    }
}
