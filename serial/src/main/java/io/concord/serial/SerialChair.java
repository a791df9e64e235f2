package io.concord.serial;

import com.fazecast.jSerialComm.SerialPort;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairEvent;
import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Odometry;
import io.concord.agents.chair.Pose;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.time.Clock;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.Set;
import java.util.concurrent.locks.LockSupport;
import java.util.stream.Collectors;

/**
 * A real chair's board over a serial port (docs/chair-protocol.md, version 3), as a
 * {@link ChairDriver}: the control agent drives it as it drives the simulated chair, through a
 * {@link io.concord.agents.chair.ChairSupervisor}.
 *
 * <p>Three threads meet here, and no hop waits for another:
 * <ul>
 *   <li>a reader takes the port's bytes, cuts them into frames, drops and counts corrupt, stale,
 *       repeated, out-of-order and old-boot ones ({@link #drops()}), and hands each STATE, HELLO
 *       and NAK to the runtime's loop (one hop), where the odometry is integrated and the listener
 *       told: the readings, and as events ({@link ChairEvent}) every refusal, every change of the
 *       board's armed bit and every reboot (a new boot number);</li>
 *   <li>the loop sends a drive command at once when the agents change it ({@link #drive}), and
 *       each call confirms the command is still wanted;</li>
 *   <li>a heartbeat thread of its own sends the last command again every
 *       {@link Settings#heartbeatMs()} (the board stops the motors after 200 ms without a frame),
 *       whatever the loop is doing, as long as the loop confirmed it within
 *       {@link Settings#commandDeadlineMs()}; past that it sends one STOP and falls silent, so that
 *       the board trips its watchdog and a frozen host never keeps a chair moving. It also watches
 *       for a silent board.</li>
 * </ul>
 *
 * <p>The command the heartbeat repeats is cleared in one place ({@link #neutralOnly}), by every
 * hold: a new session (the port opened, after a lost link too), a link lost, the supervisor's
 * {@link #holdMotion()}, and a host that was frozen (nothing sent for {@link Settings#frozenMs()}
 * while the command drove: the command predates the freeze, and is never sent after it). Until
 * the supervisor resumes ({@link #releaseMotion()}) only neutral frames go out, whatever the
 * agents ask. The board arms only on an ARM, which goes out only on the supervisor's resume
 * ({@link #arm()}), never from the heartbeat.
 *
 * <p>When the port goes away, or the board falls silent for {@link Settings#silentMs()}, the port
 * is closed, the listener is told the chair is offline (a reading with the LINK fault, then
 * {@code onOnline(false)}), and the port is opened again with back-off (0.1 s doubling to 2 s)
 * until it returns; a new session starts with a SYNC PING, which disarms the board. A board that
 * speaks another version of the protocol is refused: nothing it says is taken, and the log says
 * which version it speaks.
 */
public final class SerialChair implements ChairDriver {
    private static final Logger LOG = LoggerFactory.getLogger(SerialChair.class);
    /** The drift the protocol tolerates, in words. */
    private static final String TOLERANCE = Math.round(SequenceCheck.DRIFT * 100) + " %";

    /**
     * How to reach the board.
     *
     * @param port              the port's path ({@code /dev/ttyUSB0}, a pty's path, {@code COM3})
     * @param baud              bits a second (115200; the frame is 8N1)
     * @param name              the chair's name
     * @param key               the pairing key (16 bytes or more), or null for no MAC
     * @param start             the pose the odometry starts from (the first floor-marker fix replaces it)
     * @param layout            the layout expected until the board's HELLO gives its own
     * @param stateHz           STATE frames a second asked of the board
     * @param heartbeatMs       how often the drive command is sent again
     * @param silentMs          a board silent this long is taken as gone
     * @param commandDeadlineMs a command the loop has not confirmed for this long is not sent again
     * @param frozenMs          a host that has sent nothing for longer than this (frozen, starved) never sends
     *                          the driving command it held: neutral, and a hold (the board's 200 ms watchdog
     *                          less one heartbeat: the board may not have tripped)
     */
    public record Settings(String port, int baud, String name, byte[] key, Pose start, ChairLayout layout, int stateHz,
                           long heartbeatMs, long silentMs, long commandDeadlineMs, long frozenMs) {
        /**
         * 115200 baud, no key, odometry from (0, 0, 0), the standard layout, 20 Hz, heartbeat 50 ms, silent after 500 ms,
         * deadline 300 ms, frozen after 150 ms.
         */
        public static Settings of(String port, String name) {
            return new Settings(port, 115_200, name, null, new Pose(0, 0, 0), ChairLayout.standard(), 20, 50, 500, 300, 150);
        }

        public Settings withKey(byte[] k) {
            return new Settings(port, baud, name, k, start, layout, stateHz, heartbeatMs, silentMs, commandDeadlineMs, frozenMs);
        }

        public Settings withStart(Pose p) {
            return new Settings(port, baud, name, key, p, layout, stateHz, heartbeatMs, silentMs, commandDeadlineMs, frozenMs);
        }

        public Settings withCommandDeadlineMs(long ms) {
            return new Settings(port, baud, name, key, start, layout, stateHz, heartbeatMs, silentMs, ms, frozenMs);
        }
    }

    /** The driver's defences, each switched off only by a test that shows its hazard ({@link #openWithDefences}). */
    public enum Defence {
        /**
         * Every hold (a new session, a lost link, the supervisor's, a frozen host) clears the
         * command and only neutral goes out until {@link #releaseMotion()}; off, the heartbeat
         * sends the last command again after the port reopens.
         */
        NEUTRAL_UNTIL_RESUMED,
        /**
         * A driving command is not sent after the host sent nothing for {@link Settings#frozenMs()};
         * off, the first frame after a freeze is the command from before it.
         */
        NO_FROZEN_COMMAND
    }

    private final Settings settings;
    private final Set<Defence> defences;
    private final AgentRuntime runtime;
    private final Clock clock;
    private final BoardLink.Opener opener;
    private final FrameCodec codec;
    private final FrameReceiver receiver;
    private final Thread reader;
    private final Thread heartbeat;
    /** Guards the port's writes and the sending side's sequence number, session and STOP flag. */
    private final Object sendLock = new Object();
    private volatile BoardLink port;
    private volatile boolean closed;
    private volatile long lastFrameNanos;
    /** True once a frame has come since the port was opened. */
    private volatile boolean heard;
    /** MAC drops counted when the port was opened; whether a mismatch was logged since. */
    private volatile long macAtOpen;
    private volatile boolean macLogged;
    private volatile ChairLayout layout;
    private volatile String firmware;
    private volatile String incompatible;
    /** The command wanted: left per mille in the high half, right in the low. */
    private volatile long command;
    /** When the loop last confirmed the command. */
    private volatile long confirmedNanos;
    private volatile boolean expired;
    private final java.util.concurrent.atomic.AtomicLong nakCount = new java.util.concurrent.atomic.AtomicLong();
    private final java.util.concurrent.atomic.AtomicLong framesSent = new java.util.concurrent.atomic.AtomicLong();
    /** Frames sent since the port was last opened. */
    private volatile long sessionFrames;
    private final java.util.concurrent.atomic.AtomicLong sessions = new java.util.concurrent.atomic.AtomicLong();
    private final java.util.concurrent.atomic.AtomicLong frozenCount = new java.util.concurrent.atomic.AtomicLong();
    /** Drops counted when the last frame was taken: what has been dropped since tells a stale link from a silent one. */
    private volatile long staleAtFrame;
    private volatile long droppedAtFrame;
    /** Whether the drift over the protocol's tolerance was logged in this session. */
    private volatile boolean driftLogged;
    // guarded by sendLock
    private boolean stopSent;
    private int seq;
    private boolean sync = true;
    /** Only neutral goes out until the supervisor resumes ({@link #releaseMotion()}). */
    private boolean motionHeld = true;
    /** When the last frame went to the board in this session, or -1 before the first. */
    private long lastWriteNanos = -1;
    /** Under sendLock: when the last ARM went out, -1 for none this session. */
    private long lastArmNanos = -1;
    /** The last STATE taken (the loop's thread writes it): what an ARM names. */
    private volatile BoardProtocol.State lastState;
    private final java.util.concurrent.atomic.AtomicLong armsSent = new java.util.concurrent.atomic.AtomicLong();
    // heartbeat thread
    private final long[] gapsUs = new long[1 << 16];
    private volatile int gapCount;
    private int gapAt;
    /** When the heartbeat last sent the command, or -1 after a pause (no port, command expired). */
    private long lastSent = -1;
    // loop-confined
    private ChairListener listener;
    private ChairReadings latest;
    private Odometry odometry;
    private boolean online;
    private long boot = -1;
    private Boolean boardArmed;
    private boolean nakLogged;
    private final long startNanos;
    private long reconnects;
    private long accepted;

    /**
     * A driver whose threads are not started: {@link #open} starts them; a test drives its steps
     * ({@link #openPort}, {@link #onBytes}, {@link #beat}) itself on a manual clock.
     *
     * @param clock  every time the driver reads: its frames' times, the heartbeat, the deadlines
     * @param opener opens the link to the board
     */
    SerialChair(AgentRuntime runtime, Settings settings, Clock clock, BoardLink.Opener opener) {
        this(runtime, settings, clock, opener, EnumSet.allOf(Defence.class));
    }

    SerialChair(AgentRuntime runtime, Settings settings, Clock clock, BoardLink.Opener opener, Set<Defence> defences) {
        this.runtime = runtime;
        this.settings = settings;
        this.defences = defences.isEmpty() ? EnumSet.noneOf(Defence.class) : EnumSet.copyOf(defences);
        this.clock = clock;
        this.opener = opener;
        this.startNanos = clock.nanoTime();
        this.confirmedNanos = startNanos;
        this.codec = new FrameCodec(settings.key());
        this.layout = settings.layout();
        this.odometry = new Odometry(settings.layout(), settings.start());
        this.receiver = new FrameReceiver(codec, true, FrameReceiver.BOARD_FRAME_MAX_AGE_MS, this::onBoardFrame);
        this.reader = new Thread(this::readLoop, "serial-" + settings.name());
        this.reader.setDaemon(true);
        this.heartbeat = new Thread(this::heartbeatLoop, "serial-heartbeat-" + settings.name());
        this.heartbeat.setDaemon(true);
        this.heartbeat.setPriority(Thread.MAX_PRIORITY);
    }

    /**
     * Opens the board's port and starts the link. Call on the runtime's loop, or before it runs.
     *
     * @throws IllegalArgumentException if there is no such port (the message lists the ports found,
     *                                  and says that pseudo-terminals are not among them)
     */
    public static SerialChair open(AgentRuntime runtime, Settings settings) {
        return openWithDefences(runtime, settings, EnumSet.allOf(Defence.class));
    }

    /**
     * As {@link #open}, with only some of the driver's defences: for the tests that show what each
     * one stands against. Never use it to drive a chair.
     */
    public static SerialChair openWithDefences(AgentRuntime runtime, Settings settings, Set<Defence> defences) {
        if (!Files.exists(Path.of(settings.port())) && !settings.port().toUpperCase().startsWith("COM")) {
            String found = Arrays.stream(SerialPort.getCommPorts()).map(SerialPort::getSystemPortPath).collect(Collectors.joining(", "));
            throw new IllegalArgumentException("no serial port at " + settings.port() + "; ports found: "
                    + (found.isEmpty() ? "none" : found) + " (pseudo-terminals, such as socat's, are never listed: give their path)");
        }
        SerialChair c = new SerialChair(runtime, settings, Clock.system(), () -> openSerialPort(settings), defences);
        c.reader.start();
        c.heartbeat.start();
        return c;
    }

    // ---- ChairDriver ------------------------------------------------------------------------------

    @Override
    public String name() {
        return settings.name();
    }

    @Override
    public ChairLayout layout() {
        return layout;
    }

    /** Sets the command and confirms it; it goes out at once if it changed, and with each heartbeat while confirmed. */
    @Override
    public void drive(double leftPercent, double rightPercent) {
        command(permille(leftPercent), permille(rightPercent));
    }

    private static int permille(double pct) {
        if (Double.isNaN(pct)) {
            return 0;
        }
        return (int) Math.round(Math.max(-100, Math.min(100, pct)) * 10);
    }

    @Override
    public void stop() {
        command(0, 0);
    }

    private void command(int l, int r) {
        long c = ((long) l << 32) | (r & 0xFFFFFFFFL);
        boolean change;
        synchronized (sendLock) {
            if (motionHeld && defences.contains(Defence.NEUTRAL_UNTIL_RESUMED)) {
                c = 0; // held: a command given now is not kept for after the resume
            }
            change = c != command || expired;
            command = c;
        }
        confirmedNanos = clock.nanoTime();
        if (change) {
            expired = false;
            sendCommand();
        }
    }

    /** The supervisor holds motion: the command is forgotten, neutral goes out at once and until {@link #releaseMotion()}. */
    @Override
    public void holdMotion() {
        if (!defences.contains(Defence.NEUTRAL_UNTIL_RESUMED)) {
            stop();
            return;
        }
        neutralOnly();
        expired = false;
        confirmedNanos = clock.nanoTime();
        sendCommand();
    }

    /** The supervisor resumed: the agents' commands go out again. */
    @Override
    public void releaseMotion() {
        synchronized (sendLock) {
            motionHeld = false;
        }
    }

    /**
     * The supervisor's resume, while the board is not armed: one ARM for the boot number and the
     * reason the last STATE showed (at most one per {@link #ARM_REPEAT_MS}; the supervisor asks again
     * at each reading until a STATE says armed). Nothing when the last STATE showed the board armed
     * or its e-stop pressed, before a new session's first STATE, or with a board of another version.
     * The heartbeat never sends an ARM. The loop's thread.
     */
    @Override
    public void arm() {
        BoardProtocol.State s = lastState;
        if (s == null || s.armed() || s.estop() || incompatible != null) {
            return;
        }
        long now = clock.nanoTime();
        synchronized (sendLock) {
            if (port == null || sync || lastArmNanos >= 0 && now - lastArmNanos < ARM_REPEAT_MS * 1_000_000) {
                return;
            }
            lastArmNanos = now;
            write(Frame.Type.ARM, BoardProtocol.arm(s.boot(), s.reason()));
        }
        armsSent.incrementAndGet();
    }

    /** True if the board's last word (a STATE, a NAK, a new boot) says it is armed. The loop's thread. */
    public boolean boardArmed() {
        return Boolean.TRUE.equals(boardArmed);
    }

    /** The least time between two ARMs. */
    public static final long ARM_REPEAT_MS = 100;

    /** ARM frames sent: one per resume, and again for one lost or stale. */
    public long armsSent() {
        return armsSent.get();
    }

    /** True while only neutral goes out (a hold, until the supervisor resumes). */
    public boolean motionHeld() {
        synchronized (sendLock) {
            return motionHeld;
        }
    }

    /**
     * The one place a hold clears the command: the heartbeat forgets it, the next frame is a STOP,
     * and only neutral goes out until {@link #releaseMotion()}. Every hold comes here: a new
     * session, a lost link, the supervisor's, a frozen host. Any thread.
     */
    private void neutralOnly() {
        if (!defences.contains(Defence.NEUTRAL_UNTIL_RESUMED)) {
            return;
        }
        synchronized (sendLock) {
            command = 0;
            stopSent = false;
            motionHeld = true;
        }
    }

    @Override
    public ChairReadings latest() {
        return latest;
    }

    @Override
    public boolean online() {
        return online;
    }

    /** The board arms: it says so in every STATE, and refuses what it does not take. */
    @Override
    public boolean reportsArming() {
        return true;
    }

    @Override
    public void setListener(ChairListener l) {
        this.listener = l;
    }

    // ---- what it can tell -------------------------------------------------------------------------

    /** Frames dropped, by reason. */
    public Drops drops() {
        return receiver.drops();
    }

    /** Frames taken. */
    public long accepted() {
        return accepted;
    }

    /** Frames sent to the board, of every type. */
    public long framesSent() {
        return framesSent.get();
    }

    /** How often the port was opened: each opening starts a session (a SYNC PING first). */
    public long sessions() {
        return sessions.get();
    }

    /** Frames sent to the board since the port was last opened (a new session's SYNC PING and CONFIGURE first). */
    public long sessionFramesSent() {
        return sessionFrames;
    }

    /** How often a frozen host's command was not sent (nothing sent for over {@link Settings#frozenMs()}). */
    public long frozen() {
        return frozenCount.get();
    }

    /**
     * The board's clock drift against the host's, as measured since the session or the board's
     * restart began (0.03: the board's clock runs 3 % slow; negative: fast); NaN before a second
     * of frames.
     */
    public double drift() {
        return receiver.drift();
    }

    /** Refusals (NAKs) received. */
    public long refusals() {
        return nakCount.get();
    }

    @Override
    public java.util.Map<String, Long> linkDrops() {
        return receiver.drops().snapshot();
    }

    /** The board's firmware version, from its HELLO, or null. */
    public String firmware() {
        return firmware;
    }

    /** Why the board is refused (it speaks another version of the protocol), or null. */
    public String incompatible() {
        return incompatible;
    }

    @Override
    public String whyOffline() {
        if (incompatible != null) {
            return incompatible;
        }
        if (online) {
            return null;
        }
        if (port == null) {
            return "the port " + settings.port() + " is not there, or cannot be opened";
        }
        if (!heard && receiver.drops().get("mac") > macAtOpen) {
            return macMismatch();
        }
        return heard ? null : "the board on " + settings.port() + " says nothing";
    }

    private String macMismatch() {
        return "every frame from the board fails its MAC check: the board is paired with another key, or only one end has a"
                + " key; give both ends the same pairing key (--pair-key)";
    }

    /** The board's boot number, from its HELLO or STATE, or -1 before the first. */
    public long boot() {
        return receiver.boot();
    }

    /** How often the link has come back after going down. */
    public long reconnects() {
        return reconnects;
    }

    /**
     * The gaps between the heartbeat's frames so far (at most the last 65,536), in milliseconds:
     * what the board's watchdog sees of a busy host.
     */
    public double[] heartbeatGapsMs() {
        int n = Math.min(gapCount, gapsUs.length);
        double[] out = new double[n];
        for (int i = 0; i < n; i++) {
            out[i] = gapsUs[i] / 1000.0;
        }
        return out;
    }

    /** Stops the chair, closes the port and ends the reader and the heartbeat. */
    public void close() {
        Runnable r = () -> {
            stop();
            closed = true;
            LockSupport.unpark(heartbeat);
            closePort();
        };
        if (runtime.inLoop()) {
            r.run();
        } else {
            runtime.execute(r);
        }
    }

    // ---- sending (the loop, and the heartbeat thread) ------------------------------------------------

    private void heartbeatLoop() {
        long period = settings.heartbeatMs() * 1_000_000;
        long next = clock.nanoTime() + period;
        while (!closed) {
            long wait = next - clock.nanoTime();
            if (wait > 0) {
                LockSupport.parkNanos(wait);
                continue;
            }
            long now = clock.nanoTime();
            next = Math.max(next + period, now + period / 2);
            beat(now);
        }
    }

    /**
     * One heartbeat at {@code now} (the heartbeat thread's, or a test's): watches for a silent
     * board, then sends the command again if the loop confirmed it within the deadline; past the
     * deadline, one STOP and then nothing until the loop confirms a command again.
     */
    void beat(long now) {
        watchSilence(now);
        if (port == null) {
            lastSent = -1;
            return;
        }
        if (now - confirmedNanos > settings.commandDeadlineMs() * 1_000_000) {
            if (!expired) {
                // The loop has not confirmed the command in time (frozen, or far behind): one
                // STOP, then silence, so that the board trips and needs a decision to drive again.
                expired = true;
                LOG.warn("{}: the agents have not confirmed the drive command for {} ms (over {} ms): sends STOP and"
                        + " stops the heartbeat; the board's watchdog trips", settings.name(), (now - confirmedNanos) / 1_000_000,
                        settings.commandDeadlineMs());
                synchronized (sendLock) {
                    command = 0;
                    stopSent = false;
                }
                sendCommand();
            }
            lastSent = -1;
            return;
        }
        sendCommand();
        if (lastSent >= 0) {
            gapsUs[gapAt] = (now - lastSent) / 1_000;
            gapAt = (gapAt + 1) & (gapsUs.length - 1);
            gapCount++;
        }
        lastSent = now;
    }

    private void watchSilence(long now) {
        if (!heard && !macLogged && port != null && receiver.drops().get("mac") >= macAtOpen + 10) {
            macLogged = true;
            LOG.error("{}: {} ({} frames dropped)", settings.name(), macMismatch(), receiver.drops().get("mac") - macAtOpen);
        }
        double drift = receiver.drift();
        if (!driftLogged && port != null && receiver.driftSpanMs() >= 10_000 && Math.abs(drift) > SequenceCheck.DRIFT) {
            driftLogged = true;
            LOG.warn("{}: {}: its frames grow late by {} ms a second, and are stale once {} ms late", settings.name(), driftWords(drift),
                    Math.round((Math.abs(drift) - SequenceCheck.DRIFT) * 1000), FrameReceiver.BOARD_FRAME_MAX_AGE_MS);
        }
        if (heard && port != null && now - lastFrameNanos > settings.silentMs() * 1_000_000) {
            long silent = (now - lastFrameNanos) / 1_000_000;
            long stale = receiver.drops().get("stale") - staleAtFrame;
            long dropped = receiver.drops().total() - droppedAtFrame;
            if (stale > 0 && stale == dropped) {
                lost("every frame stale: " + driftWords(drift) + "; " + stale + " frames in " + silent + " ms were dropped as over "
                        + FrameReceiver.BOARD_FRAME_MAX_AGE_MS + " ms late");
            } else if (dropped > 0) {
                lost("every frame from the board was dropped for " + silent + " ms (" + dropped + " frames, " + stale + " of them stale;"
                        + " drops so far: " + receiver.drops() + ")");
            } else {
                lost("the board has been silent for " + silent + " ms");
            }
        }
    }

    /** The measured drift in words: "the board's clock drifts more than 2 % (3.0 % slow, measured over 50.5 s)". */
    private String driftWords(double drift) {
        if (Double.isNaN(drift)) {
            return "the board's clock drifts more than " + TOLERANCE + " (too few frames to measure by how much)";
        }
        String over = Math.abs(drift) > SequenceCheck.DRIFT ? "more than" : "within";
        return "the board's clock drifts " + over + " " + TOLERANCE + " (" + pct(Math.abs(drift)) + " % "
                + (drift >= 0 ? "slow" : "fast") + ", measured over " + String.format(java.util.Locale.ROOT, "%.1f", receiver.driftSpanMs() / 1000.0)
                + " s)";
    }

    private static String pct(double fraction) {
        return String.format(java.util.Locale.ROOT, "%.1f", fraction * 100);
    }

    private void sendCommand() {
        String frozeWhy = null;
        synchronized (sendLock) {
            long now = clock.nanoTime();
            long c = motionHeld && defences.contains(Defence.NEUTRAL_UNTIL_RESUMED) ? 0 : command;
            if (c != 0 && port != null && lastWriteNanos >= 0 && now - lastWriteNanos > settings.frozenMs() * 1_000_000
                    && defences.contains(Defence.NO_FROZEN_COMMAND)) {
                // Nothing went to the board for longer than the freeze limit: the host was frozen
                // or starved, and the command it holds was decided before that. Never sent: the
                // board may not have tripped, and would drive on it.
                frozeWhy = "nothing was sent to the board for " + (now - lastWriteNanos) / 1_000_000 + " ms (over "
                        + settings.frozenMs() + " ms: the host was frozen or late); the command it held, confirmed "
                        + (now - confirmedNanos) / 1_000_000 + " ms ago, is not sent";
                frozenCount.incrementAndGet();
                command = 0;
                stopSent = false;
                if (defences.contains(Defence.NEUTRAL_UNTIL_RESUMED)) {
                    motionHeld = true;
                }
                c = 0;
            }
            int l = (int) (c >> 32);
            int r = (int) c;
            boolean neutral = l == 0 && r == 0;
            if (neutral && !stopSent) {
                stopSent = write(Frame.Type.STOP, new byte[0]);
            } else {
                if (!neutral) {
                    stopSent = false;
                }
                write(Frame.Type.DRIVE, BoardProtocol.drive(l, r));
            }
        }
        if (frozeWhy != null) {
            String why = frozeWhy;
            LOG.warn("{}: {}: sends STOP and holds motion until the supervisor resumes", settings.name(), why);
            runtime.execute(() -> event(new ChairEvent(ChairEvent.Kind.HOST_FROZEN, why)));
        }
    }

    /** Under sendLock. */
    private boolean write(int type, byte[] body) {
        BoardLink p = port;
        if (p == null) {
            return false;
        }
        if (sync) {
            // A new session: the board starts counting again, disarms and sends its HELLO.
            sync = false;
            sendFrame(p, Frame.Type.PING, Frame.SYNC, BoardProtocol.ping(seq));
            sendFrame(p, Frame.Type.CONFIGURE, 0, BoardProtocol.configure(settings.stateHz()));
        }
        return sendFrame(p, type, 0, body);
    }

    private boolean sendFrame(BoardLink p, int type, int flags, byte[] body) {
        byte[] b = codec.encode(new Frame(type, flags, seq, nowMs(), body));
        seq = (seq + 1) & 0xFFFF;
        lastWriteNanos = clock.nanoTime();
        framesSent.incrementAndGet();
        sessionFrames++;
        return p.write(b);
    }

    private long nowMs() {
        return ((clock.nanoTime() - startNanos) / 1_000_000) & 0xFFFFFFFFL;
    }

    // ---- receiving (reader thread, then the loop) ---------------------------------------------------

    private void readLoop() {
        byte[] buf = new byte[1024];
        long backoffMs = 100;
        while (!closed) {
            BoardLink p = port;
            if (p == null) {
                if (openPort()) {
                    backoffMs = 100;
                } else {
                    sleep(backoffMs);
                    backoffMs = Math.min(2_000, backoffMs * 2);
                }
                continue;
            }
            int n = p.read(buf);
            if (port != p) {
                continue; // closed meanwhile (a silent board, or close())
            }
            if (n < 0) {
                lost("the port " + settings.port() + " is gone");
                continue;
            }
            if (n > 0) {
                onBytes(buf, n);
            }
        }
    }

    /** The board's next bytes, as they came off the port (the reader thread, or a test). */
    void onBytes(byte[] buf, int n) {
        receiver.feed(buf, 0, n, nowMs());
    }

    /** Opens the link and starts a new session on it; false if it cannot be opened now (the reader thread, or a test). */
    boolean openPort() {
        if (closed) {
            return false;
        }
        BoardLink p = opener.open();
        if (p == null) {
            return false;
        }
        receiver.reset();
        lastFrameNanos = clock.nanoTime();
        heard = false;
        macAtOpen = receiver.drops().get("mac");
        macLogged = false;
        staleAtFrame = receiver.drops().get("stale");
        droppedAtFrame = receiver.drops().total();
        driftLogged = false;
        lastState = null;   // an ARM waits for this session's first STATE
        synchronized (sendLock) {
            // A new session never carries the last one's command: cleared before the port is used.
            neutralOnly();
            lastArmNanos = -1;
            sync = true;
            stopSent = false;
            lastWriteNanos = -1;
            sessionFrames = 0;
            port = p;
        }
        sessions.incrementAndGet();
        LOG.info("{}: opened {}{}", settings.name(), settings.port(), codec.paired() ? " (paired: every frame carries a MAC)" : "");
        return true;
    }

    /** The board's serial port, opened and set up; null if it is not there or cannot be opened now. */
    private static BoardLink openSerialPort(Settings settings) {
        if (!Files.exists(Path.of(settings.port())) && !settings.port().toUpperCase().startsWith("COM")) {
            return null;
        }
        // A relative path is made absolute: jSerialComm would take a bare name for one under /dev.
        String where = settings.port().toUpperCase().startsWith("COM") ? settings.port() : Path.of(settings.port()).toAbsolutePath().toString();
        SerialPort p = SerialPort.getCommPort(where);
        p.setComPortParameters(settings.baud(), 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
        // A read returns as soon as a byte is there (a timeout on a pty is only good to about 10 ms,
        // which a STATE frame's way to the agent then carried); the heartbeat thread watches for a
        // silent board, and closing the port ends a read.
        p.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING, 0, 0);
        if (!p.openPort()) {
            LOG.warn("{}: cannot open {} (error {}); tries again", settings.name(), settings.port(), p.getLastErrorCode());
            return null;
        }
        return new SerialPortLink(p, Path.of(settings.port()));
    }

    private void lost(String why) {
        if (port == null) {
            return;
        }
        neutralOnly();
        closePort();
        LOG.warn("{}: link down: {}; opens the port again when it returns (frames dropped so far: {})", settings.name(), why,
                receiver.drops());
        runtime.execute(() -> {
            event(new ChairEvent(ChairEvent.Kind.LINK_LOST, why));
            setOnline(false);
        });
    }

    private void closePort() {
        BoardLink p;
        synchronized (sendLock) {
            p = port;
            port = null;
        }
        if (p != null) {
            p.close();
        }
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void onBoardFrame(Frame f) {
        lastFrameNanos = clock.nanoTime();
        heard = true;
        staleAtFrame = receiver.drops().get("stale");
        droppedAtFrame = receiver.drops().total();
        accepted++;
        try {
            switch (f.type()) {
                case Frame.Type.STATE -> {
                    if (incompatible != null) {
                        receiver.drops().count("incompatible");
                        return;
                    }
                    BoardProtocol.State s = BoardProtocol.readState(f);
                    if (s.rangesMm().length != layout.sensors().size()) {
                        throw new FrameException("malformed", s.rangesMm().length + " ranges, the layout has " + layout.sensors().size());
                    }
                    runtime.execute(() -> onState(f, s));
                }
                case Frame.Type.HELLO, Frame.Type.OLD_HELLO -> {
                    int v = BoardProtocol.version(f);
                    if (v != BoardProtocol.VERSION) {
                        String speaks = f.type() == Frame.Type.OLD_HELLO ? "version 1 or 2 of the chair protocol (its HELLO has type 0x82)"
                                : "version " + v + " of the chair protocol (the first byte of its HELLO)";
                        String why = "the board speaks " + speaks + ", this host speaks version "
                                + BoardProtocol.VERSION + ": nothing the board says is taken; update its firmware to"
                                + " docs/chair-protocol.md version " + BoardProtocol.VERSION;
                        if (!why.equals(incompatible)) {
                            LOG.error("{}: {}", settings.name(), why);
                        }
                        incompatible = why;
                        receiver.drops().count("incompatible");
                        runtime.execute(() -> event(new ChairEvent(ChairEvent.Kind.INCOMPATIBLE, why)));
                        return;
                    }
                    incompatible = null;
                    BoardProtocol.Hello h = BoardProtocol.readHello(f);
                    firmware = h.firmware();
                    runtime.execute(() -> onHello(h));
                }
                case Frame.Type.NAK -> {
                    BoardProtocol.Nak n = BoardProtocol.readNak(f);
                    nakCount.incrementAndGet();
                    runtime.execute(() -> onNak(n));
                }
                case Frame.Type.ACK -> { }
                default -> receiver.drops().count("unknown-type");
            }
        } catch (FrameException e) {
            receiver.drops().count(e.reason());
        }
    }

    private void onHello(BoardProtocol.Hello h) {
        rebooted(h.boot());
        ChairLayout l = h.layout();
        if (!l.equals(layout)) {
            LOG.info("{}: the board's layout replaces the one expected", settings.name());
        }
        layout = l;
        Pose at = odometry.pose();
        odometry = new Odometry(l, at);
    }

    /** A new boot number: the board restarted (its counts from zero, its motors stopped, not armed). */
    private void rebooted(long b) {
        if (boot >= 0 && b != boot) {
            String detail = "boot " + b + " after boot " + boot;
            LOG.warn("{}: the board restarted ({}): its encoder counts start again; the odometry keeps its pose", settings.name(), detail);
            odometry.reset(odometry.pose());
            boardArmed = false;
            boot = b;
            event(new ChairEvent(ChairEvent.Kind.REBOOTED, detail));
        }
        boot = b;
    }

    private void onNak(BoardProtocol.Nak n) {
        if (n.reason() == BoardProtocol.NAK_STALE_ARM) {
            // An ARM for a state the board has left (a reboot, a new disarm): the supervisor asks
            // again on the next STATE, for the state it shows; not a refusal of a command.
            LOG.info("{}: the board refused an ARM for another state (now not armed: {}); arms again on its next STATE",
                    settings.name(), BoardProtocol.disarmedBy(n.disarmedBy()));
            return;
        }
        if (n.disarmedBy() != BoardProtocol.ARMED && !Boolean.FALSE.equals(boardArmed)) {
            // The refusal says the board is not armed, and why, before any STATE could: the
            // host's next neutral command may re-arm it before the next STATE is sent.
            boardArmed = false;
            event(new ChairEvent(ChairEvent.Kind.DISARMED, BoardProtocol.disarmedBy(n.disarmedBy())));
        }
        String detail = "NAK " + BoardProtocol.nakReason(n.reason()) + " for frame " + n.seq();
        if (!nakLogged) {
            nakLogged = true;
            LOG.warn("{}: the board refused a command: {} (further refusals are counted until it is armed again)", settings.name(), detail);
        }
        event(new ChairEvent(ChairEvent.Kind.REFUSED, detail));
    }

    private void event(ChairEvent e) {
        if (listener != null) {
            listener.onEvent(e);
        }
    }

    private void onState(Frame f, BoardProtocol.State s) {
        lastState = s;
        if (!online) {
            setOnline(true);
        }
        rebooted(s.boot());
        if (boardArmed == null || boardArmed != s.armed()) {
            boardArmed = s.armed();
            if (s.armed()) {
                nakLogged = false;
                event(new ChairEvent(ChairEvent.Kind.ARMED, null));
            } else {
                event(new ChairEvent(ChairEvent.Kind.DISARMED, BoardProtocol.disarmedBy(s.reason())));
            }
        }
        Pose odo = odometry.update(s.leftTicks(), s.rightTicks());
        double[] ranges = new double[s.rangesMm().length];
        for (int i = 0; i < ranges.length; i++) {
            ranges[i] = s.rangesMm()[i] == BoardProtocol.NO_RANGE ? layout.sensors().get(i).maxRangeM() : s.rangesMm()[i] / 1000.0;
        }
        latest = new ChairReadings(f.timeMs() * 1_000_000, f.seq(), s.leftTicks(), s.rightTicks(), ranges, s.bumper(),
                s.batteryMv() / 1000.0, s.estop(), s.faults(), odo, s.fix());
        if (listener != null) {
            listener.onReadings(latest);
        }
    }

    private void setOnline(boolean up) {
        if (up == online) {
            return;
        }
        online = up;
        boardArmed = null;
        if (up) {
            reconnects++;
        }
        if (!up && latest != null) {
            Set<ChairFault> faults = EnumSet.of(ChairFault.LINK);
            faults.addAll(latest.faults());
            latest = new ChairReadings(latest.timeNs(), latest.seq(), latest.leftTicks(), latest.rightTicks(), latest.ranges(),
                    latest.bumper(), latest.batteryVolts(), latest.emergencyStop(), faults, latest.odometry(), null);
            if (listener != null) {
                listener.onReadings(latest);
            }
        }
        if (listener != null) {
            listener.onOnline(up);
        }
    }
}
