package io.concord.sim.world;

import io.concord.agents.chair.ChairLayout;

/**
 * How a simulated chair is built and how imperfect it is: its layout (body, wheels, encoders,
 * sensors), its mass and acceleration curve, and the noise of its sensors and wheels. Every
 * noise draws from the world's seed, so a run replays exactly.
 *
 * @param layout            body, wheels, encoders, top speed and sensors
 * @param massKg            with its occupant
 * @param accelMps2         how fast a wheel speeds up toward its commanded speed
 * @param decelMps2         how fast a wheel slows down (braking)
 * @param sonarRays         rays cast across a sonar's cone
 * @param rangeNoiseM       standard deviation of every range reading, metres
 * @param rangeNoiseRel     plus this fraction of the distance
 * @param wheelScaleSigma   standard deviation of each wheel's true radius against its nominal one
 *                          (a fraction, drawn once per chair): the systematic part of odometry drift
 * @param slipSigma         wheel slip, metres per square root of metre travelled: the random part
 * @param stateRateHz       state reports a second
 * @param batteryWh         battery capacity
 * @param markerFixes       whether the chair reads floor markers at the map's nodes (a position
 *                          fix within 0.8 m of a node, read by a camera, 1 cm and 0.5° of noise)
 * @param watchdogS         the board's watchdog: a chair not commanded for this long while its
 *                          motors run stops and reports {@code WATCHDOG}; 0 turns it off
 */
public record ChairConfig(ChairLayout layout, double massKg, double accelMps2, double decelMps2, int sonarRays,
                          double rangeNoiseM, double rangeNoiseRel, double wheelScaleSigma, double slipSigma,
                          double stateRateHz, double batteryWh, boolean markerFixes, double watchdogS) {

    /** Validates every setting, naming the wrong one. */
    public ChairConfig {
        if (layout == null) {
            throw new IllegalArgumentException("a chair needs a layout (ChairLayout.standard() is the dissertation's)");
        }
        check("massKg", massKg > 0 && massKg < 1000, massKg);
        check("accelMps2", accelMps2 > 0 && accelMps2 <= 20, accelMps2);
        check("decelMps2", decelMps2 > 0 && decelMps2 <= 20, decelMps2);
        if (sonarRays < 1 || sonarRays > 32) {
            throw new IllegalArgumentException("sonarRays must be 1 to 32, got " + sonarRays);
        }
        check("rangeNoiseM", rangeNoiseM >= 0 && rangeNoiseM < 1, rangeNoiseM);
        check("rangeNoiseRel", rangeNoiseRel >= 0 && rangeNoiseRel < 1, rangeNoiseRel);
        check("wheelScaleSigma", wheelScaleSigma >= 0 && wheelScaleSigma < 0.2, wheelScaleSigma);
        check("slipSigma", slipSigma >= 0 && slipSigma < 1, slipSigma);
        check("stateRateHz", stateRateHz > 0 && stateRateHz <= 1000, stateRateHz);
        check("batteryWh", batteryWh > 0, batteryWh);
        check("watchdogS", watchdogS >= 0 && watchdogS <= 10, watchdogS);
    }

    private static void check(String name, boolean ok, double value) {
        if (!ok || Double.isNaN(value)) {
            throw new IllegalArgumentException("chair setting " + name + " is out of range: " + value);
        }
    }

    /**
     * The dissertation's chair ({@link ChairLayout#standard()}), 100 kg, 1 m/s² up and 1.5 m/s²
     * down, five rays a sonar, 1 cm + 1 % range noise, 0.2 % wheel size error, 2 mm/√m slip,
     * 20 reports a second, a 500 Wh battery, floor markers read at the nodes, no watchdog (a test
     * drives with one command; the hospital's chairs run with {@link #withWatchdog}).
     */
    public static ChairConfig standard() {
        return new ChairConfig(ChairLayout.standard(), 100, 1.0, 1.5, 5, 0.01, 0.01, 0.002, 0.002, 20, 500, true, 0);
    }

    /** The same chair with perfect sensors and wheels: no range noise, no wheel error, no slip. */
    public ChairConfig noiseless() {
        return new ChairConfig(layout, massKg, accelMps2, decelMps2, sonarRays, 0, 0, 0, 0, stateRateHz, batteryWh, markerFixes, watchdogS);
    }

    /** The same chair with other odometry errors. */
    public ChairConfig withWheelErrors(double wheelScaleSigma, double slipSigma) {
        return new ChairConfig(layout, massKg, accelMps2, decelMps2, sonarRays, rangeNoiseM, rangeNoiseRel,
                wheelScaleSigma, slipSigma, stateRateHz, batteryWh, markerFixes, watchdogS);
    }

    /** The same chair with other range noise. */
    public ChairConfig withRangeNoise(double metres, double relative) {
        return new ChairConfig(layout, massKg, accelMps2, decelMps2, sonarRays, metres, relative, wheelScaleSigma,
                slipSigma, stateRateHz, batteryWh, markerFixes, watchdogS);
    }

    /** The same chair with another layout. */
    public ChairConfig withLayout(ChairLayout layout) {
        return new ChairConfig(layout, massKg, accelMps2, decelMps2, sonarRays, rangeNoiseM, rangeNoiseRel,
                wheelScaleSigma, slipSigma, stateRateHz, batteryWh, markerFixes, watchdogS);
    }

    /** The same chair with floor markers read (true) or not. */
    public ChairConfig withMarkerFixes(boolean on) {
        return new ChairConfig(layout, massKg, accelMps2, decelMps2, sonarRays, rangeNoiseM, rangeNoiseRel,
                wheelScaleSigma, slipSigma, stateRateHz, batteryWh, on, watchdogS);
    }

    /**
     * The same chair with the board's watchdog at this many seconds (0.3 is what the control
     * agent's 20 commands a second need; the real chair's board uses 0.2).
     */
    public ChairConfig withWatchdog(double seconds) {
        return new ChairConfig(layout, massKg, accelMps2, decelMps2, sonarRays, rangeNoiseM, rangeNoiseRel,
                wheelScaleSigma, slipSigma, stateRateHz, batteryWh, markerFixes, seconds);
    }

    /** The same chair with another mass. */
    public ChairConfig withMassKg(double massKg) {
        return new ChairConfig(layout, massKg, accelMps2, decelMps2, sonarRays, rangeNoiseM, rangeNoiseRel,
                wheelScaleSigma, slipSigma, stateRateHz, batteryWh, markerFixes, watchdogS);
    }

    /** The same chair with another acceleration curve. */
    public ChairConfig withAcceleration(double accelMps2, double decelMps2) {
        return new ChairConfig(layout, massKg, accelMps2, decelMps2, sonarRays, rangeNoiseM, rangeNoiseRel,
                wheelScaleSigma, slipSigma, stateRateHz, batteryWh, markerFixes, watchdogS);
    }
}
