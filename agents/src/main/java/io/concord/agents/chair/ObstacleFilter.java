package io.concord.agents.chair;

import java.util.Map;

/**
 * The chair's stop and slow zones, as a driver of its own between whatever plans the motion (the
 * route follower) and the safety supervisor, in the manner of Nav2's collision monitor: every
 * command passes through it, and it alone decides, from the latest range readings, whether the
 * command reaches the supervisor as it is, slowed, or as a stop.
 *
 * <ul>
 * <li><b>Stop</b>: something nearer than {@link #STOP_M} to the front sonar, or {@link #STOP_IR_M}
 *     to either front infrared sensor: the chair is stopped, and {@link #blockedAt()} says how far
 *     the nearest thing was (the planner's cue to report the edge blocked).</li>
 * <li><b>Slow</b>: something nearer than {@link #SLOW_M} to the front sonar: the command at
 *     {@link #SLOW_SCALE} of its power.</li>
 * <li>A turn on the spot (equal and opposite powers) moves nothing forward: it passes, so that a
 *     chair can turn away from what stands before it.</li>
 * </ul>
 *
 * <p>Everything else (the hold, the arming, the readings, the link) is the wrapped driver's. Its
 * defence can be switched off by a test ({@link #enabled(boolean)}), to show what it prevents;
 * nothing else turns it off. On the agent's loop, as the driver it wraps.
 */
public final class ObstacleFilter implements ChairDriver {
    /** Nearer than this ahead (front sonar), the chair stops. */
    public static final double STOP_M = 0.45;
    /** Nearer than this ahead (either front infrared sensor), the chair stops. */
    public static final double STOP_IR_M = 0.3;
    /** Nearer than this ahead, the chair drives at {@link #SLOW_SCALE} of its power. */
    public static final double SLOW_M = 1.2;
    /** The share of its power a chair keeps in the slow zone. */
    public static final double SLOW_SCALE = 0.35;

    private final ChairDriver chair;
    private final int front;
    private final int irLeft;
    private final int irRight;
    private boolean enabled = true;
    /** The reading the next command is judged on (the latest the caller saw), or null: the driver's latest. */
    private ChairReadings seen;
    /** How far ahead the thing was that stopped the last command, or NaN if it went through. */
    private double blockedAt = Double.NaN;
    private long stops;
    private long slowed;

    /** The zones for the chair {@code chair} drives (its layout names the sensors {@code front}, {@code ir-front-left}, {@code ir-front-right}). */
    public ObstacleFilter(ChairDriver chair) {
        this.chair = java.util.Objects.requireNonNull(chair, "chair");
        this.front = chair.layout().sensorIndex("front");
        this.irLeft = chair.layout().sensorIndex("ir-front-left");
        this.irRight = chair.layout().sensorIndex("ir-front-right");
    }

    /** The driver the filtered commands go to (the supervisor). */
    public ChairDriver wrapped() {
        return chair;
    }

    /**
     * Whether the zones apply (true unless a test switched them off, to show what the chair does
     * without them). Returns this filter.
     */
    public ObstacleFilter enabled(boolean on) {
        this.enabled = on;
        return this;
    }

    /** Whether the zones apply. */
    public boolean enabled() {
        return enabled;
    }

    /** The reading the next commands are judged on: the one the caller is acting on (the driver's latest if never called). */
    public void observe(ChairReadings r) {
        this.seen = r;
    }

    /** How far ahead (metres) the thing was that stopped the last command; NaN if the last command went through. */
    public double blockedAt() {
        return blockedAt;
    }

    /** Commands stopped and slowed since the start, for the log and the console. */
    public Map<String, Long> counts() {
        return Map.of("obstacle-stop", stops, "obstacle-slow", slowed);
    }

    @Override
    public void drive(double leftPercent, double rightPercent) {
        ChairReadings r = seen != null ? seen : chair.latest();
        boolean spotTurn = Math.abs(leftPercent + rightPercent) < 1e-9 && leftPercent != 0;
        if (!enabled || r == null || spotTurn) {
            blockedAt = Double.NaN;
            chair.drive(leftPercent, rightPercent);
            return;
        }
        double ahead = r.range(front);
        double irl = r.range(irLeft);
        double irr = r.range(irRight);
        if (ahead < STOP_M || irl < STOP_IR_M || irr < STOP_IR_M) {
            blockedAt = Math.min(ahead, Math.min(irl, irr));
            stops++;
            chair.stop();
            return;
        }
        blockedAt = Double.NaN;
        if (ahead < SLOW_M) {
            slowed++;
            chair.drive(leftPercent * SLOW_SCALE, rightPercent * SLOW_SCALE);
        } else {
            chair.drive(leftPercent, rightPercent);
        }
    }

    @Override
    public void stop() {
        blockedAt = Double.NaN;
        chair.stop();
    }

    @Override
    public String name() {
        return chair.name();
    }

    @Override
    public ChairLayout layout() {
        return chair.layout();
    }

    @Override
    public void holdMotion() {
        chair.holdMotion();
    }

    @Override
    public void releaseMotion() {
        chair.releaseMotion();
    }

    @Override
    public void arm() {
        chair.arm();
    }

    @Override
    public ChairReadings latest() {
        return chair.latest();
    }

    @Override
    public boolean online() {
        return chair.online();
    }

    @Override
    public boolean reportsArming() {
        return chair.reportsArming();
    }

    @Override
    public String whyOffline() {
        return chair.whyOffline();
    }

    @Override
    public Map<String, Long> linkDrops() {
        return chair.linkDrops();
    }

    @Override
    public void setListener(ChairListener listener) {
        chair.setListener(listener);
    }
}
