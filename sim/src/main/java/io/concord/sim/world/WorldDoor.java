package io.concord.sim.world;

import io.concord.agents.door.DoorDriver;
import io.concord.agents.door.DoorListener;
import io.concord.agents.map.Door;
import io.concord.agents.map.Point;

import org.jbox2d.collision.WorldManifold;
import org.jbox2d.collision.shapes.CircleShape;
import org.jbox2d.collision.shapes.PolygonShape;
import org.jbox2d.collision.shapes.Shape;
import org.jbox2d.common.Vec2;
import org.jbox2d.dynamics.Body;
import org.jbox2d.dynamics.contacts.ContactEdge;
import org.jbox2d.dynamics.joints.PrismaticJoint;
import org.jbox2d.dynamics.joints.RevoluteJoint;

import java.util.ArrayList;
import java.util.List;

/**
 * A door of the map as a moving body: a hinged leaf that swings a quarter turn, a sliding leaf,
 * or a revolving leaf on a central pivot. It gives the door agent the motion (open, close, halt)
 * and the sensing (where the leaf is, whether it met something, what is in the doorway and in
 * the leaf's sweep); the agent owns the state machine. A leaf that meets a chair or an obstacle
 * while moving stops where it is and reports the contact; it never pushes on.
 *
 * <p>Confined to the thread that steps the world.
 */
public final class WorldDoor implements DoorDriver {

    /** Half the depth of the doorway zone, each side of the wall, metres. */
    static final double DOORWAY_DEPTH_M = 0.7;
    private static final double LEAF_THICKNESS_M = 0.05;
    private static final double SWING_SPEED_RAD_S = 1.0;
    private static final double SLIDE_SPEED_M_S = 0.6;
    private static final double REVOLVE_SPEED_RAD_S = 0.7;
    private static final double GAIN = 4.0;
    private static final double ARRIVED_RAD = 0.005;
    private static final double ARRIVED_M = 0.003;

    private final HospitalWorld world;
    private final Door spec;
    final Body leaf;
    private final RevoluteJoint hinge;
    private final PrismaticJoint slide;
    /** +1 if the hinged leaf opens counter-clockwise, -1 if clockwise. */
    private final int swingSign;
    private final double travel;

    private double target;
    private float motorSpeed;
    private Motion motion = Motion.STILL;
    private boolean blocked;
    private String lastContact;
    private long contacts;
    private boolean mechanismFailed;
    private DoorListener listener;
    private long listenerFailures;

    private final Shape doorwayShape;
    private final Shape sweepShape;
    private final WorldManifold manifold = new WorldManifold();
    private final Vec2 rel = new Vec2();

    WorldDoor(HospitalWorld world, Door spec, Body leaf, RevoluteJoint hinge, PrismaticJoint slide, int swingSign) {
        this.world = world;
        this.spec = spec;
        this.leaf = leaf;
        this.hinge = hinge;
        this.slide = slide;
        this.swingSign = swingSign;
        this.travel = switch (spec.kind()) {
            case HINGED -> Math.PI / 2;
            case SLIDING -> spec.width();
            case ROTATING -> Math.PI / 2;
        };
        this.doorwayShape = doorwayZone(spec);
        this.sweepShape = sweepZone(spec, swingSign);
    }

    // ---- commands -------------------------------------------------------------------------------

    /** The world's time. */
    @Override
    public long nowNs() {
        return world.worldTimeNs();
    }

    /** Starts opening (or keeps opening); a revolving door turns on the same way. Ignored while the mechanism has failed. */
    @Override
    public void open() {
        world.onLoop("door " + spec.id() + ": open");
        if (mechanismFailed) {
            return;
        }
        blocked = false;
        target = switch (spec.kind()) {
            case HINGED -> swingSign * Math.PI / 2;
            case SLIDING -> spec.width();
            case ROTATING -> nextRevolveStop(Math.PI / 2);
        };
        motion = Motion.OPENING;
        wake();
    }

    /** Starts closing. Ignored while the mechanism has failed. */
    @Override
    public void close() {
        world.onLoop("door " + spec.id() + ": close");
        if (mechanismFailed) {
            return;
        }
        blocked = false;
        target = spec.kind() == Door.Kind.ROTATING ? nextRevolveStop(0) : 0;
        motion = Motion.CLOSING;
        wake();
    }

    /** Stops the leaf where it is, and holds it there. */
    @Override
    public void halt() {
        world.onLoop("door " + spec.id() + ": halt");
        target = position();
        motion = Motion.STILL;
    }

    /**
     * Fails the door's mechanism (true) or repairs it: a failed door ignores commands and its leaf
     * stands where it is; {@link #mechanismFailed()} tells the door agent, which reports OFFLINE.
     */
    public void setMechanismFailed(boolean failed) {
        mechanismFailed = failed;
        if (failed) {
            halt();
        }
    }

    /** Sets the one listener told of contacts and arrivals (replacing any before); null removes it. */
    @Override
    public void setListener(DoorListener listener) {
        this.listener = listener;
    }

    // ---- sensing --------------------------------------------------------------------------------

    /** The door of the map this is. */
    @Override
    public Door spec() {
        return spec;
    }

    /** The door's id. */
    @Override
    public String id() {
        return spec.id();
    }

    /** What the leaf is doing now. */
    @Override
    public Motion motion() {
        return motion;
    }

    /** How open the door is: 0 closed, 1 fully open. */
    @Override
    public double openFraction() {
        if (spec.kind() == Door.Kind.ROTATING) {
            double a = Math.abs(Math.IEEEremainder(position(), Math.PI));
            return Math.min(1, a / (Math.PI / 2));
        }
        return Math.max(0, Math.min(1, Math.abs(position()) / travel));
    }

    /** True if the door is open far enough to pass (at least 95 %). */
    @Override
    public boolean isOpen() {
        return openFraction() >= 0.95;
    }

    /** True if the leaf closes the opening (within 1 %). */
    @Override
    public boolean isClosed() {
        return openFraction() <= 0.01;
    }

    /** True if the leaf stopped because it met something, until the next command. */
    @Override
    public boolean blocked() {
        return blocked;
    }

    /** The name of what the leaf last met, or null. */
    @Override
    public String lastContact() {
        return lastContact;
    }

    /** Callbacks on which the listener threw (each counted; the world goes on). */
    public long listenerFailures() {
        return listenerFailures;
    }

    /** How many times the leaf has met something while moving. */
    public long contacts() {
        return contacts;
    }

    /** True while the mechanism has failed. */
    @Override
    public boolean mechanismFailed() {
        return mechanismFailed;
    }

    /** True if a chair or an obstacle is in the doorway (the opening, 0.7 m each side of the wall). */
    @Override
    public boolean doorwayOccupied() {
        return !world.overlapping(doorwayShape, null).isEmpty();
    }

    /** The chairs and obstacles in the doorway, by name. */
    @Override
    public List<String> inDoorway() {
        return world.overlapping(doorwayShape, null);
    }

    /** True if a chair or an obstacle is where the leaf moves (a swing's quarter circle, a revolving door's circle, a sliding leaf's line). */
    @Override
    public boolean sweepOccupied() {
        return !world.overlapping(sweepShape, null).isEmpty();
    }

    /** The chairs and obstacles in the leaf's sweep, by name. */
    @Override
    public List<String> inSweep() {
        return world.overlapping(sweepShape, null);
    }

    /** The two ends of the leaf now, for a picture: {x1, y1, x2, y2}. */
    public double[] leafEnds() {
        Vec2 c = leaf.getPosition();
        double a = leaf.getAngle();
        double h = leafLength() / 2;
        double cx = StrictMath.cos(a) * h;
        double cy = StrictMath.sin(a) * h;
        return new double[] {c.x - cx, c.y - cy, c.x + cx, c.y + cy};
    }

    double leafLength() {
        return spec.kind() == Door.Kind.ROTATING ? spec.width() - 0.04 : spec.width() - 0.02;
    }

    // ---- the step -------------------------------------------------------------------------------

    /** The joint's coordinate: radians for hinged and revolving doors, metres for sliding ones. */
    double position() {
        return slide != null ? slide.getJointTranslation() : hinge.getJointAngle();
    }

    private double nextRevolveStop(double phase) {
        double a = position();
        double k = Math.ceil((a - phase - 0.01) / Math.PI);
        return phase + k * Math.PI;
    }

    private void wake() {
        leaf.setAwake(true);
    }

    void beforeStep() {
        if (motion == Motion.STILL && motorSpeed == 0 && !leaf.isAwake()) {
            // At rest and asleep: nothing pushes the leaf, nothing to correct.
            return;
        }
        double err = target - position();
        double max = slide != null ? SLIDE_SPEED_M_S
                : spec.kind() == Door.Kind.ROTATING ? REVOLVE_SPEED_RAD_S : SWING_SPEED_RAD_S;
        double speed = Math.max(-max, Math.min(max, GAIN * err));
        if (motion == Motion.STILL && Math.abs(err) <= (slide != null ? ARRIVED_M : ARRIVED_RAD)) {
            speed = 0;
        }
        // Setting a joint's motor speed wakes its bodies: only when it changes, so that a leaf
        // at rest sleeps and costs the solver nothing.
        if ((float) speed != motorSpeed) {
            motorSpeed = (float) speed;
            if (slide != null) {
                slide.setMotorSpeed(motorSpeed);
            } else {
                hinge.setMotorSpeed(motorSpeed);
            }
        }
    }

    void afterStep() {
        if (motion == Motion.STILL) {
            return;
        }
        double err = target - position();
        if (Math.abs(err) <= (slide != null ? ARRIVED_M : ARRIVED_RAD)) {
            motion = Motion.STILL;
            if (listener != null) {
                try {
                    listener.onArrived(this);
                } catch (RuntimeException e) {
                    listenerFailures++;
                }
            }
            return;
        }
        String met = pushingInto(Math.signum(err));
        if (met != null) {
            halt();
            blocked = true;
            lastContact = met;
            contacts++;
            if (listener != null) {
                try {
                    listener.onContact(this, met);
                } catch (RuntimeException e) {
                    listenerFailures++;
                }
            }
        }
    }

    /**
     * The name of a chair or obstacle the leaf touches on the side it is moving toward, or null.
     * The leaf's intended motion at each contact point is compared with the contact normal.
     */
    private String pushingInto(double direction) {
        for (ContactEdge e = leaf.getContactList(); e != null; e = e.next) {
            if (!e.contact.isTouching() || !(e.other.getUserData() instanceof Thing t) || !t.isSolidMover()) {
                continue;
            }
            e.contact.getWorldManifold(manifold);
            boolean leafIsA = e.contact.getFixtureA().getBody() == leaf;
            float nx = leafIsA ? manifold.normal.x : -manifold.normal.x;
            float ny = leafIsA ? manifold.normal.y : -manifold.normal.y;
            int points = e.contact.getManifold().pointCount;
            for (int i = 0; i < points; i++) {
                Vec2 p = manifold.points[i];
                double vx;
                double vy;
                if (slide != null) {
                    Vec2 axis = slide.getLocalAxisA();
                    vx = axis.x * direction;
                    vy = axis.y * direction;
                } else {
                    hinge.getAnchorA(rel);
                    vx = -(p.y - rel.y) * direction;
                    vy = (p.x - rel.x) * direction;
                }
                if (vx * nx + vy * ny > 1e-6) {
                    return t.name;
                }
            }
        }
        return null;
    }

    // ---- zones ----------------------------------------------------------------------------------

    private static Shape doorwayZone(Door d) {
        return strip(d, DOORWAY_DEPTH_M);
    }

    /** The opening widened by {@code halfDepth} metres each side of the wall's line. */
    private static Shape strip(Door d, double halfDepth) {
        double ux = (d.to().x() - d.from().x()) / d.width();
        double uy = (d.to().y() - d.from().y()) / d.width();
        double nx = -uy * halfDepth;
        double ny = ux * halfDepth;
        Point a = d.from();
        Point b = d.to();
        PolygonShape s = new PolygonShape();
        s.set(new Vec2[] {
            v(a.x() - nx, a.y() - ny), v(b.x() - nx, b.y() - ny), v(b.x() + nx, b.y() + ny), v(a.x() + nx, a.y() + ny)
        }, 4);
        return s;
    }

    private static Shape sweepZone(Door d, int swingSign) {
        switch (d.kind()) {
            case ROTATING -> {
                CircleShape c = new CircleShape();
                c.m_p.set((float) d.centre().x(), (float) d.centre().y());
                c.m_radius = (float) (d.width() / 2);
                return c;
            }
            case SLIDING -> {
                return strip(d, 0.15);
            }
            default -> {
                Point h = d.hingePoint();
                Point f = d.freePoint();
                double a0 = StrictMath.atan2(f.y() - h.y(), f.x() - h.x());
                double r = d.width();
                List<Vec2> pts = new ArrayList<>();
                pts.add(v(h.x(), h.y()));
                for (int i = 0; i <= 6; i++) {
                    double a = a0 + swingSign * (Math.PI / 2) * i / 6;
                    pts.add(v(h.x() + r * StrictMath.cos(a), h.y() + r * StrictMath.sin(a)));
                }
                PolygonShape s = new PolygonShape();
                s.set(pts.toArray(new Vec2[0]), pts.size());
                return s;
            }
        }
    }

    private static Vec2 v(double x, double y) {
        return new Vec2((float) x, (float) y);
    }

    @Override
    public String toString() {
        return "WorldDoor[" + spec.id() + " " + spec.kind() + " " + motion + String.format(java.util.Locale.ROOT, " %.0f%% open", 100 * openFraction())
                + (blocked ? " blocked by " + lastContact : "") + "]";
    }
}
