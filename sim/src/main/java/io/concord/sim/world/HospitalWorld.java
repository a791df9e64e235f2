package io.concord.sim.world;

import io.concord.agents.chair.Pose;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.layer.Tracer;
import io.concord.agents.map.Door;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Node;
import io.concord.agents.map.Point;
import io.concord.agents.map.Wall;

import org.jbox2d.callbacks.ContactImpulse;
import org.jbox2d.callbacks.ContactListener;
import org.jbox2d.collision.AABB;
import org.jbox2d.collision.Manifold;
import org.jbox2d.collision.WorldManifold;
import org.jbox2d.collision.shapes.CircleShape;
import org.jbox2d.collision.shapes.PolygonShape;
import org.jbox2d.collision.shapes.Shape;
import org.jbox2d.common.Transform;
import org.jbox2d.common.Vec2;
import org.jbox2d.dynamics.Body;
import org.jbox2d.dynamics.BodyDef;
import org.jbox2d.dynamics.BodyType;
import org.jbox2d.dynamics.Fixture;
import org.jbox2d.dynamics.FixtureDef;
import org.jbox2d.dynamics.World;
import org.jbox2d.dynamics.contacts.Contact;
import org.jbox2d.dynamics.joints.PrismaticJoint;
import org.jbox2d.dynamics.joints.PrismaticJointDef;
import org.jbox2d.dynamics.joints.RevoluteJoint;
import org.jbox2d.dynamics.joints.RevoluteJointDef;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;

/**
 * The hospital as a physical world: the map's walls, its doors as moving leaves, chairs that
 * drive, and obstacles, stepped at a fixed rate (60 Hz by default).
 *
 * <p>One clock: {@link #attach(AgentRuntime)} steps the world on the runtime's loop at the
 * runtime's clock, so that on a runtime with the system clock it runs in real time (or
 * {@code speedup} times faster), and inside the test kit's {@code Simulation} as fast as the CPU
 * allows, the same seed giving the same run, physics and messages together: every step adds
 * every chair's and door's pose to the runtime's trace. {@link #step()} steps it by hand.
 *
 * <pre>{@code
 * HospitalWorld world = HospitalWorld.builder(HospitalMap.defaultHospital()).seed(42).build();
 * SimChair chair = world.addChair("chair1", ChairConfig.standard(), world.poseAt(19, 0));
 * world.attach(runtime);                 // steps on the runtime's loop from now on
 * chair.drive(50, 50);                   // on the loop
 * }</pre>
 *
 * <p>Confined to one thread: the loop it is attached to, or the caller that steps it.
 */
public final class HospitalWorld {
    /** Collisions kept for pictures and tests; older ones are dropped. */
    static final int COLLISIONS_KEPT = 1_000;
    private static final int VELOCITY_ITERATIONS = 8;
    private static final int POSITION_ITERATIONS = 3;

    private final HospitalMap map;
    private final java.util.List<io.concord.agents.map.Point> markers;
    private final double stepHz;
    private final double dtS;
    private final float dt;
    private final SplittableRandom random;
    private final World world;
    private final Body ground;
    /** The floor the chairs' brakes hold on to: a body of its own, since a joint stops its bodies colliding. */
    private final Body floor;
    private final Map<String, WorldDoor> doors = new LinkedHashMap<>();
    private final List<WorldDoor> doorList = new ArrayList<>();
    private final Map<String, SimChair> chairs = new LinkedHashMap<>();
    private final List<SimChair> chairList = new ArrayList<>();
    private final Map<String, Obstacle> obstacles = new LinkedHashMap<>();
    private final List<Obstacle> obstacleList = new ArrayList<>();
    private final List<Runnable> stepHooks = new ArrayList<>();
    private final ArrayDeque<Collision> collisions = new ArrayDeque<>();
    private long collisionCount;
    private long steps;
    private long nowNs;
    private Tracer tracer = Tracer.NONE;

    // scratch
    private final Vec2 from = new Vec2();
    private final Vec2 to = new Vec2();
    private final AABB aabb = new AABB();
    private final Transform identity = new Transform();
    private final WorldManifold manifold = new WorldManifold();

    private HospitalWorld(Builder b) {
        this.map = b.map;
        this.markers = java.util.List.copyOf(b.edgeMarkers ? b.map.markers() : b.map.nodeMarkers());
        this.stepHz = b.stepHz;
        this.dtS = 1.0 / b.stepHz;
        this.dt = (float) dtS;
        this.random = new SplittableRandom(b.seed);
        this.world = new World(new Vec2(0, 0));
        world.setAllowSleep(true);
        world.setContactListener(new Contacts());
        identity.setIdentity();
        BodyDef gd = new BodyDef();
        gd.type = BodyType.STATIC;
        this.ground = world.createBody(gd);
        this.floor = world.createBody(gd);
        ground.setUserData(new Thing(Thing.Kind.WALL, "wall", null));
        for (Wall w : map.walls()) {
            PolygonShape s = new PolygonShape();
            double cx = (w.from().x() + w.to().x()) / 2;
            double cy = (w.from().y() + w.to().y()) / 2;
            float angle = (float) StrictMath.atan2(w.to().y() - w.from().y(), w.to().x() - w.from().x());
            s.setAsBox((float) (w.length() / 2), (float) (w.thicknessM() / 2), new Vec2((float) cx, (float) cy), angle);
            FixtureDef fd = new FixtureDef();
            fd.shape = s;
            fd.friction = 0.3f;
            fd.filter.categoryBits = Thing.WALL_BIT;
            fd.filter.maskBits = Thing.CHAIR_BIT | Thing.OBSTACLE_BIT;
            ground.createFixture(fd);
        }
        if (b.doors) {
            for (Door d : map.doors()) {
                WorldDoor door = buildDoor(d);
                doors.put(d.id(), door);
                doorList.add(door);
            }
        }
    }

    /** A builder for a world of this map. */
    public static Builder builder(HospitalMap map) {
        return new Builder(map);
    }

    /** Settings of a world, checked when built. */
    public static final class Builder {
        private final HospitalMap map;
        private long seed = 1;
        private double stepHz = 60;
        private boolean doors = true;
        private boolean edgeMarkers = true;

        private Builder(HospitalMap map) {
            if (map == null) {
                throw new IllegalArgumentException("a world needs a map (HospitalMap.defaultHospital() is one)");
            }
            this.map = map;
        }

        /** The seed every noise of the world is drawn from (default 1). */
        public Builder seed(long seed) {
            this.seed = seed;
            return this;
        }

        /** Steps a second of world time (default 60). */
        public Builder stepHz(double hz) {
            if (!(hz >= 10 && hz <= 1000)) {
                throw new IllegalArgumentException("stepHz must be 10 to 1000, got " + hz);
            }
            this.stepHz = hz;
            return this;
        }

        /** Whether the map's doors are built as moving leaves (default true); false leaves the gaps open. */
        public Builder doors(boolean doors) {
            this.doors = doors;
            return this;
        }

        /**
         * Test-only: {@code false} lays floor markers at the nodes alone, none along the long
         * edges ({@link HospitalMap#edgeMarkers()}), so that a test can show what the markers
         * along them prevent. Never for a hospital.
         */
        public Builder edgeMarkers(boolean on) {
            this.edgeMarkers = on;
            return this;
        }

        /** The world. */
        public HospitalWorld build() {
            return new HospitalWorld(this);
        }
    }

    // ---- contents -------------------------------------------------------------------------------

    /** The map the world was built from. */
    public HospitalMap map() {
        return map;
    }

    /** The floor markers a chair reads here: the map's ({@link HospitalMap#markers()}). */
    public java.util.List<io.concord.agents.map.Point> markers() {
        return markers;
    }

    /** Steps a second of world time. */
    public double stepHz() {
        return stepHz;
    }

    /** Steps taken so far. */
    public long stepCount() {
        return steps;
    }

    /** World time: the steps taken, in nanoseconds. */
    public long worldTimeNs() {
        return Math.round(steps * 1e9 / stepHz);
    }

    /** The pose of a node of the map, facing {@code headingDeg} degrees from east. */
    public Pose poseAt(int node, double headingDeg) {
        Node n = map.node(node);
        return new Pose(n.at().x(), n.at().y(), Math.toRadians(headingDeg));
    }

    /**
     * Puts a chair in the world.
     *
     * @throws IllegalArgumentException if the name is taken or the chair would stand inside
     *                                  something (naming what)
     */
    public SimChair addChair(String name, ChairConfig config, Pose start) {
        onLoop("addChair");
        checkName(name);
        if (chairs.containsKey(name)) {
            throw new IllegalArgumentException("there is a chair named '" + name + "' already");
        }
        var layout = config.layout();
        PolygonShape shape = new PolygonShape();
        shape.setAsBox((float) (layout.lengthM() / 2), (float) (layout.widthM() / 2));
        Transform xf = new Transform();
        xf.set(new Vec2((float) start.x(), (float) start.y()), (float) start.heading());
        List<String> in = overlapping(shape, xf, true);
        if (!in.isEmpty()) {
            throw new IllegalArgumentException("chair '" + name + "' cannot start at " + start + ": it would stand inside "
                    + String.join(", ", in) + "; choose a free place (a node of the map is one)");
        }
        BodyDef bd = new BodyDef();
        bd.type = BodyType.DYNAMIC;
        bd.position.set((float) start.x(), (float) start.y());
        bd.angle = (float) start.heading();
        bd.allowSleep = false;
        Body body = world.createBody(bd);
        FixtureDef fd = new FixtureDef();
        fd.shape = shape;
        fd.density = (float) (config.massKg() / (layout.lengthM() * layout.widthM()));
        fd.friction = 0.3f;
        fd.restitution = 0f;
        fd.filter.categoryBits = Thing.CHAIR_BIT;
        fd.filter.maskBits = Thing.WALL_BIT | Thing.LEAF_BIT | Thing.CHAIR_BIT | Thing.OBSTACLE_BIT;
        body.createFixture(fd);
        // The brakes: friction against the floor, solved inside the step (an impulse before it would
        // let a push creep the chair along); its force is set each step, grip while the wheels stand.
        org.jbox2d.dynamics.joints.FrictionJointDef brake = new org.jbox2d.dynamics.joints.FrictionJointDef();
        brake.initialize(floor, body, body.getWorldCenter());
        brake.maxForce = 0;
        brake.maxTorque = 0;
        var brakeJoint = (org.jbox2d.dynamics.joints.FrictionJoint) world.createJoint(brake);
        SimChair chair = new SimChair(this, name, config, body, brakeJoint, start, random.split());
        body.setUserData(new Thing(Thing.Kind.CHAIR, name, chair));
        chairs.put(name, chair);
        chairList.add(chair);
        return chair;
    }

    /** The chair with this name. */
    public SimChair chair(String name) {
        SimChair c = chairs.get(name);
        if (c == null) {
            throw new IllegalArgumentException("no chair named '" + name + "'; chairs: " + chairs.keySet());
        }
        return c;
    }

    /** Every chair, in the order added. */
    public List<SimChair> chairs() {
        return Collections.unmodifiableList(chairList);
    }

    /** Takes a chair out of the world (its driver goes offline). */
    public void removeChair(String name) {
        onLoop("removeChair");
        SimChair c = chair(name);
        chairs.remove(name);
        chairList.remove(c);
        world.destroyBody(c.body);
        c.markRemoved();
    }

    /** The door with this id. */
    public WorldDoor door(String id) {
        WorldDoor d = doors.get(id);
        if (d == null) {
            throw new IllegalArgumentException("no door '" + id + "' in this world; doors: " + doors.keySet());
        }
        return d;
    }

    /** Every door, in map order. */
    public List<WorldDoor> doors() {
        return Collections.unmodifiableList(doorList);
    }

    /** A static box (a bed, a trolley): centre, length along {@code angleDeg}, width across. */
    public Obstacle addBox(String name, Point centre, double lengthM, double widthM, double angleDeg) {
        onLoop("addBox");
        checkObstacle(name, lengthM, widthM);
        PolygonShape s = new PolygonShape();
        s.setAsBox((float) (lengthM / 2), (float) (widthM / 2));
        return addObstacle(name, Obstacle.Kind.BOX, BodyType.STATIC, s, centre, Math.toRadians(angleDeg), 0, lengthM,
                widthM, null, 0, false);
    }

    /** A static round thing of a diameter. */
    public Obstacle addRound(String name, Point centre, double diameterM) {
        checkObstacle(name, diameterM, diameterM);
        CircleShape s = new CircleShape();
        s.m_radius = (float) (diameterM / 2);
        return addObstacle(name, Obstacle.Kind.ROUND, BodyType.STATIC, s, centre, 0, 0, diameterM, diameterM, null, 0, false);
    }

    /**
     * A person (0.5 m across, 70 kg) who walks the path at a pace, again and again if
     * {@code loop}, and can be pushed and blocked like anything else.
     */
    public Obstacle addPerson(String name, List<Point> path, double speedMps, boolean loop) {
        onLoop("addPerson");
        checkObstacle(name, 0.5, 0.5);
        if (path == null || path.isEmpty()) {
            throw new IllegalArgumentException("person '" + name + "' needs a path of at least one point");
        }
        if (!(speedMps > 0 && speedMps <= 3)) {
            throw new IllegalArgumentException("person '" + name + "': speed must be in (0, 3] m/s, got " + speedMps);
        }
        CircleShape s = new CircleShape();
        s.m_radius = 0.25f;
        return addObstacle(name, Obstacle.Kind.PERSON, BodyType.DYNAMIC, s, path.get(0), 0,
                70 / (Math.PI * 0.25 * 0.25), 0.5, 0.5, path, speedMps, loop);
    }

    private void checkObstacle(String name, double a, double b) {
        checkName(name);
        if (obstacles.containsKey(name) || chairs.containsKey(name)) {
            throw new IllegalArgumentException("the name '" + name + "' is taken");
        }
        if (!(a > 0 && b > 0 && a < 50 && b < 50)) {
            throw new IllegalArgumentException("obstacle '" + name + "': sizes must be in (0, 50) m, got " + a + " and " + b);
        }
    }

    private static void checkName(String name) {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("a name must not be empty");
        }
    }

    private Obstacle addObstacle(String name, Obstacle.Kind kind, BodyType type, Shape shape, Point at, double angle,
                                 double density, double sx, double sy, List<Point> path, double speed, boolean loop) {
        BodyDef bd = new BodyDef();
        bd.type = type;
        bd.position.set((float) at.x(), (float) at.y());
        bd.angle = (float) angle;
        bd.fixedRotation = kind == Obstacle.Kind.PERSON;
        bd.allowSleep = kind != Obstacle.Kind.PERSON;
        bd.linearDamping = kind == Obstacle.Kind.PERSON ? 0.5f : 0f;
        Body body = world.createBody(bd);
        FixtureDef fd = new FixtureDef();
        fd.shape = shape;
        fd.density = (float) density;
        fd.friction = 0.3f;
        fd.filter.categoryBits = Thing.OBSTACLE_BIT;
        fd.filter.maskBits = Thing.WALL_BIT | Thing.LEAF_BIT | Thing.CHAIR_BIT | Thing.OBSTACLE_BIT;
        body.createFixture(fd);
        Obstacle o = new Obstacle(this, name, kind, body, sx, sy, path, speed, loop);
        body.setUserData(new Thing(Thing.Kind.OBSTACLE, name, o));
        obstacles.put(name, o);
        obstacleList.add(o);
        return o;
    }

    void removeObstacle(Obstacle o) {
        obstacles.remove(o.name());
        obstacleList.remove(o);
        world.destroyBody(o.body);
    }

    /** The obstacle with this name. */
    public Obstacle obstacle(String name) {
        Obstacle o = obstacles.get(name);
        if (o == null) {
            throw new IllegalArgumentException("no obstacle named '" + name + "'");
        }
        return o;
    }

    /** Every obstacle, in the order added. */
    public List<Obstacle> obstacles() {
        return Collections.unmodifiableList(obstacleList);
    }

    /** The last collisions of chairs with anything (at most 1,000), oldest first. */
    public List<Collision> collisions() {
        return new ArrayList<>(collisions);
    }

    /** Collisions of chairs with anything since the start. */
    public long collisionCount() {
        return collisionCount;
    }

    /** Runs a hook on every step, before the physics (a test's or a benchmark's driver). */
    public void addStepHook(Runnable hook) {
        stepHooks.add(hook);
    }

    // ---- time -----------------------------------------------------------------------------------

    /** One step of 1/stepHz seconds, by hand. */
    public void step() {
        stepAt(worldTimeNs());
    }

    /** Steps for a duration of world time, by hand. */
    public void run(double seconds) {
        long n = Math.round(seconds * stepHz);
        for (long i = 0; i < n; i++) {
            step();
        }
    }

    private void stepAt(long platformNs) {
        nowNs = platformNs;
        for (int i = 0; i < stepHooks.size(); i++) {
            stepHooks.get(i).run();
        }
        for (int i = 0; i < chairList.size(); i++) {
            chairList.get(i).beforeStep(dtS);
        }
        for (int i = 0; i < doorList.size(); i++) {
            doorList.get(i).beforeStep();
        }
        for (int i = 0; i < obstacleList.size(); i++) {
            obstacleList.get(i).beforeStep(dtS);
        }
        world.step(dt, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
        steps++;
        for (int i = 0; i < doorList.size(); i++) {
            doorList.get(i).afterStep();
        }
        for (int i = 0; i < chairList.size(); i++) {
            chairList.get(i).afterStep(steps, platformNs);
        }
        if (tracer.enabled()) {
            tracer.trace(platformNs, "world", "step", Long.toHexString(poseHash()));
        }
    }

    /**
     * Steps the world on the runtime's loop, at the runtime's clock, in real time.
     *
     * @see #attach(AgentRuntime, double)
     */
    public Attachment attach(AgentRuntime runtime) {
        return attach(runtime, 1.0);
    }

    /**
     * Steps the world on the runtime's loop at {@code speedup} times its clock's pace: a step
     * every 1/(stepHz x speedup) seconds of the runtime's clock. On a virtual clock the loop jumps
     * from step to step, as fast as the CPU allows. Every step is traced to the runtime's tracer
     * with a hash of every chair's and door's pose. A loop that falls more than ten steps behind
     * skips ahead and counts the steps it lost.
     */
    public Attachment attach(AgentRuntime runtime, double speedup) {
        if (!(speedup > 0 && speedup <= 10_000)) {
            throw new IllegalArgumentException("speedup must be in (0, 10000], got " + speedup);
        }
        Attachment a = new Attachment(runtime, speedup);
        owner = runtime;
        if (runtime.inLoop()) {
            a.begin();
        } else {
            runtime.execute(a::begin);
        }
        return a;
    }

    /** The runtime whose loop steps the world since {@link #attach}, or null. */
    private volatile AgentRuntime owner;

    /**
     * Refuses a change of the world from another thread than the loop that steps it (jbox2d is not
     * thread-safe: a box added from the main thread while the loop stepped threw inside it).
     */
    void onLoop(String what) {
        AgentRuntime o = owner;
        if (o != null && !o.inLoop()) {
            throw new IllegalStateException(what + ": the world steps on its runtime's loop since attach(); change it there "
                    + "(runtime.execute(() -> ...)), or before attach()");
        }
    }

    /** The world stepping on a runtime's loop; {@link #detach()} stops it. */
    public final class Attachment {
        private static final int MAX_CATCH_UP = 10;
        private final AgentRuntime runtime;
        private final double periodNs;
        private long startNs;
        private long k;
        private long timer = -1;
        private boolean stopped;
        private long lostSteps;

        private Attachment(AgentRuntime runtime, double speedup) {
            this.runtime = runtime;
            this.periodNs = 1e9 / (stepHz * speedup);
        }

        private void begin() {
            if (stopped) {
                return;
            }
            tracer = runtime.tracer() == null ? Tracer.NONE : runtime.tracer();
            startNs = runtime.clock().nanoTime();
            k = 0;
            timer = runtime.schedule(due(), this::tick);
        }

        private long due() {
            return startNs + Math.round(k * periodNs);
        }

        private void tick() {
            if (stopped) {
                return;
            }
            long now = runtime.nowNs();
            int n = 0;
            while (due() <= now && n < MAX_CATCH_UP) {
                stepAt(due());
                k++;
                n++;
            }
            if (due() <= now) {
                long behind = (long) ((now - due()) / periodNs) + 1;
                lostSteps += behind;
                startNs += Math.round(behind * periodNs);
            }
            timer = runtime.schedule(due(), this::tick);
        }

        /** Stops stepping (on the loop). */
        public void detach() {
            if (runtime.inLoop()) {
                stop();
            } else {
                runtime.execute(this::stop);
            }
        }

        private void stop() {
            stopped = true;
            if (timer >= 0) {
                runtime.cancel(timer);
            }
        }

        /** Steps skipped because the loop fell behind (0 on a virtual clock). */
        public long lostSteps() {
            return lostSteps;
        }
    }

    /** A hash of every chair's, door's and person's pose now: equal runs give equal hashes. */
    public long poseHash() {
        long h = 0xcbf29ce484222325L;
        for (int i = 0; i < chairList.size(); i++) {
            Body b = chairList.get(i).body;
            h = mix(h, Float.floatToIntBits(b.getPosition().x));
            h = mix(h, Float.floatToIntBits(b.getPosition().y));
            h = mix(h, Float.floatToIntBits(b.getAngle()));
        }
        for (int i = 0; i < doorList.size(); i++) {
            Body b = doorList.get(i).leaf;
            h = mix(h, Float.floatToIntBits(b.getPosition().x));
            h = mix(h, Float.floatToIntBits(b.getPosition().y));
            h = mix(h, Float.floatToIntBits(b.getAngle()));
        }
        for (int i = 0; i < obstacleList.size(); i++) {
            Body b = obstacleList.get(i).body;
            h = mix(h, Float.floatToIntBits(b.getPosition().x));
            h = mix(h, Float.floatToIntBits(b.getPosition().y));
        }
        return h;
    }

    private static long mix(long h, int v) {
        for (int i = 0; i < 4; i++) {
            h ^= (v >>> (8 * i)) & 0xff;
            h *= 0x100000001b3L;
        }
        return h;
    }

    // ---- sensing (for chairs and doors) ---------------------------------------------------------

    /** Distance to the nearest thing along a ray from (ox, oy), or infinity within {@code range}. */
    double castRay(SimChair self, double ox, double oy, double dx, double dy, double range, SimChair.RayHit hit,
                   Vec2 a, Vec2 b) {
        a.set((float) ox, (float) oy);
        b.set((float) (ox + dx * range), (float) (oy + dy * range));
        hit.self = self.body;
        hit.fraction = 1.0f;
        hit.hitAny = false;
        world.raycast(hit, a, b);
        return hit.hitAny ? hit.fraction * range : Double.POSITIVE_INFINITY;
    }

    /**
     * What a chair of this layout standing at {@code pose} would read on each range sensor, without
     * noise: the walls, doors, obstacles and chairs of this world (for a chair that is not in it:
     * the augmented mode adds these to a real chair's readings). Nothing seen reads as the
     * sensor's maximum range.
     */
    public double[] rangesAt(Pose pose, io.concord.agents.chair.ChairLayout layout, int sonarRays) {
        double[] out = new double[layout.sensors().size()];
        SimChair.RayHit h = new SimChair.RayHit();
        Vec2 a = new Vec2();
        Vec2 b = new Vec2();
        double c = StrictMath.cos(pose.heading());
        double sn = StrictMath.sin(pose.heading());
        for (int i = 0; i < out.length; i++) {
            io.concord.agents.chair.SensorMount s = layout.sensors().get(i);
            double ox = pose.x() + s.x() * c - s.y() * sn;
            double oy = pose.y() + s.x() * sn + s.y() * c;
            int rays = s.kind() == io.concord.agents.chair.SensorMount.Kind.SONAR ? sonarRays : 1;
            double nearest = s.maxRangeM();
            for (int r = 0; r < rays; r++) {
                double dir = pose.heading() + s.direction() + (rays == 1 ? 0 : -s.coneRad() / 2 + s.coneRad() * r / (rays - 1));
                a.set((float) ox, (float) oy);
                b.set((float) (ox + StrictMath.cos(dir) * s.maxRangeM()), (float) (oy + StrictMath.sin(dir) * s.maxRangeM()));
                h.self = null;
                h.fraction = 1.0f;
                h.hitAny = false;
                world.raycast(h, a, b);
                if (h.hitAny) {
                    nearest = Math.min(nearest, Math.max(s.minRangeM(), h.fraction * s.maxRangeM()));
                }
            }
            out[i] = nearest;
        }
        return out;
    }

    /** The names of the chairs and obstacles overlapping a shape placed in world coordinates. */
    List<String> overlapping(Shape shape, Transform xf) {
        return overlapping(shape, xf == null ? identity : xf, false);
    }

    private List<String> overlapping(Shape shape, Transform xf, boolean everything) {
        shape.computeAABB(aabb, xf, 0);
        List<String> names = new ArrayList<>();
        org.jbox2d.collision.Collision collision = world.getPool().getCollision();
        world.queryAABB(fixture -> {
            if (fixture.getBody().getUserData() instanceof Thing t && (everything || t.isSolidMover())
                    && collision.testOverlap(shape, 0, fixture.getShape(), 0, xf, fixture.getBody().getTransform())) {
                String n = t.kind == Thing.Kind.WALL ? wallName(fixture) : t.kind == Thing.Kind.LEAF ? "door " + t.name : t.name;
                if (!names.contains(n)) {
                    names.add(n);
                }
            }
            return true;
        }, aabb);
        return names;
    }

    private String wallName(Fixture f) {
        int i = 0;
        for (Fixture g = ground.getFixtureList(); g != null; g = g.getNext()) {
            if (g == f) {
                // Fixtures are kept newest first.
                return "wall '" + map.walls().get(map.walls().size() - 1 - i).id() + "'";
            }
            i++;
        }
        return "a wall";
    }

    // ---- building -------------------------------------------------------------------------------

    private WorldDoor buildDoor(Door d) {
        Point h = d.hingePoint();
        Point f = d.freePoint();
        double w = d.width();
        double ux = (f.x() - h.x()) / w;
        double uy = (f.y() - h.y()) / w;
        float angle = (float) StrictMath.atan2(uy, ux);
        BodyDef bd = new BodyDef();
        bd.type = BodyType.DYNAMIC;
        bd.angle = angle;
        bd.angularDamping = 2f;
        bd.linearDamping = 2f;
        double leafLen;
        if (d.kind() == Door.Kind.HINGED) {
            leafLen = w - 0.02;
            bd.position.set((float) (h.x() + ux * (0.01 + leafLen / 2)), (float) (h.y() + uy * (0.01 + leafLen / 2)));
        } else {
            leafLen = d.kind() == Door.Kind.ROTATING ? w - 0.04 : w - 0.02;
            bd.position.set((float) d.centre().x(), (float) d.centre().y());
        }
        Body leaf = world.createBody(bd);
        PolygonShape s = new PolygonShape();
        s.setAsBox((float) (leafLen / 2), 0.025f);
        FixtureDef fd = new FixtureDef();
        fd.shape = s;
        fd.density = (float) (20 / (leafLen * 0.05));
        fd.friction = 0.2f;
        fd.filter.categoryBits = Thing.LEAF_BIT;
        fd.filter.maskBits = Thing.CHAIR_BIT | Thing.OBSTACLE_BIT;
        leaf.createFixture(fd);
        RevoluteJoint hinge = null;
        PrismaticJoint slide = null;
        int sign = 1;
        switch (d.kind()) {
            case HINGED -> {
                // Opening turns the leaf toward the swing side: counter-clockwise when that side is
                // on the left of the leaf's direction from its hinge.
                boolean hingeAtFrom = d.hinge() == Door.End.FROM;
                sign = hingeAtFrom == (d.swing() == Door.Side.LEFT) ? 1 : -1;
                RevoluteJointDef jd = new RevoluteJointDef();
                jd.initialize(ground, leaf, new Vec2((float) h.x(), (float) h.y()));
                jd.enableLimit = true;
                jd.lowerAngle = sign > 0 ? 0f : (float) (-Math.PI / 2);
                jd.upperAngle = sign > 0 ? (float) (Math.PI / 2) : 0f;
                jd.enableMotor = true;
                jd.maxMotorTorque = 200f;
                hinge = (RevoluteJoint) world.createJoint(jd);
            }
            case SLIDING -> {
                PrismaticJointDef jd = new PrismaticJointDef();
                jd.initialize(ground, leaf, new Vec2((float) d.centre().x(), (float) d.centre().y()),
                        new Vec2((float) -ux, (float) -uy));
                jd.enableLimit = true;
                jd.lowerTranslation = 0f;
                jd.upperTranslation = (float) w;
                jd.enableMotor = true;
                jd.maxMotorForce = 600f;
                slide = (PrismaticJoint) world.createJoint(jd);
            }
            case ROTATING -> {
                RevoluteJointDef jd = new RevoluteJointDef();
                jd.initialize(ground, leaf, new Vec2((float) d.centre().x(), (float) d.centre().y()));
                jd.enableMotor = true;
                jd.maxMotorTorque = 200f;
                hinge = (RevoluteJoint) world.createJoint(jd);
            }
            default -> throw new IllegalStateException(d.kind().toString());
        }
        WorldDoor door = new WorldDoor(this, d, leaf, hinge, slide, sign);
        leaf.setUserData(new Thing(Thing.Kind.LEAF, d.id(), door));
        return door;
    }

    /** Counts contacts on chairs (the bumper) and records collisions. */
    private final class Contacts implements ContactListener {
        @Override
        public void beginContact(Contact c) {
            Thing a = (Thing) c.getFixtureA().getBody().getUserData();
            Thing b = (Thing) c.getFixtureB().getBody().getUserData();
            // Both chairs feel a contact between two chairs; it is one collision.
            if (a.kind == Thing.Kind.CHAIR) {
                ((SimChair) a.owner).contactBegan();
                touched(c, (SimChair) a.owner, b, c.getFixtureB());
            }
            if (b.kind == Thing.Kind.CHAIR) {
                ((SimChair) b.owner).contactBegan();
                if (a.kind != Thing.Kind.CHAIR) {
                    touched(c, (SimChair) b.owner, a, c.getFixtureA());
                }
            }
        }

        private void touched(Contact c, SimChair chair, Thing other, Fixture otherFixture) {
            c.getWorldManifold(manifold);
            int n = c.getManifold().pointCount;
            Point at = n > 0 ? new Point(manifold.points[0].x, manifold.points[0].y)
                    : new Point(chair.truePose().x(), chair.truePose().y());
            String what = switch (other.kind) {
                case WALL -> wallName(otherFixture);
                case LEAF -> "door " + other.name;
                default -> other.name;
            };
            if (collisions.size() == COLLISIONS_KEPT) {
                collisions.removeFirst();
            }
            collisions.addLast(new Collision(nowNs, chair.name(), what, at));
            collisionCount++;
        }

        @Override
        public void endContact(Contact c) {
            Thing a = (Thing) c.getFixtureA().getBody().getUserData();
            Thing b = (Thing) c.getFixtureB().getBody().getUserData();
            if (a != null && a.kind == Thing.Kind.CHAIR) {
                ((SimChair) a.owner).contactEnded();
            }
            if (b != null && b.kind == Thing.Kind.CHAIR) {
                ((SimChair) b.owner).contactEnded();
            }
        }

        @Override
        public void preSolve(Contact contact, Manifold oldManifold) {
        }

        @Override
        public void postSolve(Contact contact, ContactImpulse impulse) {
        }
    }
}
