package io.concord.serial;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairReadings;

import java.util.EnumSet;
import java.util.Set;
import java.util.function.Consumer;

/**
 * The chair's board, as docs/chair-protocol.md specifies it, over any byte transport and any
 * motors and sensors (a {@link ChairDriver}: the simulated chair in the emulator). Single-threaded:
 * feed it bytes ({@link #onBytes}) and time ({@link #tick}) from one thread.
 *
 * <p>Its safety rules, which no host frame can override:
 * <ul>
 *   <li>armed only by an ARM (version 3), for its own boot number and its own reason for being
 *       disarmed, with the e-stop released: no neutral command, no heartbeat arms it, so a host
 *       fault that sends frames automatically cannot re-arm it;</li>
 *   <li>disarmed, a DRIVE other than 0, 0 is refused (NAK not armed) and the motors stay at zero;</li>
 *   <li>the watchdog: no valid host frame for {@link #WATCHDOG_MS} while armed and the motors go to
 *       zero, WATCHDOG is reported, and it is disarmed;</li>
 *   <li>switch-on disarms;</li>
 *   <li>the e-stop wins over everything: while pressed the motors are at zero, DRIVE and ARM are
 *       refused (NAK e-stop), and it is disarmed;</li>
 *   <li>a host's new session (a SYNC PING) disarms it: a new host never inherits motion.</li>
 * </ul>
 * Every STATE says whether it is armed and, if not, why (switch-on, watchdog, e-stop, new
 * session), and carries its boot number, one more at every switch-on.
 */
public final class Board {
    /** Silence from the host after which the board stops the motors. */
    public static final long WATCHDOG_MS = 200;
    /** Host frames older than this are stale. */
    public static final long HOST_MAX_AGE_MS = 200;

    private final ChairDriver chair;
    private final FrameCodec codec;
    private final String firmware;
    private final Consumer<byte[]> wire;
    private FrameReceiver receiver;
    private long boot;
    private long nowMs;
    private int seq;
    private long lastHostMs = -1;
    private boolean armed;
    private int disarmedBy = BoardProtocol.DISARMED_SWITCH_ON;
    private long leftBase;
    private long rightBase;
    private boolean tripped;
    private boolean estop;
    private int stateHz = 20;
    private long nextStateMs;
    private int leftPermille;
    private int rightPermille;
    private long accepted;
    private Consumer<String> trace;
    private boolean armStep = true;

    /**
     * @param chair    the motors and sensors
     * @param codec    the frame codec (with the pairing key, if any)
     * @param firmware the version sent in HELLO
     * @param wire     takes the bytes to send to the host
     */
    public Board(ChairDriver chair, FrameCodec codec, String firmware, Consumer<byte[]> wire) {
        this.chair = chair;
        this.codec = codec;
        this.firmware = firmware;
        this.wire = wire;
        this.receiver = new FrameReceiver(codec, false, HOST_MAX_AGE_MS, this::onHostFrame);
    }

    /**
     * This board arms on any neutral command (a STOP, a DRIVE of 0, 0) as version 2 did, not only on an
     * ARM: for the tests that show what the ARM step stands against (the host's heartbeat re-arming the
     * board). Never in firmware.
     */
    public Board withoutArmStep() {
        armStep = false;
        return this;
    }

    /**
     * Switches on at {@code nowMs} on the board's clock with boot number {@code boot} (one more
     * than at the last switch-on): sends HELLO, motors at zero, not armed, its sequence and its
     * encoder counts from 0. Called again, it is a reboot.
     */
    public void switchOn(long boot, long nowMs) {
        this.boot = boot & 0xFFFFFFFFL;
        this.nowMs = nowMs;
        Drops kept = receiver.drops();
        this.receiver = new FrameReceiver(codec, false, HOST_MAX_AGE_MS, this::onHostFrame, kept);
        seq = 0;
        lastHostMs = -1;
        tripped = false;
        stateHz = 20;   // a restarted board sends at 20 Hz until configured again
        halt(BoardProtocol.DISARMED_SWITCH_ON);
        ChairReadings r = chair.latest();
        leftBase = r == null ? 0 : r.leftTicks();
        rightBase = r == null ? 0 : r.rightTicks();
        send(Frame.Type.HELLO, 0, BoardProtocol.hello(this.boot, firmware, chair.layout()));
        nextStateMs = nowMs;
    }

    /** Switches on with boot number 1. */
    public void switchOn(long nowMs) {
        switchOn(1, nowMs);
    }

    /** The boot number it switched on with. */
    public long boot() {
        return boot;
    }

    /** Bytes from the host, in any chunks. */
    public void onBytes(byte[] b, int off, int len, long nowMs) {
        this.nowMs = nowMs;
        receiver.feed(b, off, len, nowMs);
    }

    /** Presses (true) or releases the e-stop. */
    public void estop(boolean pressed, long nowMs) {
        this.nowMs = nowMs;
        estop = pressed;
        if (pressed) {
            halt(BoardProtocol.DISARMED_ESTOP);
        }
    }

    /**
     * Trips the watchdog now, as a host silence would (fault injection for the emulator and
     * tests: the trip a short host freeze causes, which the host's next frame clears).
     */
    public void tripNow(long nowMs) {
        this.nowMs = nowMs;
        if (armed) {
            tripped = true;
            halt(BoardProtocol.DISARMED_WATCHDOG);
        }
    }

    /** Time passes: the watchdog, and the STATE frames at the configured rate. */
    public void tick(long nowMs) {
        this.nowMs = nowMs;
        if (!tripped && armed && lastHostMs >= 0 && nowMs - lastHostMs > WATCHDOG_MS) {
            tripped = true;
            halt(BoardProtocol.DISARMED_WATCHDOG);
        }
        if (estop) {
            chair.stop();
        }
        if (nowMs >= nextStateMs) {
            // On the configured cadence; a board late past a whole period starts it again from now (no burst).
            nextStateMs += 1000 / stateHz;
            if (nextStateMs <= nowMs) {
                nextStateMs = nowMs + 1000 / stateHz;
            }
            sendState();
        }
    }

    private void halt(int why) {
        // A board already disarmed keeps the graver reason: an e-stop or a switch-on is not
        // hidden by the host's new session that followed it.
        if (armed || why == BoardProtocol.DISARMED_SWITCH_ON || why == BoardProtocol.DISARMED_ESTOP) {
            disarmedBy = why;
        }
        armed = false;
        leftPermille = 0;
        rightPermille = 0;
        chair.stop();
    }

    private void onHostFrame(Frame f) {
        lastHostMs = nowMs;
        accepted++;
        if (tripped) {
            tripped = false;
        }
        try {
            act(f);
        } finally {
            if (trace != null) {
                String what = Frame.Type.name(f.type());
                if (f.type() == Frame.Type.DRIVE && f.body().length == 4) {
                    int[] p = BoardProtocol.readDrive(f);
                    what += " " + p[0] + "," + p[1];
                }
                trace.accept(what + ((f.flags() & Frame.SYNC) != 0 ? " SYNC" : "") + " seq=" + f.seq() + " t=" + f.timeMs() + " armed="
                        + armed + " motors=" + leftPermille + "," + rightPermille);
            }
        }
    }

    private void act(Frame f) {
        try {
            switch (f.type()) {
                case Frame.Type.DRIVE -> {
                    int[] p = BoardProtocol.readDrive(f);
                    boolean neutral = p[0] == 0 && p[1] == 0;
                    if (estop) {
                        send(Frame.Type.NAK, 0, BoardProtocol.nak(f.seq(), BoardProtocol.NAK_ESTOP, armed ? BoardProtocol.ARMED : disarmedBy));
                    } else if (neutral) {
                        if (!armStep) {
                            arm();
                        }
                        motors(0, 0);
                    } else if (!armed) {
                        send(Frame.Type.NAK, 0, BoardProtocol.nak(f.seq(), BoardProtocol.NAK_NOT_ARMED, disarmedBy));
                    } else {
                        motors(p[0], p[1]);
                    }
                }
                case Frame.Type.STOP -> {
                    if (!estop && !armStep) {
                        arm();
                    }
                    motors(0, 0);
                }
                case Frame.Type.ARM -> {
                    BoardProtocol.Arm a = BoardProtocol.readArm(f);
                    if (estop) {
                        send(Frame.Type.NAK, 0, BoardProtocol.nak(f.seq(), BoardProtocol.NAK_ESTOP, disarmedBy));
                    } else if (armed) {
                        send(Frame.Type.ACK, 0, BoardProtocol.ack(f.seq(), 0));   // armed already: the host's repeat
                    } else if (a.boot() != boot || a.reason() != disarmedBy) {
                        // The host decided on another state than this one: a reboot or a new disarm since.
                        send(Frame.Type.NAK, 0, BoardProtocol.nak(f.seq(), BoardProtocol.NAK_STALE_ARM, disarmedBy));
                    } else {
                        arm();
                        motors(0, 0);
                        send(Frame.Type.ACK, 0, BoardProtocol.ack(f.seq(), 0));
                    }
                }
                case Frame.Type.CONFIGURE -> {
                    Frame.Fields r = f.fields();
                    int hz = r.u8();
                    r.end();
                    if (hz < 1 || hz > 100) {
                        throw new FrameException("malformed", "a state rate of " + hz + " Hz is outside 1..100");
                    }
                    stateHz = hz;
                    send(Frame.Type.ACK, 0, BoardProtocol.ack(f.seq(), 0));
                }
                case Frame.Type.PING -> {
                    Frame.Fields r = f.fields();
                    long nonce = r.u32();
                    r.end();
                    if ((f.flags() & Frame.SYNC) != 0) {
                        // A new host session: it never inherits the last one's motion, and learns the layout again.
                        halt(BoardProtocol.DISARMED_SESSION);
                        send(Frame.Type.HELLO, 0, BoardProtocol.hello(boot, firmware, chair.layout()));
                    }
                    send(Frame.Type.ACK, 0, BoardProtocol.ack(f.seq(), nonce));
                }
                default -> {
                    receiver.drops().count("unknown-type");
                    send(Frame.Type.NAK, 0, BoardProtocol.nak(f.seq(), BoardProtocol.NAK_UNKNOWN, armed ? BoardProtocol.ARMED : disarmedBy));
                }
            }
        } catch (FrameException e) {
            receiver.drops().count(e.reason());
            send(Frame.Type.NAK, 0, BoardProtocol.nak(f.seq(), BoardProtocol.NAK_MALFORMED, armed ? BoardProtocol.ARMED : disarmedBy));
        }
    }

    private void arm() {
        armed = true;
        disarmedBy = BoardProtocol.ARMED;
    }

    private void motors(int l, int r) {
        leftPermille = l;
        rightPermille = r;
        chair.drive(l / 10.0, r / 10.0);
    }

    private void sendState() {
        ChairReadings r = chair.latest();
        if (r == null) {
            return;
        }
        int[] mm = new int[r.rangeCount()];
        for (int i = 0; i < mm.length; i++) {
            mm[i] = (int) Math.round(r.range(i) * 1000);
        }
        Set<ChairFault> faults = EnumSet.noneOf(ChairFault.class);
        faults.addAll(r.faults());
        faults.remove(ChairFault.LINK);
        if (tripped) {
            faults.add(ChairFault.WATCHDOG);
        } else {
            faults.remove(ChairFault.WATCHDOG);
        }
        send(Frame.Type.STATE, 0, BoardProtocol.state(new BoardProtocol.State(boot, r.leftTicks() - leftBase, r.rightTicks() - rightBase,
                mm, r.bumper(), estop || r.emergencyStop(), armed, armed ? BoardProtocol.ARMED : disarmedBy,
                (int) Math.round(r.batteryVolts() * 1000), faults, r.fix())));
    }

    private void send(int type, int flags, byte[] body) {
        Frame f = new Frame(type, flags, seq, nowMs & 0xFFFFFFFFL, body);
        seq = (seq + 1) & 0xFFFF;
        wire.accept(codec.encode(f));
    }

    /**
     * Told of every host frame taken, after the board acted on it, in one line: its type (a DRIVE
     * with its powers), seq, the host's time in it, then whether the board is armed and its motors
     * ("DRIVE 600,600 seq=12 t=5030 armed=true motors=600,600"); null for none. For the emulator's
     * trace and tests.
     */
    public void setTrace(Consumer<String> t) {
        this.trace = t;
    }

    /** Host frames dropped, by reason. */
    public Drops drops() {
        return receiver.drops();
    }

    /** Host frames taken. */
    public long accepted() {
        return accepted;
    }

    /** The motor powers it applies, per mille. */
    public int[] motors() {
        return new int[] {leftPermille, rightPermille};
    }

    /** True if the watchdog has stopped the motors and no valid host frame has come since. */
    public boolean tripped() {
        return tripped;
    }

    /** Why it is not armed ({@link BoardProtocol#ARMED} when it is). */
    public int disarmedBy() {
        return disarmedBy;
    }

    /** True once an ARM was taken since switch-on, a trip, the e-stop or a new session (or, without the ARM step, a neutral command). */
    public boolean armed() {
        return armed;
    }
}
