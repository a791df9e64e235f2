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
    /** NAK reasons: a DRIVE other than 0, 0 to a board that is not armed. */
    public static final int NAK_NOT_ARMED = 1;
    /** NAK: the body could not be read. */
    public static final int NAK_MALFORMED = 2;
    /** NAK: the e-stop is pressed. */
    public static final int NAK_ESTOP = 3;
    /** NAK: a frame type the board does not take. */
    public static final int NAK_UNKNOWN = 4;
    /**
     * NAK (version 3): an ARM for another state than the board's: its boot number or its reason is not the board's
     * now (the board restarted, or was disarmed again, after the STATE the host decided on).
     */
    public static final int NAK_STALE_ARM = 5;

    /** The protocol's version, the first byte of HELLO's body (HELLO's type is 0x85 from version 3 on). */
    public static final int VERSION = 3;

    /** STATE's reason: the board is armed. */
    public static final int ARMED = 0;
    /** STATE's reason: not armed since switch-on. */
    public static final int DISARMED_SWITCH_ON = 1;
    /** STATE's reason: not armed since its watchdog tripped. */
    public static final int DISARMED_WATCHDOG = 2;
    /** STATE's reason: not armed since the e-stop was pressed. */
    public static final int DISARMED_ESTOP = 3;
    /** STATE's reason: not armed since a host's new session (a SYNC PING). */
    public static final int DISARMED_SESSION = 4;

    /** A STATE reason in words, as events and logs give it. */
    public static String disarmedBy(int reason) {
        return switch (reason) {
            case ARMED -> "armed";
            case DISARMED_SWITCH_ON -> "switch-on";
            case DISARMED_WATCHDOG -> "watchdog";
            case DISARMED_ESTOP -> "e-stop";
            case DISARMED_SESSION -> "new session";
            default -> "reason " + reason;
        };
    }

    /** A NAK reason in words. */
    public static String nakReason(int reason) {
        return switch (reason) {
            case NAK_NOT_ARMED -> "not armed";
            case NAK_MALFORMED -> "malformed";
            case NAK_ESTOP -> "e-stop";
            case NAK_UNKNOWN -> "unknown type";
            case NAK_STALE_ARM -> "arm for another state";
            default -> "reason " + reason;
        };
    }

    /**
     * The boot number a STATE or HELLO carries (bytes 0-3 of a STATE's body, 1-4 of a HELLO's),
     * or -1 for any other frame or one too short to carry it (it is then dropped as malformed later).
     */
    public static long boot(Frame f) {
        byte[] b = f.body();
        int at = f.type() == Frame.Type.STATE ? 0 : f.type() == Frame.Type.HELLO ? 1 : -1;
        if (at < 0 || b.length < at + 4) {
            return -1;
        }
        return ((b[at] & 0xFFL) << 24) | ((b[at + 1] & 0xFFL) << 16) | ((b[at + 2] & 0xFFL) << 8) | (b[at + 3] & 0xFFL);
    }

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

    // ---- ARM --------------------------------------------------------------------------------------

    /** ARM: the board's boot number and its reason for not being armed, from the STATE the host decided on. */
    public static byte[] arm(long boot, int reason) {
        return new Frame.Builder().i32(boot).u8(reason).bytes();
    }

    /** An ARM's fields: the boot number and the reason it names. */
    public record Arm(long boot, int reason) {
    }

    /** Reads an ARM; malformed if its reason is not one of STATE's reasons for being disarmed (1 to 4). */
    public static Arm readArm(Frame f) {
        Frame.Fields r = f.fields();
        long boot = r.i32() & 0xFFFFFFFFL;
        int reason = r.u8();
        r.end();
        if (reason < DISARMED_SWITCH_ON || reason > DISARMED_SESSION) {
            throw new FrameException("malformed", "ARM names reason " + reason + "; a disarmed board's reasons are 1 to 4");
        }
        return new Arm(boot, reason);
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

    /**
     * NAK: the host frame's sequence number, the reason, and why the board is not armed
     * ({@link #ARMED} if it is): a refusal that explains itself, even when no STATE showed the disarm.
     */
    public static byte[] nak(int seq, int reason, int disarmedBy) {
        return new Frame.Builder().u16(seq).u8(reason).u8(disarmedBy).bytes();
    }

    /** A NAK's fields. */
    public record Nak(int seq, int reason, int disarmedBy) {
    }

    public static Nak readNak(Frame f) {
        Frame.Fields r = f.fields();
        int seq = r.u16();
        int reason = r.u8();
        int by = r.u8();
        r.end();
        return new Nak(seq, reason, by);
    }

    // ---- STATE ------------------------------------------------------------------------------------

    /**
     * A STATE's fields.
     *
     * @param boot       the board's boot number (one more at each switch-on)
     * @param leftTicks  left encoder, signed, since the board started
     * @param rightTicks right encoder
     * @param rangesMm   each range sensor's distance in mm, in the layout's order ({@link #NO_RANGE}: nothing seen)
     * @param bumper     the bumper is pressed
     * @param estop      the e-stop is pressed
     * @param armed      the board takes a non-neutral DRIVE
     * @param reason     why it is not armed ({@link #ARMED} when it is; {@link #DISARMED_SWITCH_ON}...)
     * @param batteryMv  battery, millivolts
     * @param faults     the board's faults
     * @param fix        a floor marker's pose under the chair, or null
     */
    public record State(long boot, long leftTicks, long rightTicks, int[] rangesMm, boolean bumper, boolean estop, boolean armed,
                        int reason, int batteryMv, Set<ChairFault> faults, Pose fix) {
    }

    private static final ChairFault[] FAULT_BITS = {
        ChairFault.MOTOR_LEFT, ChairFault.MOTOR_RIGHT, ChairFault.SENSOR, ChairFault.BATTERY_LOW, ChairFault.WATCHDOG
    };

    public static byte[] state(State s) {
        Frame.Builder b = new Frame.Builder().i32(s.boot()).i32(s.leftTicks()).i32(s.rightTicks()).u8(s.rangesMm().length);
        for (int r : s.rangesMm()) {
            b.u16(Math.max(0, Math.min(NO_RANGE, r)));
        }
        b.u8((s.bumper() ? 1 : 0) | (s.estop() ? 2 : 0) | (s.armed() ? 4 : 0)).u8(s.reason())
                .u16(Math.max(0, Math.min(0xFFFF, s.batteryMv())));
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
        long boot = r.i32() & 0xFFFFFFFFL;
        long l = r.i32();
        long rt = r.i32();
        int n = r.u8();
        int[] ranges = new int[n];
        for (int i = 0; i < n; i++) {
            ranges[i] = r.u16();
        }
        int bits = r.u8();
        int reason = r.u8();
        if ((bits & ~7) != 0) {
            throw new FrameException("malformed", "STATE bits " + Integer.toHexString(bits) + ": only bits 0-2 are defined");
        }
        if (((bits & 4) != 0) != (reason == ARMED)) {
            throw new FrameException("malformed", "STATE says armed=" + ((bits & 4) != 0) + " with reason " + reason);
        }
        int mv = r.u16();
        int fb = r.u16();
        Set<ChairFault> faults = EnumSet.noneOf(ChairFault.class);
        for (int i = 0; i < FAULT_BITS.length; i++) {
            if ((fb & (1 << i)) != 0) {
                faults.add(FAULT_BITS[i]);
            }
        }
        Pose fix = null;
        int hasFix = r.u8();
        if (hasFix > 1) {
            throw new FrameException("malformed", "STATE fix flag " + hasFix + ": 0 or 1");
        }
        if (hasFix == 1) {
            fix = new Pose(r.i32() / 1000.0, r.i32() / 1000.0, r.i32() / 10_000.0);
        }
        r.end();
        return new State(boot, l, rt, ranges, (bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0, reason, mv, faults, fix);
    }

    // ---- HELLO ------------------------------------------------------------------------------------

    /** HELLO: the protocol's version, the boot number, the firmware's version and the chair's layout. */
    public static byte[] hello(long boot, String firmware, ChairLayout l) {
        return hello(VERSION, boot, firmware, l);
    }

    /** HELLO of any version (a test's board of another version). */
    public static byte[] hello(int version, long boot, String firmware, ChairLayout l) {
        Frame.Builder b = new Frame.Builder().u8(version).i32(boot).text(firmware)
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

    /** A HELLO's protocol version, boot number, firmware version and layout; malformed if the layout does not validate. */
    public record Hello(int version, long boot, String firmware, ChairLayout layout) {
    }

    /**
     * A HELLO's version alone: the first byte of a HELLO (type 0x85, version 3 on); -1 for a body too short, and
     * for the HELLO of versions 1 and 2 (type 0x82), whose first byte cannot tell them apart.
     */
    public static int version(Frame f) {
        byte[] b = f.body();
        return f.type() != Frame.Type.HELLO || b.length == 0 ? -1 : b[0] & 0xFF;
    }

    /** Reads a version-3 HELLO's body (type 0x85); check {@link #version} first. */
    public static Hello readHello(Frame f) {
        Frame.Fields r = f.fields();
        int version = r.u8();
        long boot = r.i32() & 0xFFFFFFFFL;
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
            return new Hello(version, boot, fw, new ChairLayout(length, width, wheel, track, ticks, top, sensors));
        } catch (IllegalArgumentException e) {
            throw new FrameException("malformed", "the HELLO's layout: " + e.getMessage());
        }
    }
}
