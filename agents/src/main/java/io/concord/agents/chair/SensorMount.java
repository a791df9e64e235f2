package io.concord.agents.chair;

/**
 * Where a range sensor sits on the chair and what it sees: its position in the chair's frame
 * (x forward, y left, metres from the chair's centre), the direction it looks (radians from the
 * chair's forward axis, counter-clockwise), its range, and for a sonar the cone it covers.
 *
 * @param name        a short name, unique on the chair ("front-left")
 * @param kind        sonar (a cone) or infrared (one ray)
 * @param x           metres forward of the centre
 * @param y           metres left of the centre
 * @param direction   radians from forward
 * @param minRangeM   nearer than this reads as this
 * @param maxRangeM   nothing seen reads as this
 * @param coneRad     the sonar's full cone angle; 0 for infrared
 * @param rateHz      samples per second
 */
public record SensorMount(String name, Kind kind, double x, double y, double direction, double minRangeM,
                          double maxRangeM, double coneRad, double rateHz) {

    /** The two kinds of range sensor of the dissertation's chair. */
    public enum Kind { SONAR, INFRARED }

    /** Validates the mount. */
    public SensorMount {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("a sensor needs a name");
        }
        if (kind == null) {
            throw new IllegalArgumentException("sensor '" + name + "' needs a kind (SONAR or INFRARED)");
        }
        if (!(minRangeM >= 0) || !(maxRangeM > minRangeM)) {
            throw new IllegalArgumentException("sensor '" + name + "': need 0 <= minRangeM < maxRangeM, got "
                    + minRangeM + " and " + maxRangeM);
        }
        if (kind == Kind.SONAR && !(coneRad > 0 && coneRad < Math.PI)) {
            throw new IllegalArgumentException("sonar '" + name + "': its cone must be between 0 and pi radians, got " + coneRad);
        }
        if (kind == Kind.INFRARED && coneRad != 0) {
            throw new IllegalArgumentException("infrared '" + name + "' is one ray: its cone must be 0, got " + coneRad);
        }
        if (!(rateHz > 0 && rateHz <= 1000)) {
            throw new IllegalArgumentException("sensor '" + name + "': rate must be in (0, 1000] Hz, got " + rateHz);
        }
    }

    /** A sonar: a cone of {@code coneDeg} degrees, 0.05 to {@code maxRangeM} metres, 10 Hz. */
    public static SensorMount sonar(String name, double x, double y, double directionDeg, double coneDeg, double maxRangeM) {
        return new SensorMount(name, Kind.SONAR, x, y, Math.toRadians(directionDeg), 0.05, maxRangeM,
                Math.toRadians(coneDeg), 10);
    }

    /** An infrared ranger: one ray, 0.04 to {@code maxRangeM} metres, 20 Hz. */
    public static SensorMount infrared(String name, double x, double y, double directionDeg, double maxRangeM) {
        return new SensorMount(name, Kind.INFRARED, x, y, Math.toRadians(directionDeg), 0.04, maxRangeM, 0, 20);
    }

    /** The same mount sampled at another rate. */
    public SensorMount withRateHz(double hz) {
        return new SensorMount(name, kind, x, y, direction, minRangeM, maxRangeM, coneRad, hz);
    }
}
