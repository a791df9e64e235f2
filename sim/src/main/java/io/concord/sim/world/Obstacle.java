package io.concord.sim.world;

import io.concord.agents.map.Point;

import org.jbox2d.common.Vec2;
import org.jbox2d.dynamics.Body;

import java.util.List;

/**
 * Something in the way that is not part of the building: a static box or round thing (a bed, a
 * trolley), or a person walking a path of points at a steady pace. Added and removed while the
 * world runs, so that a test or the demo can block a corridor.
 */
public final class Obstacle {
    /** The kinds of obstacle. */
    public enum Kind { BOX, ROUND, PERSON }

    private static final double PERSON_FORCE_N = 250;

    private final HospitalWorld world;
    private final String name;
    private final Kind kind;
    final Body body;
    private final double sizeX;
    private final double sizeY;
    private final List<Point> path;
    private final double speedMps;
    private final boolean loop;
    private int nextPoint;
    private boolean removed;
    private final Vec2 tmp = new Vec2();

    Obstacle(HospitalWorld world, String name, Kind kind, Body body, double sizeX, double sizeY, List<Point> path,
             double speedMps, boolean loop) {
        this.world = world;
        this.name = name;
        this.kind = kind;
        this.body = body;
        this.sizeX = sizeX;
        this.sizeY = sizeY;
        this.path = path == null ? List.of() : List.copyOf(path);
        this.speedMps = speedMps;
        this.loop = loop;
        this.nextPoint = this.path.size() > 1 ? 1 : 0;
    }

    /** Its name. */
    public String name() {
        return name;
    }

    /** What it is. */
    public Kind kind() {
        return kind;
    }

    /** Where its centre is now. */
    public Point position() {
        Vec2 p = body.getPosition();
        return new Point(p.x, p.y);
    }

    /** Its heading now, radians. */
    public double angle() {
        return body.getAngle();
    }

    /** For a box its length and width, for a round thing or a person its diameter twice. */
    public double[] size() {
        return new double[] {sizeX, sizeY};
    }

    /** True once a walking person has reached the end of a path that does not loop. */
    public boolean arrived() {
        return kind == Kind.PERSON && !loop && nextPoint >= path.size();
    }

    /** Takes it out of the world. */
    public void remove() {
        if (!removed) {
            removed = true;
            world.removeObstacle(this);
        }
    }

    /** True once removed. */
    public boolean removed() {
        return removed;
    }

    void beforeStep(double dt) {
        if (kind != Kind.PERSON) {
            return;
        }
        double vx = 0;
        double vy = 0;
        if (nextPoint < path.size()) {
            Point target = path.get(nextPoint);
            Vec2 p = body.getPosition();
            double dx = target.x() - p.x;
            double dy = target.y() - p.y;
            double d = Math.hypot(dx, dy);
            if (d < 0.1) {
                nextPoint++;
                if (nextPoint >= path.size() && loop) {
                    nextPoint = 0;
                }
            } else {
                double v = Math.min(speedMps, d * 2);
                vx = dx / d * v;
                vy = dy / d * v;
            }
        }
        Vec2 vel = body.getLinearVelocity();
        double m = body.getMass();
        double bound = PERSON_FORCE_N * dt;
        tmp.set((float) clamp(m * (vx - vel.x), bound), (float) clamp(m * (vy - vel.y), bound));
        body.applyLinearImpulse(tmp, body.getWorldCenter());
    }

    private static double clamp(double v, double b) {
        return Math.max(-b, Math.min(b, v));
    }

    @Override
    public String toString() {
        return "Obstacle[" + name + " " + kind + " at " + position() + "]";
    }
}
