package io.concord.sim.board;

import com.fazecast.jSerialComm.SerialPort;

import io.concord.agents.map.HospitalMap;
import io.concord.core.time.Clock;
import io.concord.serial.Board;
import io.concord.serial.FrameCodec;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.SimChair;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.HexFormat;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.concurrent.ConcurrentLinkedQueue;

/**
 * The chair's board on one end of a serial port (a pty of a {@code socat} pair), backed by the
 * hospital simulation's physics for one chair: the same world, the same sensors. A host's driver
 * pointed at the other end drives it as it would drive the real chair.
 *
 * <pre>
 * socat pty,raw,echo=0,link=chair-host pty,raw,echo=0,link=chair-board &amp;
 * java -cp concord-demo.jar io.concord.sim.board.BoardEmulator --port chair-board --at 19
 * </pre>
 *
 * <p>Faults on what the board sends (each a probability per frame): {@code --drop},
 * {@code --corrupt} (one byte flipped), {@code --duplicate}, {@code --reorder} (swapped with the
 * next), {@code --garbage} (random bytes before it); {@code --delay-ms} holds every frame back.
 * {@code --clock-rate 0.99} runs the board's clock 1 % slow (a poor crystal); {@code --boot N}
 * is the boot number it switches on with. On standard input: {@code estop on|off},
 * {@code reboot} (switches on again with the next boot number: motors at zero, counts from 0),
 * {@code status} (one line: motors, watchdog, armed, boot, pose, drops), {@code trip} (the
 * watchdog trips as soon as the motors turn, as after a short host freeze; the host's next frame
 * clears the fault before any STATE shows it), {@code corrupt-rx N} (the next N host frames arrive with a byte flipped),
 * {@code drop-sync} (the host's next SYNC PING is lost on the wire: the board never sees the new
 * session), {@code mute MS} (the board's frames to the host are lost for MS ms while it still
 * hears the host: the host takes the link for lost), {@code trace on|off} (one line per host frame
 * taken: {@code rx DRIVE 600,600 seq=12 t=5030 armed=true motors=600,600}, t the host's time in
 * it), {@code arm-on-neutral} (a faulty firmware: from now on any neutral command arms the board, as
 * version 2 did; for the tests that show what the ARM step stands against), {@code quit}. When the port goes away (unplugged), the board waits for it to return; its motors
 * are at zero by its watchdog meanwhile.
 */
public final class BoardEmulator {
    /** The firmware version it reports. */
    public static final String FIRMWARE = "concord-board-emulator 3";

    private final SerialPort[] port = new SerialPort[1];
    private final String path;
    private final HospitalWorld world;
    private final SimChair chair;
    private final Board board;
    private final Faults faults;
    private final Clock clock;
    private final long startNs;
    private final ConcurrentLinkedQueue<String> commands = new ConcurrentLinkedQueue<>();
    private final PrintStream out;
    private final double clockRate;
    private long boot;
    /** Trips the watchdog as soon as the motors turn (the {@code trip} command). */
    private boolean tripWhenDriving;
    private final boolean paired;
    private boolean macSaid;
    /** Host frames still to corrupt on their way in. */
    private int corruptIn;
    /** Drops the host's next SYNC PING on its way in (the {@code drop-sync} command). */
    private boolean dropSync;
    /** A host frame cut short by a read while {@code drop-sync} looks at whole frames. */
    private final java.io.ByteArrayOutputStream partialIn = new java.io.ByteArrayOutputStream();
    /** Until when (the board's clock) its frames to the host are lost ({@code mute}). */
    private long mutedUntilMs = -1;

    /** Fault probabilities on the board's frames. */
    record Faults(double drop, double corrupt, double duplicate, double reorder, double garbage, long delayMs, SplittableRandom random) {
    }

    private final ArrayDeque<long[]> heldTimes = new ArrayDeque<>();
    private final ArrayDeque<byte[]> held = new ArrayDeque<>();
    private byte[] reorderHeld;

    /** @param clock the real time the board's clock and the world follow (times {@code clockRate} for the board's) */
    BoardEmulator(String path, HospitalMap map, int atNode, long seed, byte[] key, Faults faults, PrintStream out, double clockRate,
                  long boot, Clock clock) {
        this.clock = clock;
        this.startNs = clock.nanoTime();
        this.path = path;
        this.clockRate = clockRate;
        this.boot = boot;
        this.paired = key != null;
        this.faults = faults;
        this.out = out;
        this.world = HospitalWorld.builder(map).seed(seed).doors(false).build();
        this.chair = world.addChair("chair", ChairConfig.standard(), world.poseAt(atNode, 90));
        this.board = new Board(chair, new FrameCodec(key), FIRMWARE, this::emit);
    }

    /** The board's clock: real time, times the clock's rate. */
    private long nowMs() {
        return (long) ((clock.nanoTime() - startNs) / 1e6 * clockRate);
    }

    /** Runs until {@code quit} on standard input. */
    void run() {
        Thread in = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8))) {
                for (String line; (line = r.readLine()) != null; ) {
                    commands.add(line.trim());
                }
            } catch (java.io.IOException e) {
                // standard input closed
            }
        }, "board-stdin");
        in.setDaemon(true);
        in.start();
        byte[] buf = new byte[512];
        long stepNs = (long) (1e9 / world.stepHz());
        boolean switchedOn = false;
        while (true) {
            String cmd = commands.poll();
            if (cmd != null && !command(cmd)) {
                break;
            }
            SerialPort p = port[0];
            if (p == null) {
                p = open();
                if (p == null) {
                    sleep(50);
                } else if (!switchedOn) {
                    switchedOn = true;
                    board.switchOn(boot, nowMs());
                }
            } else {
                // Polled every 0.2 ms, as a board's timer interrupt would: a read's timeout on a pty is
                // only good to about 10 ms, which would delay the watchdog by as much.
                int avail = p.bytesAvailable();
                int n = avail > 0 ? p.readBytes(buf, Math.min(avail, buf.length)) : avail;
                if (n == 0) {
                    java.util.concurrent.locks.LockSupport.parkNanos(200_000);
                }
                if (n < 0 || !Files.exists(Path.of(path))) {
                    p.closePort();
                    port[0] = null;
                    out.println("board: the port " + path + " is gone; waiting for it");
                } else if (n > 0) {
                    corruptIncoming(buf, n);
                    receive(buf, n);
                    if (!macSaid && board.drops().get("mac") > 0) {
                        macSaid = true;
                        out.println("board: a host frame failed its MAC check: the host is paired with another key, or only one end"
                                + " has a key (the board's: " + (paired ? "given" : "none") + ")");
                    }
                }
            }
            while (world.worldTimeNs() + stepNs <= clock.nanoTime() - startNs) {
                world.step();
            }
            if (tripWhenDriving && (board.motors()[0] != 0 || board.motors()[1] != 0)) {
                tripWhenDriving = false;
                board.tripNow(nowMs());
            }
            board.tick(nowMs());
            flushHeld();
        }
    }

    /** Flips a byte of each host frame while {@code corrupt-rx} asks for it (a burst of noise on the line). */
    private void corruptIncoming(byte[] buf, int n) {
        boolean inFrame = false;
        for (int i = 0; i < n && corruptIn > 0; i++) {
            if (buf[i] == 0) {
                if (inFrame) {
                    corruptIn--;
                }
                inFrame = false;
            } else if (!inFrame) {
                inFrame = true;
                int j = Math.min(i + 3, n - 1);
                if (buf[j] != 0) {
                    buf[j] = (byte) (buf[j] == (byte) 0xFF ? 0x7F : buf[j] ^ 0x55);
                    if (buf[j] == 0) {
                        buf[j] = 1;
                    }
                }
            }
        }
    }

    /** The host's bytes to the board, less a SYNC PING that {@code drop-sync} loses. */
    private void receive(byte[] buf, int n) {
        if (!dropSync && partialIn.size() == 0) {
            board.onBytes(buf, 0, n, nowMs());
            return;
        }
        for (int i = 0; i < n; i++) {
            partialIn.write(buf[i]);
            if (buf[i] == 0) {
                byte[] frame = partialIn.toByteArray();
                partialIn.reset();
                // Stuffed, a frame starts with its COBS code byte, then its type and flags (both
                // non-zero in a SYNC PING, so they are the first block's first bytes).
                if (dropSync && frame.length > 3 && frame[1] == io.concord.serial.Frame.Type.PING
                        && (frame[2] & io.concord.serial.Frame.SYNC) != 0) {
                    dropSync = false;
                    out.println("board: the host's SYNC PING was lost on the wire");
                    out.flush();
                } else {
                    board.onBytes(frame, 0, frame.length, nowMs());
                }
            }
        }
    }

    private SerialPort open() {
        if (!Files.exists(Path.of(path))) {
            return null;
        }
        // A relative path is made absolute: jSerialComm would take a bare name for one under /dev.
        SerialPort p = SerialPort.getCommPort(Path.of(path).toAbsolutePath().toString());
        p.setComPortParameters(115_200, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
        p.setComPortTimeouts(SerialPort.TIMEOUT_NONBLOCKING, 0, 0);
        if (!p.openPort()) {
            return null;
        }
        port[0] = p;
        out.println("board: on " + path + (paired ? " (paired: every frame carries a MAC)" : ""));
        return p;
    }

    private boolean command(String cmd) {
        switch (cmd) {
            case "estop on" -> board.estop(true, nowMs());
            case "estop off" -> board.estop(false, nowMs());
            case "trip" -> tripWhenDriving = true;
            case "drop-sync" -> dropSync = true;
            case "arm-on-neutral" -> board.withoutArmStep();
            case "trace on" -> board.setTrace(l -> {
                out.println("rx " + l);
                out.flush();
            });
            case "trace off" -> board.setTrace(null);
            case "reboot" -> {
                boot++;
                board.switchOn(boot, nowMs());
                out.println("board: rebooted, boot " + boot);
            }
            case "status" -> {
                int[] m = board.motors();
                var pose = chair.truePose();
                out.printf(Locale.ROOT, "status motors=%d,%d tripped=%b armed=%b reason=%s boot=%d x=%.3f y=%.3f moved=%.3f accepted=%d"
                                + " drops=%s%n", m[0], m[1], board.tripped(), board.armed(),
                        io.concord.serial.BoardProtocol.disarmedBy(board.disarmedBy()).replace(' ', '-'), board.boot(), pose.x(), pose.y(),
                        chair.distanceTravelled(), board.accepted(), board.drops());
            }
            case "quit" -> {
                return false;
            }
            default -> {
                if (cmd.startsWith("corrupt-rx ") || cmd.startsWith("mute ")) {
                    String n = cmd.substring(cmd.indexOf(' ') + 1).trim();
                    try {
                        if (cmd.startsWith("mute ")) {
                            mutedUntilMs = nowMs() + Long.parseLong(n);
                        } else {
                            corruptIn = Integer.parseInt(n);
                        }
                    } catch (NumberFormatException e) {
                        out.println("board: " + cmd.substring(0, cmd.indexOf(' ')) + " takes a whole number (frames, or ms), not '" + n + "'");
                    }
                } else {
                    out.println("board: commands are estop on, estop off, reboot, trip, corrupt-rx N, drop-sync, mute MS, trace on|off,"
                            + " status, quit; not '" + cmd + "'");
                }
            }
        }
        out.flush();
        return true;
    }

    /** A frame the board sends, through the fault plan. */
    private void emit(byte[] frame) {
        if (mutedUntilMs >= 0 && nowMs() < mutedUntilMs) {
            return;
        }
        SplittableRandom r = faults.random();
        if (r.nextDouble() < faults.drop()) {
            return;
        }
        byte[] f = frame;
        if (r.nextDouble() < faults.corrupt()) {
            f = frame.clone();
            int i = r.nextInt(Math.max(1, f.length - 1));
            f[i] = (byte) (f[i] ^ (1 + r.nextInt(255)));
            if (f[i] == 0) {
                f[i] = 1;
            }
        }
        if (r.nextDouble() < faults.garbage()) {
            byte[] g = new byte[1 + r.nextInt(16)];
            for (int i = 0; i < g.length; i++) {
                g[i] = (byte) r.nextInt(256);
            }
            hold(g);
        }
        if (r.nextDouble() < faults.reorder() && reorderHeld == null) {
            reorderHeld = f;
            return;
        }
        hold(f);
        if (reorderHeld != null) {
            hold(reorderHeld);
            reorderHeld = null;
        }
        if (r.nextDouble() < faults.duplicate()) {
            hold(f);
        }
    }

    private void hold(byte[] b) {
        held.add(b);
        heldTimes.add(new long[] {nowMs() + faults.delayMs()});
    }

    private void flushHeld() {
        SerialPort p = port[0];
        while (!held.isEmpty() && heldTimes.peek()[0] <= nowMs()) {
            byte[] b = held.poll();
            heldTimes.poll();
            if (p != null) {
                p.writeBytes(b, b.length);
            }
        }
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    public static void main(String[] args) {
        String port = null;
        int at = 19;
        long seed = 1;
        byte[] key = null;
        double drop = 0;
        double corrupt = 0;
        double dup = 0;
        double reorder = 0;
        double garbage = 0;
        long delay = 0;
        double clockRate = 1;
        long boot = 1;
        HospitalMap map = HospitalMap.defaultHospital();
        try {
            for (int i = 0; i < args.length; i++) {
                String a = args[i];
                String v = i + 1 < args.length ? args[i + 1] : null;
                switch (a) {
                    case "--port" -> port = need(a, v);
                    case "--at" -> at = Integer.parseInt(need(a, v));
                    case "--seed" -> seed = Long.parseLong(need(a, v));
                    case "--key" -> {
                        try {
                            key = HexFormat.of().parseHex(need(a, v));
                        } catch (IllegalArgumentException e) {
                            throw new IllegalArgumentException("--key takes the pairing key as hex digits (32 or more): " + e.getMessage());
                        }
                        if (key.length < io.concord.serial.PairingKey.MIN_BYTES) {
                            throw new IllegalArgumentException("--key holds " + key.length + " bytes; a pairing key needs "
                                    + io.concord.serial.PairingKey.MIN_BYTES + " or more (32 hex digits or more)");
                        }
                    }
                    case "--pair-key" -> key = io.concord.serial.PairingKey.read(Path.of(need(a, v)));
                    case "--map" -> map = HospitalMap.load(Path.of(need(a, v)));
                    case "--drop" -> drop = Double.parseDouble(need(a, v));
                    case "--corrupt" -> corrupt = Double.parseDouble(need(a, v));
                    case "--duplicate" -> dup = Double.parseDouble(need(a, v));
                    case "--reorder" -> reorder = Double.parseDouble(need(a, v));
                    case "--garbage" -> garbage = Double.parseDouble(need(a, v));
                    case "--delay-ms" -> delay = Long.parseLong(need(a, v));
                    case "--clock-rate" -> clockRate = Double.parseDouble(need(a, v));
                    case "--boot" -> boot = Long.parseLong(need(a, v));
                    default -> throw new IllegalArgumentException("unknown option " + a);
                }
                i++;
            }
            if (port == null) {
                throw new IllegalArgumentException("--port PATH is required (one end of a socat pty pair, or a real port)");
            }
            if (!map.hasNode(at)) {
                throw new IllegalArgumentException("--at " + at + ": the map has no such node");
            }
        } catch (IllegalArgumentException e) {
            System.err.println("board emulator: " + e.getMessage());
            System.err.println("usage: BoardEmulator --port PATH [--at NODE] [--seed N] [--key HEX | --pair-key FILE] [--map FILE]"
                    + " [--drop P] [--corrupt P] [--duplicate P] [--reorder P] [--garbage P] [--delay-ms N] [--clock-rate R] [--boot N]");
            System.exit(2);
            return;
        }
        new BoardEmulator(port, map, at, seed, key, new Faults(drop, corrupt, dup, reorder, garbage, delay, new SplittableRandom(seed)),
                System.out, clockRate, boot, Clock.system()).run();
        System.exit(0);
    }

    private static String need(String opt, String v) {
        if (v == null) {
            throw new IllegalArgumentException(opt + " needs a value");
        }
        return v;
    }
}
