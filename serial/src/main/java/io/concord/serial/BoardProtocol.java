package io.concord.serial;

import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.Pose;
import io.concord.agents.chair.SensorMount;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

/** The bodies of the board protocol's frames (docs/chair-protocol.md), written and read. */
public final class BoardProtocol {
    /** A range with no reading (nothing seen within the sensor's range). */
    public static final int NO_RANGE = 0xFFFF;
    /** NAK reasons. */
    public static final int NAK_NOT_NEUTRAL = 1;
    /** NAK: the body could not be read. */
    public static final int NAK_MALFORMED = 2;
    /** NAK: the e-stop is pressed. */
    public static final int NAK_ESTOP = 3;
    /** NAK: a frame type the board does not take. */
    public static final int NAK_UNKNOWN = 4;

    private BoardProtocol() {
    }

    // ---- DRIVE ------------------------------------------------------------------------------------

    /** DRIVE: left and right power, per mille, -1000 to 1000. */
    public static byte[] drive(int leftPermille, int rightPermille) {
        return new Frame.Builder().u16(clamp(leftPermille)).u16(clamp(rightPermille)).bytes();
    }

    private static int clamp(int p) {
        return Math.max(-1000, Math.min(1000, p)) & 0xFFFF;
    }

    /** A DRIVE's powers, per mille; throws malformed if out of range. */
    public static int[] readDrive(Frame f) {
        Frame.Fields r = f.fields();
        int l = r.i16();
        int rt = r.i16();
        r.end();
        if (Math.abs(l) > 1000 || Math.abs(rt) > 1000) {
            throw new FrameException("malformed", "drive powers " + l + ", " + rt + " are outside -1000..1000 per mille");
        }
        return new int[] {l, rt};
    }

    // ---- CONFIGURE, PING, ACK, NAK ------------------------------------------------------------------

    /** CONFIGURE: STATE frames a second, 1 to 100. */
    public static byte[] configure(int stateHz) {
        return new Frame.Builder().u8(stateHz).bytes();
    }

    /** PING and its ACK: a nonce. */
    public static byte[] ping(long nonce) {
        return new Frame.Builder().i32(nonce).bytes();
    }

    /** ACK: the host frame's sequence number, and for a PING its nonce (0 otherwise). */
    public static byte[] ack(int seq, long nonce) {
        return new Frame.Builder().u16(seq).i32(nonce).bytes();
    }

    /** NAK: the host frame's sequence number and the reason. */
    public static byte[] nak(int seq, int reason) {
        return new Frame.Builder().u16(seq).u8(reason).bytes();
    }

    // ---- STATE ------------------------------------------------------------------------------------

    /**
     * A STATE's fields.
     *
     * @param leftTicks  left encoder, signed, since the board started
     * @param rightTicks right encoder
     * @param rangesMm   each range sensor's distance in mm, in the layout's order ({@link #NO_RANGE}: nothing seen)
     * @param bumper     the bumper is pressed
     * @param estop      the e-stop is pressed
     * @param batteryMv  battery, millivolts
     * @param faults     the board's faults
     * @param fix        a floor marker's pose under the chair, or null
     */
    public record State(long leftTicks, long rightTicks, int[] rangesMm, boolean bumper, boolean estop, int batteryMv,
                        Set<ChairFault> faults, Pose fix) {
    }

    private static final ChairFault[] FAULT_BITS = {
        ChairFault.MOTOR_LEFT, ChairFault.MOTOR_RIGHT, ChairFault.SENSOR, ChairFault.BATTERY_LOW, ChairFault.WATCHDOG
    };

    public static byte[] state(State s) {
        Frame.Builder b = new Frame.Builder().i32(s.leftTicks()).i32(s.rightTicks()).u8(s.rangesMm().length);
        for (int r : s.rangesMm()) {
            b.u16(Math.max(0, Math.min(NO_RANGE, r)));
        }
        b.u8((s.bumper() ? 1 : 0) | (s.estop() ? 2 : 0)).u16(Math.max(0, Math.min(0xFFFF, s.batteryMv())));
        int bits = 0;
        for (int i = 0; i < FAULT_BITS.length; i++) {
            if (s.faults().contains(FAULT_BITS[i])) {
                bits |= 1 << i;
            }
        }
        b.u16(bits);
        if (s.fix() == null) {
            b.u8(0);
        } else {
            b.u8(1).i32(Math.round(s.fix().x() * 1000)).i32(Math.round(s.fix().y() * 1000))
                    .i32(Math.round(s.fix().heading() * 10_000));
        }
        return b.bytes();
    }

    public static State readState(Frame f) {
        Frame.Fields r = f.fields();
        long l = r.i32();
        long rt = r.i32();
        int n = r.u8();
        int[] ranges = new int[n];
        for (int i = 0; i < n; i++) {
            ranges[i] = r.u16();
        }
        int bits = r.u8();
        int mv = r.u16();
        int fb = r.u16();
        Set<ChairFault> faults = EnumSet.noneOf(ChairFault.class);
        for (int i = 0; i < FAULT_BITS.length; i++) {
            if ((fb & (1 << i)) != 0) {
                faults.add(FAULT_BITS[i]);
            }
        }
        Pose fix = null;
        if (r.u8() == 1) {
            fix = new Pose(r.i32() / 1000.0, r.i32() / 1000.0, r.i32() / 10_000.0);
        }
        r.end();
        return new State(l, rt, ranges, (bits & 1) != 0, (bits & 2) != 0, mv, faults, fix);
    }

    // ---- HELLO ------------------------------------------------------------------------------------

    /** HELLO: the firmware's version and the chair's layout. */
    public static byte[] hello(String firmware, ChairLayout l) {
        Frame.Builder b = new Frame.Builder().text(firmware)
                .u16(mm(l.lengthM())).u16(mm(l.widthM())).u16((int) Math.round(l.wheelRadiusM() * 10_000))
                .u16(mm(l.trackM())).u16(l.ticksPerRev()).u16(mm(l.topSpeedMps())).u8(l.sensors().size());
        for (SensorMount s : l.sensors()) {
            b.u8(s.kind() == SensorMount.Kind.SONAR ? 0 : 1).text(s.name())
                    .u16(mm(s.x()) & 0xFFFF).u16(mm(s.y()) & 0xFFFF).u16(mm(s.direction()) & 0xFFFF)
                    .u16(mm(s.minRangeM())).u16(mm(s.maxRangeM())).u16(mm(s.coneRad())).u16((int) Math.round(s.rateHz() * 10));
        }
        return b.bytes();
    }

    private static int mm(double v) {
        return (int) Math.round(v * 1000);
    }

    /** A HELLO's firmware version and layout; malformed if the layout does not validate. */
    public record Hello(String firmware, ChairLayout layout) {
    }

    public static Hello readHello(Frame f) {
        Frame.Fields r = f.fields();
        String fw = r.text();
        double length = r.u16() / 1000.0;
        double width = r.u16() / 1000.0;
        double wheel = r.u16() / 10_000.0;
        double track = r.u16() / 1000.0;
        int ticks = r.u16();
        double top = r.u16() / 1000.0;
        int n = r.u8();
        List<SensorMount> sensors = new ArrayList<>();
        try {
            for (int i = 0; i < n; i++) {
                int kind = r.u8();
                String name = r.text();
                double x = r.i16() / 1000.0;
                double y = r.i16() / 1000.0;
                double dir = r.i16() / 1000.0;
                double min = r.u16() / 1000.0;
                double max = r.u16() / 1000.0;
                double cone = r.u16() / 1000.0;
                double rate = r.u16() / 10.0;
                sensors.add(new SensorMount(name, kind == 0 ? SensorMount.Kind.SONAR : SensorMount.Kind.INFRARED, x, y, dir, min, max,
                        kind == 0 ? cone : 0, rate));
            }
            r.end();
            return new Hello(fw, new ChairLayout(length, width, wheel, track, ticks, top, sensors));
        } catch (IllegalArgumentException e) {
            throw new FrameException("malformed", "the HELLO's layout: " + e.getMessage());
        }
    }
}
