package io.concord.agents.chair;

/**
 * Dead reckoning from the two wheel encoders with the chair's nominal geometry (wheel radius,
 * track, ticks per revolution). It drifts as a real chair's does: a wheel a little larger than
 * its nominal size, a slip, a bump all go into the pose unseen. Feed it every report's cumulative
 * counts; the first call only sets the reference.
 */
public final class Odometry {
    private final double metresPerTick;
    private final double trackM;
    private double x;
    private double y;
    private double heading;
    private long lastLeft;
    private long lastRight;
    private boolean started;
    private double distanceM;

    /** Odometry for a layout, starting at a pose. */
    public Odometry(ChairLayout layout, Pose start) {
        this.metresPerTick = layout.metresPerTick();
        this.trackM = layout.trackM();
        reset(start);
    }

    /** Sets the pose (a fix from a landmark, or the start); the next counts are taken as the reference. */
    public void reset(Pose pose) {
        x = pose.x();
        y = pose.y();
        heading = pose.heading();
        started = false;
    }

    /**
     * Integrates the wheel motion since the previous counts (midpoint rule on the arc).
     *
     * @return the pose now
     */
    public Pose update(long leftTicks, long rightTicks) {
        if (!started) {
            started = true;
            lastLeft = leftTicks;
            lastRight = rightTicks;
            return pose();
        }
        double dl = (leftTicks - lastLeft) * metresPerTick;
        double dr = (rightTicks - lastRight) * metresPerTick;
        lastLeft = leftTicks;
        lastRight = rightTicks;
        double ds = (dl + dr) / 2;
        double dth = (dr - dl) / trackM;
        double mid = heading + dth / 2;
        x += ds * Math.cos(mid);
        y += ds * Math.sin(mid);
        heading = Pose.normalize(heading + dth);
        distanceM += Math.abs(ds);
        return pose();
    }

    /** The pose now. */
    public Pose pose() {
        return new Pose(x, y, heading);
    }

    /** Metres travelled (by the centre, counted by the encoders) since creation. */
    public double distanceM() {
        return distanceM;
    }
}
