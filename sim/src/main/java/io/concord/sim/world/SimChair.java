package io.concord.sim.world;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Odometry;
import io.concord.agents.chair.Pose;
import io.concord.agents.chair.SensorMount;

import org.jbox2d.callbacks.RayCastCallback;
import org.jbox2d.common.Vec2;
import org.jbox2d.dynamics.Body;
import org.jbox2d.dynamics.Fixture;

import java.util.EnumSet;
import java.util.Set;
import java.util.SplittableRandom;

/**
 * A simulated chair in a {@link HospitalWorld}: a rectangular body on two driven wheels. The
 * motor powers set each wheel's commanded speed, which follows the acceleration curve; the body is
 * pushed toward that motion with the force the motors have, without sideways slip, and stops at
 * whatever it meets. The encoders count what the wheels really turned (with each wheel's size
 * error and slip), the range sensors cast rays into the world at their own rates, and a state
 * report goes to the listener at the chair's rate. The true pose is kept beside the odometry.
 *
 * <p>Confined to the thread that steps the world.
 */
public final class SimChair implements ChairDriver {
    private static final double GRAVITY = 9.81;
    private static final double GRIP = 0.8;
    private static final double FULL_VOLTS = 25.6;
    private static final double EMPTY_VOLTS = 21.0;
    private static final double LOW_VOLTS = 22.0;
    private static final double MOTOR_WATTS = 450;
    private static final double IDLE_WATTS = 15;
    private static final double MARKER_RANGE_M = 0.8;

    private final HospitalWorld world;
    /** The world's floor markers: the map's nodes, at a node with lanes each lane's point, and along the long edges. */
    private final java.util.List<io.concord.agents.map.Point> markers;
    private final String name;
    private final ChairConfig config;
    private final ChairLayout layout;
    final Body body;
    private final org.jbox2d.dynamics.joints.FrictionJoint brake;
    private boolean brakeOn;
    private final SplittableRandom random;
    private final double scaleLeft;
    private final double scaleRight;
    private final double metresPerTick;
    private final double halfTrack;
    private final double forceMax;
    private final double torqueMax;
    private final double inertia;

    private double powerLeft;
    private double powerRight;
    private double wheelLeft;
    private double wheelRight;
    private double ticksLeft;
    private double ticksRight;
    private double lastX;
    private double lastY;
    private double lastAngle;
    private double distance;

    private final double[] ranges;
    private final long[] nextSampleStep;
    private final long[] samplePeriodSteps;
    private long nextReportStep;
    private final long reportPeriodSteps;
    private long seq;
    private boolean bumperLatch;
    private int contacts;
    private long bumps;
    private boolean emergencyStop;
    private final Set<ChairFault> faults = EnumSet.noneOf(ChairFault.class);
    private double usedWh;
    private long lastDriveStep;
    private final Odometry odometry;
    private ChairReadings latest;
    private ChairListener listener;
    private final Track truth;
    private final Track dead;
    private boolean removed;
    private long listenerFailures;
    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(SimChair.class);

    // scratch, so that a step allocates nothing
    private final Vec2 tmp = new Vec2();
    private final Vec2 rayFrom = new Vec2();
    private final Vec2 rayTo = new Vec2();
    private final RayHit hit = new RayHit();

    SimChair(HospitalWorld world, String name, ChairConfig config, Body body, org.jbox2d.dynamics.joints.FrictionJoint brake,
             Pose start, SplittableRandom random) {
        this.world = world;
        this.markers = world.markers();
        this.brake = brake;
        this.name = name;
        this.config = config;
        this.layout = config.layout();
        this.body = body;
        this.random = random;
        this.scaleLeft = 1 + config.wheelScaleSigma() * random.nextGaussian();
        this.scaleRight = 1 + config.wheelScaleSigma() * random.nextGaussian();
        this.metresPerTick = layout.metresPerTick();
        this.halfTrack = layout.trackM() / 2;
        this.forceMax = 2 * config.massKg() * Math.max(config.accelMps2(), config.decelMps2());
        this.inertia = body.getInertia();
        this.torqueMax = inertia * 2 * forceMax / config.massKg() / halfTrack;
        int n = layout.sensors().size();
        this.ranges = new double[n];
        this.nextSampleStep = new long[n];
        this.samplePeriodSteps = new long[n];
        double hz = world.stepHz();
        for (int i = 0; i < n; i++) {
            SensorMount s = layout.sensors().get(i);
            ranges[i] = s.maxRangeM();
            samplePeriodSteps[i] = Math.max(1, Math.round(hz / s.rateHz()));
            // Spread the sensors over their period so that one step does not cast every ray.
            nextSampleStep[i] = world.stepCount() + (i % samplePeriodSteps[i]);
        }
        this.reportPeriodSteps = Math.max(1, Math.round(hz / config.stateRateHz()));
        this.nextReportStep = world.stepCount();
        this.odometry = new Odometry(layout, start);
        this.lastX = body.getPosition().x;
        this.lastY = body.getPosition().y;
        this.lastAngle = body.getAngle();
        this.truth = new Track(20_000);
        this.dead = new Track(20_000);
        // A report never carries a distance nobody measured: every sensor reads once now.
        for (int i = 0; i < n; i++) {
            ranges[i] = sample(layout.sensors().get(i));
        }
    }

    // ---- ChairDriver ----------------------------------------------------------------------------

    @Override
    public String name() {
        return name;
    }

    @Override
    public ChairLayout layout() {
        return layout;
    }

    @Override
    public void drive(double leftPercent, double rightPercent) {
        powerLeft = clampPower(leftPercent);
        powerRight = clampPower(rightPercent);
        lastDriveStep = world.stepCount();
        faults.remove(ChairFault.WATCHDOG);
    }

    private static double clampPower(double p) {
        if (Double.isNaN(p)) {
            return 0;
        }
        return Math.max(-100, Math.min(100, p));
    }

    @Override
    public ChairReadings latest() {
        return latest;
    }

    @Override
    public boolean online() {
        return !removed;
    }

    @Override
    public void setListener(ChairListener listener) {
        this.listener = listener;
    }

    // ---- what a test and a picture see ----------------------------------------------------------

    /** The configuration the chair was built with. */
    public ChairConfig config() {
        return config;
    }

    /** Where the chair really is (ground truth), which no agent is given. */
    public Pose truePose() {
        Vec2 p = body.getPosition();
        return new Pose(p.x, p.y, body.getAngle());
    }

    /** Where the chair's odometry believes it is. */
    public Pose odometryPose() {
        return odometry.pose();
    }

    /** Metres the odometry has counted (the centre's path, by the encoders). */
    public double odometry() {
        return odometry.distanceM();
    }

    /** The motor powers last set, {left, right}. */
    public double[] powers() {
        return new double[] {powerLeft, powerRight};
    }

    /** The speed of the body along its heading now, m/s (negative backwards). */
    public double forwardSpeed() {
        Vec2 v = body.getLinearVelocity();
        double a = body.getAngle();
        return v.x * StrictMath.cos(a) + v.y * StrictMath.sin(a);
    }

    /** True while the body touches anything. */
    public boolean touching() {
        return contacts > 0;
    }

    /** Reports on which the listener threw (each counted, the first logged). */
    public long listenerFailures() {
        return listenerFailures;
    }

    /** Contacts begun since the chair was added. */
    public long bumps() {
        return bumps;
    }

    /** Metres the body's centre has travelled (ground truth). */
    public double distanceTravelled() {
        return distance;
    }

    /** The true path, sampled. */
    public Track truthTrack() {
        return truth;
    }

    /** The odometry's path, sampled. */
    public Track odometryTrack() {
        return dead;
    }

    /** Presses (true) or releases the chair's emergency stop: while pressed the motors do nothing. */
    public void emergencyStop(boolean pressed) {
        this.emergencyStop = pressed;
    }

    /** Makes a fault appear (a failed motor stops its wheel; a failed sensor reads NaN). */
    public void injectFault(ChairFault fault) {
        faults.add(fault);
    }

    /** Battery voltage now. */
    public double batteryVolts() {
        double frac = Math.min(1, usedWh / config.batteryWh());
        return FULL_VOLTS - (FULL_VOLTS - EMPTY_VOLTS) * frac;
    }

    /** Sets how much of the battery has been used, 0 (full) to 1 (empty). */
    public void setBatteryUsed(double fraction) {
        usedWh = Math.max(0, Math.min(1, fraction)) * config.batteryWh();
    }

    /** Moves the chair to a pose at a stand (a test's set-up, or carrying it by hand); odometry keeps its belief. */
    public void place(Pose pose) {
        tmp.set((float) pose.x(), (float) pose.y());
        body.setTransform(tmp, (float) pose.heading());
        tmp.setZero();
        body.setLinearVelocity(tmp);
        body.setAngularVelocity(0);
        body.setAwake(true);
        wheelLeft = 0;
        wheelRight = 0;
        lastX = body.getPosition().x;
        lastY = body.getPosition().y;
        lastAngle = body.getAngle();
    }

    // ---- the step -------------------------------------------------------------------------------

    void beforeStep(double dt) {
        // The board's watchdog: a host that stops commanding a moving chair stops it.
        if (config.watchdogS() > 0 && (powerLeft != 0 || powerRight != 0)
                && world.stepCount() - lastDriveStep > config.watchdogS() * world.stepHz()) {
            powerLeft = 0;
            powerRight = 0;
            faults.add(ChairFault.WATCHDOG);
        }
        boolean dead = emergencyStop || batteryVolts() <= EMPTY_VOLTS;
        double top = layout.topSpeedMps();
        double targetLeft = dead || faults.contains(ChairFault.MOTOR_LEFT) ? 0 : powerLeft / 100 * top;
        double targetRight = dead || faults.contains(ChairFault.MOTOR_RIGHT) ? 0 : powerRight / 100 * top;
        wheelLeft = ramp(wheelLeft, targetLeft, dt);
        wheelRight = ramp(wheelRight, targetRight, dt);
        usedWh += ((Math.abs(wheelLeft) + Math.abs(wheelRight)) / (2 * top) * MOTOR_WATTS + IDLE_WATTS) * dt / 3600;

        double v = (wheelLeft + wheelRight) / 2;
        double w = (wheelRight - wheelLeft) / layout.trackM();
        float angle = body.getAngle();
        double c = StrictMath.cos(angle);
        double s = StrictMath.sin(angle);
        Vec2 vel = body.getLinearVelocity();
        double vf = vel.x * c + vel.y * s;
        double vl = -vel.x * s + vel.y * c;
        double m = body.getMass();
        // A chair whose wheels stand holds with its brakes (a friction joint to the floor, solved inside
        // the step), up to the tyres' grip; a driving one pushes with its motors' force.
        boolean braked = wheelLeft == 0 && wheelRight == 0;
        double grip = GRIP * m * GRAVITY;
        if (braked != brakeOn) {
            brakeOn = braked;
            brake.setMaxForce(braked ? (float) grip : 0f);
            brake.setMaxTorque(braked ? (float) (torqueMax * grip / forceMax) : 0f);
        }
        double jf = clamp(m * (v - vf), forceMax * dt);
        double jl = clamp(-m * vl, grip * dt);
        if (jf != 0 || jl != 0) {
            tmp.set((float) (jf * c - jl * s), (float) (jf * s + jl * c));
            body.applyLinearImpulse(tmp, body.getWorldCenter());
        }
        double ja = clamp(inertia * (w - body.getAngularVelocity()), torqueMax * dt);
        if (ja != 0) {
            body.applyAngularImpulse((float) ja);
        }
    }

    private double ramp(double current, double target, double dt) {
        if (current == target) {
            return current;
        }
        boolean speedingUp = Math.abs(target) > Math.abs(current) && Math.signum(target) * Math.signum(current) >= 0;
        double rate = (speedingUp ? config.accelMps2() : config.decelMps2()) * dt;
        if (Math.abs(target - current) <= rate) {
            return target;
        }
        return current + Math.signum(target - current) * rate;
    }

    private static double clamp(double v, double bound) {
        return Math.max(-bound, Math.min(bound, v));
    }

    void afterStep(long step, long nowNs) {
        Vec2 p = body.getPosition();
        double angle = body.getAngle();
        double dx = p.x - lastX;
        double dy = p.y - lastY;
        double dth = angle - lastAngle;
        double mid = lastAngle + dth / 2;
        double ds = dx * StrictMath.cos(mid) + dy * StrictMath.sin(mid);
        lastX = p.x;
        lastY = p.y;
        lastAngle = angle;
        distance += Math.hypot(dx, dy);
        double dl = ds - dth * halfTrack;
        double dr = ds + dth * halfTrack;
        if (dl != 0 || dr != 0) {
            ticksLeft += wheelTicks(dl, scaleLeft);
            ticksRight += wheelTicks(dr, scaleRight);
        }
        for (int i = 0; i < ranges.length; i++) {
            if (step >= nextSampleStep[i]) {
                nextSampleStep[i] = step + samplePeriodSteps[i];
                ranges[i] = sample(layout.sensors().get(i));
            }
        }
        if (step >= nextReportStep) {
            nextReportStep = step + reportPeriodSteps;
            report(world.worldTimeNs());
        }
    }

    private double wheelTicks(double metres, double scale) {
        double slip = config.slipSigma() == 0 ? 0 : config.slipSigma() * Math.sqrt(Math.abs(metres)) * random.nextGaussian();
        return (metres + slip) / (metresPerTick * scale);
    }

    private void report(long nowNs) {
        long lt = (long) Math.floor(ticksLeft);
        long rt = (long) Math.floor(ticksRight);
        Pose odo = odometry.update(lt, rt);
        Set<ChairFault> f = faults;
        double volts = batteryVolts();
        if (volts < LOW_VOLTS && !faults.contains(ChairFault.BATTERY_LOW)) {
            faults.add(ChairFault.BATTERY_LOW);
        }
        latest = new ChairReadings(nowNs, seq++, lt, rt, ranges, bumperLatch || contacts > 0, volts, emergencyStop, f, odo,
                config.markerFixes() ? markerFix() : null);
        bumperLatch = false;
        truth.offer(body.getPosition().x, body.getPosition().y);
        dead.offer(odo.x(), odo.y());
        if (listener != null) {
            try {
                listener.onReadings(latest);
            } catch (RuntimeException e) {
                // One driver's fault must not stop the world: count it, say it once, go on.
                if (listenerFailures++ == 0) {
                    LOG.warn("the listener of chair {} failed on a report; the world goes on", name, e);
                }
            }
        }
    }

    /** The pose a floor marker under the chair gives, with its noise, or null if none is within reach. */
    private Pose markerFix() {
        Vec2 p = body.getPosition();
        for (io.concord.agents.map.Point m : markers) {
            double dx = m.x() - p.x;
            double dy = m.y() - p.y;
            if (dx * dx + dy * dy <= MARKER_RANGE_M * MARKER_RANGE_M) {
                return new Pose(p.x + 0.01 * random.nextGaussian(), p.y + 0.01 * random.nextGaussian(),
                        body.getAngle() + Math.toRadians(0.5) * random.nextGaussian());
            }
        }
        return null;
    }

    /** One range reading: the nearest hit of the sensor's rays, with noise, within its range. */
    private double sample(SensorMount s) {
        Vec2 p = body.getPosition();
        double a = body.getAngle();
        double c = StrictMath.cos(a);
        double sn = StrictMath.sin(a);
        double ox = p.x + s.x() * c - s.y() * sn;
        double oy = p.y + s.x() * sn + s.y() * c;
        int rays = s.kind() == SensorMount.Kind.SONAR ? config.sonarRays() : 1;
        double nearest = Double.POSITIVE_INFINITY;
        // The first ray's direction, then each next one turned by the rays' spacing: two sines a
        // sensor, not two a ray.
        double first = a + s.direction() - (rays == 1 ? 0 : s.coneRad() / 2);
        double dx = StrictMath.cos(first);
        double dy = StrictMath.sin(first);
        double stepCos = rays == 1 ? 1 : StrictMath.cos(s.coneRad() / (rays - 1));
        double stepSin = rays == 1 ? 0 : StrictMath.sin(s.coneRad() / (rays - 1));
        for (int r = 0; r < rays; r++) {
            double d = world.castRay(this, ox, oy, dx, dy, s.maxRangeM(), hit, rayFrom, rayTo);
            nearest = Math.min(nearest, d);
            double nx = dx * stepCos - dy * stepSin;
            dy = dx * stepSin + dy * stepCos;
            dx = nx;
        }
        if (nearest == Double.POSITIVE_INFINITY) {
            return s.maxRangeM();
        }
        double sigma = config.rangeNoiseM() + config.rangeNoiseRel() * nearest;
        double d = sigma == 0 ? nearest : nearest + sigma * random.nextGaussian();
        return Math.max(s.minRangeM(), Math.min(s.maxRangeM(), d));
    }

    void contactBegan() {
        contacts++;
        bumps++;
        bumperLatch = true;
    }

    void contactEnded() {
        contacts = Math.max(0, contacts - 1);
    }

    void markRemoved() {
        removed = true;
        if (listener != null) {
            listener.onOnline(false);
        }
    }

    /** The nearest fixture a ray meets, other than the chair's own. */
    static final class RayHit implements RayCastCallback {
        Body self;
        float fraction;
        boolean hitAny;

        @Override
        public float reportFixture(Fixture fixture, Vec2 point, Vec2 normal, float f) {
            if (fixture.getBody() == self || fixture.isSensor()) {
                return -1;
            }
            fraction = Math.min(fraction, f);
            hitAny = true;
            return f;
        }
    }

    @Override
    public String toString() {
        return "SimChair[" + name + " at " + truePose() + "]";
    }
}
