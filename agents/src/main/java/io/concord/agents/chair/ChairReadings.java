package io.concord.agents.chair;

import java.util.Arrays;
import java.util.Collections;
import java.util.EnumSet;
import java.util.Set;

/**
 * One state report of a chair, as its board sends it at a steady rate: the encoder counts, every
 * range sensor's latest distance (in the layout's order), the bumper, the battery, the e-stop
 * and the faults, with the odometry the driver integrated from the encoders. Immutable.
 *
 * @param timeNs       the chair's clock at the report (a board's own clock; a simulated chair's world time):
 *                     measure the chair's waits and stalls on it, not on the platform's clock
 * @param seq          report number, from 0
 * @param leftTicks    left encoder, ticks since start (signed)
 * @param rightTicks   right encoder, ticks since start (signed)
 * @param ranges       metres, per sensor in layout order; a sensor that saw nothing reads its max range
 * @param bumper       true if the body touched anything since the previous report
 * @param batteryVolts battery voltage
 * @param emergencyStop true while the chair's e-stop is pressed
 * @param faults       active faults, empty when healthy
 * @param odometry     the pose integrated from the encoders
 * @param fix          a position fix from a floor marker near the chair (a marker at each node
 *                     of the route graph, read by a camera, as guided vehicles use), or null when none is read
 */
public record ChairReadings(long timeNs, long seq, long leftTicks, long rightTicks, double[] ranges, boolean bumper,
                            double batteryVolts, boolean emergencyStop, Set<ChairFault> faults, Pose odometry, Pose fix) {

    /** Copies the arrays and sets, so that the record stays immutable. */
    public ChairReadings {
        ranges = ranges.clone();
        // In the enum's order, in every JVM (Set.copyOf iterates in an order salted per run).
        faults = Collections.unmodifiableSet(faults.isEmpty() ? EnumSet.noneOf(ChairFault.class) : EnumSet.copyOf(faults));
    }

    /** The distance in metres read by sensor {@code index}. */
    public double range(int index) {
        return ranges[index];
    }

    /** A copy of every distance, in layout order. */
    @Override
    public double[] ranges() {
        return ranges.clone();
    }

    /** The number of range readings. */
    public int rangeCount() {
        return ranges.length;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ChairReadings r && r.timeNs == timeNs && r.seq == seq && r.leftTicks == leftTicks
                && r.rightTicks == rightTicks && Arrays.equals(r.ranges, ranges) && r.bumper == bumper
                && Double.compare(r.batteryVolts, batteryVolts) == 0 && r.emergencyStop == emergencyStop
                && r.faults.equals(faults) && r.odometry.equals(odometry) && java.util.Objects.equals(r.fix, fix);
    }

    @Override
    public int hashCode() {
        return Long.hashCode(seq) * 31 + Arrays.hashCode(ranges);
    }

    @Override
    public String toString() {
        return "ChairReadings[seq=" + seq + " ticks=" + leftTicks + "/" + rightTicks + " ranges=" + Arrays.toString(ranges)
                + " bumper=" + bumper + " battery=" + batteryVolts + "V estop=" + emergencyStop + " faults=" + faults
                + " odometry=" + odometry + (fix == null ? "" : " fix=" + fix) + "]";
    }
}
