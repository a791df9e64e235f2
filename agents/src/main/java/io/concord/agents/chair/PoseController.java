package io.concord.agents.chair;

/**
 * Motor powers that take a differential-drive chair to a point, or to a pose, from where it
 * believes it is: turn on the spot toward the target while the heading error is large, then
 * drive with a proportional correction, slowing down on the last metre. Stateless and
 * allocation-free; call it on every report.
 */
public final class PoseController {
    /** Powers for both wheels, percent. */
    public record Powers(double left, double right) {
        /** Both zero. */
        public static final Powers STOP = new Powers(0, 0);

        /** True if both are zero. */
        public boolean stopped() {
            return left == 0 && right == 0;
        }
    }

    private final double cruisePercent;
    private final double turnPercent;
    private final double positionToleranceM;
    private final double headingToleranceRad;

    /**
     * @param cruisePercent       power when far and aligned (e.g. 60)
     * @param turnPercent         power on the spot (e.g. 30)
     * @param positionToleranceM  close enough to a point
     * @param headingToleranceRad close enough to a heading
     */
    public PoseController(double cruisePercent, double turnPercent, double positionToleranceM, double headingToleranceRad) {
        if (!(cruisePercent > 0 && cruisePercent <= 100) || !(turnPercent > 0 && turnPercent <= 100)) {
            throw new IllegalArgumentException("powers must be in (0, 100], got " + cruisePercent + " and " + turnPercent);
        }
        if (!(positionToleranceM > 0) || !(headingToleranceRad > 0)) {
            throw new IllegalArgumentException("tolerances must be positive");
        }
        this.cruisePercent = cruisePercent;
        this.turnPercent = turnPercent;
        this.positionToleranceM = positionToleranceM;
        this.headingToleranceRad = headingToleranceRad;
    }

    /** 60 % cruise, 30 % on the spot, 5 cm and 3°. */
    public static PoseController standard() {
        return new PoseController(60, 30, 0.05, Math.toRadians(3));
    }

    /** True once {@code pose} is within the position tolerance of the point. */
    public boolean reached(Pose pose, double tx, double ty) {
        return pose.distanceTo(tx, ty) <= positionToleranceM;
    }

    /** True once {@code pose} is within both tolerances of the target. */
    public boolean reached(Pose pose, Pose target) {
        return reached(pose, target.x(), target.y())
                && Math.abs(Pose.normalize(target.heading() - pose.heading())) <= headingToleranceRad;
    }

    /** Powers toward the point (tx, ty); STOP once there. Drives backwards never. */
    public Powers toPoint(Pose pose, double tx, double ty) {
        double dx = tx - pose.x();
        double dy = ty - pose.y();
        double dist = Math.hypot(dx, dy);
        if (dist <= positionToleranceM) {
            return Powers.STOP;
        }
        double err = Pose.normalize(Math.atan2(dy, dx) - pose.heading());
        if (Math.abs(err) > Math.toRadians(35)) {
            return turn(err);
        }
        double forward = cruisePercent * Math.min(1, 0.25 + dist) * Math.cos(err);
        double steer = Math.max(-turnPercent, Math.min(turnPercent, err * 2.0 * cruisePercent));
        return new Powers(clamp(forward - steer), clamp(forward + steer));
    }

    /** Powers that turn on the spot to the heading; STOP once within tolerance. */
    public Powers toHeading(Pose pose, double heading) {
        double err = Pose.normalize(heading - pose.heading());
        if (Math.abs(err) <= headingToleranceRad) {
            return Powers.STOP;
        }
        return turn(err);
    }

    /** To the target's position, then to its heading. */
    public Powers toPose(Pose pose, Pose target) {
        Powers p = toPoint(pose, target.x(), target.y());
        return p.stopped() ? toHeading(pose, target.heading()) : p;
    }

    private Powers turn(double err) {
        // Slow down on the last 20 degrees, so that the chair does not swing past the heading.
        double p = turnPercent * Math.max(0.3, Math.min(1, Math.abs(err) / Math.toRadians(20)));
        return err > 0 ? new Powers(-p, p) : new Powers(p, -p);
    }

    private static double clamp(double p) {
        return Math.max(-100, Math.min(100, p));
    }
}
