package io.concord.serial;

import com.fazecast.jSerialComm.SerialPort;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Odometry;
import io.concord.agents.chair.Pose;
import io.concord.core.agent.AgentRuntime;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.Set;
import java.util.stream.Collectors;

/**
 * A real chair's board over a serial port (docs/chair-protocol.md), as a {@link ChairDriver}: the
 * control agent drives it as it drives the simulated chair.
 *
 * <p>A reader thread takes the port's bytes, cuts them into frames, drops and counts corrupt,
 * stale, repeated and out-of-order ones ({@link #drops()}), and hands each STATE to the runtime's
 * loop (one hop), where the odometry is integrated and the listener told. On the loop, a drive
 * command goes out at once and again every {@link Settings#heartbeatMs()} (the board stops the
 * motors after 200 ms without one). When the port goes away, or the board falls silent for
 * {@link Settings#silentMs()}, the port is closed, the listener is told the chair is offline (a
 * reading with the LINK fault, then {@code onOnline(false)}), and the port is opened again with
 * back-off (0.1 s doubling to 2 s) until it returns; a new session starts with a SYNC PING.
 */
public final class SerialChair implements ChairDriver {
    private static final Logger LOG = LoggerFactory.getLogger(SerialChair.class);

    /**
     * How to reach the board.
     *
     * @param port        the port's path ({@code /dev/ttyUSB0}, a pty's path, {@code COM3})
     * @param baud        bits a second (115200; the frame is 8N1)
     * @param name        the chair's name
     * @param key         the pairing key (16 bytes or more), or null for no MAC
     * @param start       the pose the odometry starts from (the first floor-marker fix replaces it)
     * @param layout      the layout expected until the board's HELLO gives its own
     * @param stateHz     STATE frames a second asked of the board
     * @param heartbeatMs how often the drive command is sent again
     * @param silentMs    a board silent this long is taken as gone
     */
    public record Settings(String port, int baud, String name, byte[] key, Pose start, ChairLayout layout, int stateHz,
                           long heartbeatMs, long silentMs) {
        /** 115200 baud, no key, odometry from (0, 0, 0), the standard layout, 20 Hz, heartbeat 50 ms, silent after 500 ms. */
        public static Settings of(String port, String name) {
            return new Settings(port, 115_200, name, null, new Pose(0, 0, 0), ChairLayout.standard(), 20, 50, 500);
        }

        public Settings withKey(byte[] k) {
            return new Settings(port, baud, name, k, start, layout, stateHz, heartbeatMs, silentMs);
        }

        public Settings withStart(Pose p) {
            return new Settings(port, baud, name, key, p, layout, stateHz, heartbeatMs, silentMs);
        }
    }

    private final Settings settings;
    private final AgentRuntime runtime;
    private final FrameCodec codec;
    private final FrameReceiver receiver;
    private final Thread reader;
    private final Object portLock = new Object();
    private volatile SerialPort port;
    private volatile boolean closed;
    private volatile long lastFrameNanos;
    private volatile ChairLayout layout;
    private volatile String firmware;
    // loop-confined
    private ChairListener listener;
    private ChairReadings latest;
    private Odometry odometry;
    private boolean online;
    private int leftPermille;
    private int rightPermille;
    private boolean stopSent;
    private long heartbeatTimer = -1;
    private int seq;
    private boolean sync = true;
    private final long startNanos = System.nanoTime();
    private long reconnects;
    private long accepted;

    private SerialChair(AgentRuntime runtime, Settings settings) {
        this.runtime = runtime;
        this.settings = settings;
        this.codec = new FrameCodec(settings.key());
        this.layout = settings.layout();
        this.odometry = new Odometry(settings.layout(), settings.start());
        this.receiver = new FrameReceiver(codec, true, 500, this::onBoardFrame);
        this.reader = new Thread(this::readLoop, "serial-" + settings.name());
        this.reader.setDaemon(true);
    }

    /**
     * Opens the board's port and starts the link. Call on the runtime's loop, or before it runs.
     *
     * @throws IllegalArgumentException if there is no such port (the message lists the ports found,
     *                                  and says that pseudo-terminals are not among them)
     */
    public static SerialChair open(AgentRuntime runtime, Settings settings) {
        if (!Files.exists(Path.of(settings.port())) && !settings.port().toUpperCase().startsWith("COM")) {
            String found = Arrays.stream(SerialPort.getCommPorts()).map(SerialPort::getSystemPortPath).collect(Collectors.joining(", "));
            throw new IllegalArgumentException("no serial port at " + settings.port() + "; ports found: "
                    + (found.isEmpty() ? "none" : found) + " (pseudo-terminals, such as socat's, are never listed: give their path)");
        }
        SerialChair c = new SerialChair(runtime, settings);
        c.reader.start();
        c.heartbeatTimer = runtime.schedule(runtime.nowNs() + settings.heartbeatMs() * 1_000_000, c::heartbeat);
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

    @Override
    public void drive(double leftPercent, double rightPercent) {
        int l = permille(leftPercent);
        int r = permille(rightPercent);
        boolean change = l != leftPermille || r != rightPermille;
        leftPermille = l;
        rightPermille = r;
        if (change) {
            sendCommand();
        }
    }

    private static int permille(double pct) {
        if (Double.isNaN(pct)) {
            return 0;
        }
        return (int) Math.round(Math.max(-100, Math.min(100, pct)) * 10);
    }

    @Override
    public void stop() {
        boolean change = leftPermille != 0 || rightPermille != 0 || !stopSent;
        leftPermille = 0;
        rightPermille = 0;
        if (change) {
            sendCommand();
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

    /** The board's firmware version, from its HELLO, or null. */
    public String firmware() {
        return firmware;
    }

    /** How often the link has come back after going down. */
    public long reconnects() {
        return reconnects;
    }

    /** Stops the chair, closes the port and ends the reader. */
    public void close() {
        runtime.execute(() -> {
            stop();
            runtime.cancel(heartbeatTimer);
            closed = true;
            closePort();
        });
    }

    // ---- sending (loop) ---------------------------------------------------------------------------

    private void heartbeat() {
        if (closed) {
            return;
        }
        if (online && port != null && System.nanoTime() - lastFrameNanos > settings.silentMs() * 1_000_000) {
            SerialPort p = port;
            long silent = (System.nanoTime() - lastFrameNanos) / 1_000_000;
            // Closing the port ends the reader's read; the reader then opens it again.
            closePort();
            LOG.warn("{}: link down: the board has been silent for {} ms; opens the port again", settings.name(), silent);
            setOnline(false);
            if (p != null) {
                lastFrameNanos = System.nanoTime();
            }
        }
        sendCommand();
        heartbeatTimer = runtime.schedule(runtime.nowNs() + settings.heartbeatMs() * 1_000_000, this::heartbeat);
    }

    private void sendCommand() {
        boolean neutral = leftPermille == 0 && rightPermille == 0;
        if (neutral && !stopSent) {
            stopSent = write(Frame.Type.STOP, new byte[0]);
        } else {
            if (!neutral) {
                stopSent = false;
            }
            write(Frame.Type.DRIVE, BoardProtocol.drive(leftPermille, rightPermille));
        }
    }

    private boolean write(int type, byte[] body) {
        SerialPort p = port;
        if (p == null) {
            return false;
        }
        if (sync) {
            // A new session: the board starts counting again and sends its HELLO.
            sync = false;
            sendFrame(p, Frame.Type.PING, Frame.SYNC, BoardProtocol.ping(seq));
            sendFrame(p, Frame.Type.CONFIGURE, 0, BoardProtocol.configure(settings.stateHz()));
        }
        return sendFrame(p, type, 0, body);
    }

    private boolean sendFrame(SerialPort p, int type, int flags, byte[] body) {
        byte[] b = codec.encode(new Frame(type, flags, seq, nowMs(), body));
        seq = (seq + 1) & 0xFFFF;
        synchronized (portLock) {
            return p.writeBytes(b, b.length) == b.length;
        }
    }

    private long nowMs() {
        return ((System.nanoTime() - startNanos) / 1_000_000) & 0xFFFFFFFFL;
    }

    // ---- receiving (reader thread, then the loop) ---------------------------------------------------

    private void readLoop() {
        byte[] buf = new byte[1024];
        long backoffMs = 100;
        while (!closed) {
            SerialPort p = port;
            if (p == null) {
                if (openPort()) {
                    backoffMs = 100;
                } else {
                    sleep(backoffMs);
                    backoffMs = Math.min(2_000, backoffMs * 2);
                }
                continue;
            }
            int n = p.readBytes(buf, buf.length);
            if (port != p) {
                continue; // closed meanwhile (a silent board, or close())
            }
            if (n < 0 || !Files.exists(Path.of(settings.port()))) {
                lost("the port " + settings.port() + " is gone");
                continue;
            }
            if (n > 0) {
                receiver.feed(buf, 0, n, nowMs());
            }
        }
    }

    private boolean openPort() {
        if (!Files.exists(Path.of(settings.port())) && !settings.port().toUpperCase().startsWith("COM")) {
            return false;
        }
        // A relative path is made absolute: jSerialComm would take a bare name for one under /dev.
        String where = settings.port().toUpperCase().startsWith("COM") ? settings.port() : Path.of(settings.port()).toAbsolutePath().toString();
        SerialPort p = SerialPort.getCommPort(where);
        p.setComPortParameters(settings.baud(), 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
        // A read returns as soon as a byte is there (a timeout on a pty is only good to about 10 ms,
        // which a STATE frame's way to the agent then carried); the loop's heartbeat watches for a
        // silent board, and closing the port ends a read.
        p.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING, 0, 0);
        if (!p.openPort()) {
            LOG.warn("{}: cannot open {} (error {}); tries again", settings.name(), settings.port(), p.getLastErrorCode());
            return false;
        }
        receiver.reset();
        lastFrameNanos = System.nanoTime();
        port = p;
        runtime.execute(() -> {
            sync = true;
            stopSent = false;
            sendCommand();
        });
        LOG.info("{}: opened {}", settings.name(), settings.port());
        return true;
    }

    private void lost(String why) {
        closePort();
        LOG.warn("{}: link down: {}; opens the port again when it returns", settings.name(), why);
        runtime.execute(() -> setOnline(false));
    }

    private void closePort() {
        SerialPort p = port;
        port = null;
        if (p != null) {
            synchronized (portLock) {
                p.closePort();
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

    private void onBoardFrame(Frame f) {
        lastFrameNanos = System.nanoTime();
        accepted++;
        try {
            switch (f.type()) {
                case Frame.Type.STATE -> {
                    BoardProtocol.State s = BoardProtocol.readState(f);
                    if (s.rangesMm().length != layout.sensors().size()) {
                        throw new FrameException("malformed", s.rangesMm().length + " ranges, the layout has " + layout.sensors().size());
                    }
                    runtime.execute(() -> onState(f, s));
                }
                case Frame.Type.HELLO -> {
                    BoardProtocol.Hello h = BoardProtocol.readHello(f);
                    firmware = h.firmware();
                    ChairLayout l = h.layout();
                    runtime.execute(() -> {
                        if (!l.equals(layout)) {
                            LOG.info("{}: the board's layout replaces the one expected", settings.name());
                        }
                        layout = l;
                        Pose at = odometry.pose();
                        odometry = new Odometry(l, at);
                    });
                }
                case Frame.Type.NAK -> {
                    Frame.Fields r = f.fields();
                    int s = r.u16();
                    int why = r.u8();
                    LOG.debug("{}: the board refused frame {}: reason {}", settings.name(), s, why);
                }
                case Frame.Type.ACK -> { }
                default -> receiver.drops().count("unknown-type");
            }
        } catch (FrameException e) {
            receiver.drops().count(e.reason());
        }
    }

    private void onState(Frame f, BoardProtocol.State s) {
        if (!online) {
            setOnline(true);
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
