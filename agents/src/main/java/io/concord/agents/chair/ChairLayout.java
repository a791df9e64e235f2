package io.concord.agents.chair;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * What a chair is, as its driver reports it: the body's size, the wheels and encoders the
 * odometry needs, the top speed, and the range sensors in the order their readings arrive. A
 * simulated chair takes it from its configuration; the serial chair from the board's hello.
 *
 * @param lengthM          body length, metres (along the direction of travel)
 * @param widthM           body width, metres
 * @param wheelRadiusM     nominal drive-wheel radius, metres
 * @param trackM           distance between the two drive wheels, metres
 * @param ticksPerRev      encoder ticks per wheel revolution
 * @param topSpeedMps      wheel speed at 100 % motor power, metres a second
 * @param sensors          range sensors, in reading order
 */
public record ChairLayout(double lengthM, double widthM, double wheelRadiusM, double trackM, int ticksPerRev,
                          double topSpeedMps, List<SensorMount> sensors) {

    /** Validates the layout; the sensor list is copied. */
    public ChairLayout {
        positive("lengthM", lengthM);
        positive("widthM", widthM);
        positive("wheelRadiusM", wheelRadiusM);
        positive("trackM", trackM);
        positive("topSpeedMps", topSpeedMps);
        if (ticksPerRev <= 0) {
            throw new IllegalArgumentException("ticksPerRev must be positive, got " + ticksPerRev);
        }
        if (trackM > widthM) {
            throw new IllegalArgumentException("the wheel track (" + trackM + " m) cannot be wider than the body (" + widthM + " m)");
        }
        sensors = List.copyOf(sensors);
        Set<String> names = new HashSet<>();
        for (SensorMount s : sensors) {
            if (!names.add(s.name())) {
                throw new IllegalArgumentException("two sensors are named '" + s.name() + "'");
            }
        }
    }

    private static void positive(String what, double v) {
        if (!(v > 0) || !Double.isFinite(v)) {
            throw new IllegalArgumentException(what + " must be a positive number, got " + v);
        }
    }

    /** Metres a wheel travels per encoder tick. */
    public double metresPerTick() {
        return 2 * Math.PI * wheelRadiusM / ticksPerRev;
    }

    /** The index of the sensor with this name, or -1. */
    public int sensorIndex(String name) {
        for (int i = 0; i < sensors.size(); i++) {
            if (sensors.get(i).name().equals(name)) {
                return i;
            }
        }
        return -1;
    }

    /**
     * The dissertation's chair: 1.2 m by 0.7 m, 0.17 m wheels 0.56 m apart with 2,048-tick
     * encoders, 1.5 m/s at full power; eight sonars (three ahead, one each corner at 45°, one
     * each side, one behind) and two infrared rangers ahead and two on the front corners, low.
     */
    public static ChairLayout standard() {
        double fx = 0.6;
        double sx = 0.35;
        return new ChairLayout(1.2, 0.7, 0.17, 0.56, 2048, 1.5, List.of(
                SensorMount.sonar("front", fx, 0, 0, 30, 3.0),
                SensorMount.sonar("front-left", fx, 0.2, 20, 30, 3.0),
                SensorMount.sonar("front-right", fx, -0.2, -20, 30, 3.0),
                SensorMount.sonar("corner-left", fx, sx, 60, 30, 3.0),
                SensorMount.sonar("corner-right", fx, -sx, -60, 30, 3.0),
                SensorMount.sonar("left", 0, sx, 90, 30, 3.0),
                SensorMount.sonar("right", 0, -sx, -90, 30, 3.0),
                SensorMount.sonar("rear", -fx, 0, 180, 30, 3.0),
                SensorMount.infrared("ir-front-left", fx, 0.3, 0, 0.8),
                SensorMount.infrared("ir-front-right", fx, -0.3, 0, 0.8),
                SensorMount.infrared("ir-corner-left", fx, sx, 45, 0.8),
                SensorMount.infrared("ir-corner-right", fx, -sx, -45, 0.8)));
    }
}
