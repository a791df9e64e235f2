package io.concord.bench.harness;

import com.fazecast.jSerialComm.SerialPort;
import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.Pose;
import io.concord.core.agent.AgentRuntime;
import io.concord.layers.Platform;
import io.concord.serial.Board;
import io.concord.serial.BoardProtocol;
import io.concord.serial.Frame;
import io.concord.serial.FrameCodec;
import io.concord.serial.SerialChair;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.LockSupport;

/**
 * The serial link's timings over a real pty pair (socat), the board's logic on one end in a
 * thread of its own, the host's driver on the other on a platform's loop: a drive command from
 * the loop to the board's motors; a STATE from the board's write to the control agent's listener;
 * and the watchdog, from the host's last frame to the motors at zero.
 */
public final class SerialBench {
    private SerialBench() {
    }

    /** Each measurement's samples, in microseconds (watchdog: milliseconds). */
    /**
     * @param reopenFrames          host frames the board took on the session after a reopen mid-drive, before any resume
     * @param reopenNonNeutralFrames of those, DRIVEs other than 0, 0 (the hazard: the last command sent again; must be 0)
     * @param reopenSessions        sessions the host started after the reopen (1: the reopen happened)
     */
    public record Outcome(double[] cmdToMotorUs, double[] sensorToAgentUs, double[] watchdogStopMs, int reopenFrames,
                          int reopenNonNeutralFrames, int reopenSessions) {
    }

    /** Motors that note when each power arrives. */
    static final class Motors implements ChairDriver {
        final Map<Integer, Long> applied = new ConcurrentHashMap<>();
        volatile long zeroAtNs;
        volatile int left;

        @Override
        public String name() {
            return "bench";
        }

        @Override
        public ChairLayout layout() {
            return ChairLayout.standard();
        }

        @Override
        public void drive(double l, double r) {
            int p = (int) Math.round(l * 10);
            long now = System.nanoTime();
            if (p != left) {
                applied.putIfAbsent(p, now);
                if (p == 0) {
                    zeroAtNs = now;
                }
            }
            left = p;
        }

        @Override
        public ChairReadings latest() {
            return new ChairReadings(0, 0, 0, 0, new double[layout().sensors().size()], false, 24, false, Set.of(), new Pose(0, 0, 0), null);
        }

        @Override
        public boolean online() {
            return true;
        }

        @Override
        public void setListener(ChairListener l) {
        }
    }

    public static Outcome run(boolean full) throws Exception {
        try (PtyPair pty = new PtyPair("concord-serial-bench")) {
            Path host = pty.host;
            Motors motors = new Motors();
            FrameCodec codec = new FrameCodec();
            Map<Integer, Long> stateSentNs = new ConcurrentHashMap<>();
            SerialPort bp = pty.openBoard();
            long t0 = System.nanoTime();
            Board board = new Board(motors, codec, "bench", bytes -> {
                Frame f = codec.decode(bytes, 0, bytes.length - 1);
                if (f.type() == Frame.Type.STATE) {
                    stateSentNs.put(f.seq(), System.nanoTime());
                }
                bp.writeBytes(bytes, bytes.length);
            });
            AtomicBoolean stop = new AtomicBoolean();
            // A cable's glitch: while muted the board hears nothing and says nothing.
            AtomicBoolean mute = new AtomicBoolean();
            Thread boardThread = new Thread(() -> {
                byte[] buf = new byte[512];
                board.switchOn(0);
                while (!stop.get()) {
                    // Polled every 0.1 ms, as a board's timer interrupt would: a read's timeout on a pty
                    // is only good to about 10 ms, which the watchdog's figure then carried.
                    int avail = bp.bytesAvailable();
                    int n = avail > 0 ? bp.readBytes(buf, Math.min(avail, buf.length)) : 0;
                    long now = (System.nanoTime() - t0) / 1_000_000;
                    if (mute.get()) {
                        LockSupport.parkNanos(100_000);
                        continue;
                    }
                    if (n > 0) {
                        board.onBytes(buf, 0, n, now);
                    }
                    board.tick(now);
                    if (n <= 0) {
                        LockSupport.parkNanos(100_000);
                    }
                }
            }, "bench-board");
            boardThread.setDaemon(true);
            boardThread.start();

            int samples = full ? 400 : 100;
            List<Double> sensor = Collections.synchronizedList(new ArrayList<>());
            List<Double> cmd = new ArrayList<>();
            int[] reopen = new int[3];
            try (Platform platform = Platform.builder().name("bench").build()) {
                AgentRuntime rt = platform.runtime();
                CountDownLatch open = new CountDownLatch(1);
                SerialChair[] chair = new SerialChair[1];
                int[] warm = {0};
                rt.execute(() -> {
                    chair[0] = SerialChair.open(rt, SerialChair.Settings.of(host.toString(), "bench"));
                    chair[0].setListener(r -> {
                        Long sent = stateSentNs.remove((int) r.seq());
                        if (sent != null && warm[0]++ >= WARM_UP) {
                            sensor.add((System.nanoTime() - sent) / 1e3);
                        }
                    });
                    open.countDown();
                });
                open.await(10, TimeUnit.SECONDS);
                while (sensor.size() < 1) {
                    Thread.sleep(10);
                }
                // No supervisor here: the bench resumes the driver itself, as a supervisor does: an ARM,
                // and once the board reads armed the commands (a new session sends only neutral until then).
                arm(rt, chair[0]);
                // Drive commands: each power its own value, so that its arrival is its own.
                for (int i = -WARM_UP; i < samples; i++) {
                    int pct = 1 + (i + WARM_UP) % 99;
                    long[] at = new long[1];
                    CountDownLatch sent = new CountDownLatch(1);
                    motors.applied.remove(pct * 10);
                    rt.execute(() -> {
                        at[0] = System.nanoTime();
                        chair[0].drive(pct, pct);
                        sent.countDown();
                    });
                    sent.await();
                    long deadline = System.nanoTime() + 1_000_000_000L;
                    while (!motors.applied.containsKey(pct * 10) && System.nanoTime() < deadline) {
                        Thread.onSpinWait();
                    }
                    Long got = motors.applied.get(pct * 10);
                    if (got != null && i >= 0) {
                        cmd.add((got - at[0]) / 1e3);
                    }
                    Thread.sleep(5);
                }
                while (sensor.size() < samples) {
                    Thread.sleep(10);
                }
                // A reopen mid-drive: the agents drive at 60 % (confirming every 20 ms); the board falls
                // silent; the host finds the link down, opens the port again and starts a new session.
                // Until a resume, the board must take nothing but neutral from it.
                AtomicBoolean agents = new AtomicBoolean(true);
                Thread driving = new Thread(() -> {
                    while (agents.get()) {
                        rt.execute(() -> chair[0].drive(60, 60));
                        LockSupport.parkNanos(20_000_000);
                    }
                }, "bench-agents");
                driving.setDaemon(true);
                driving.start();
                long drivenBy = System.nanoTime() + 2_000_000_000L;
                while (motors.left != 600 && System.nanoTime() < drivenBy) {
                    Thread.sleep(5);
                }
                long sessions = chair[0].sessions();
                java.util.concurrent.atomic.AtomicInteger taken = new java.util.concurrent.atomic.AtomicInteger();
                java.util.concurrent.atomic.AtomicInteger nonNeutral = new java.util.concurrent.atomic.AtomicInteger();
                mute.set(true);
                long reopenBy = System.nanoTime() + 5_000_000_000L;
                while (chair[0].sessions() == sessions && System.nanoTime() < reopenBy) {
                    Thread.sleep(5);
                }
                board.setTrace(line -> {
                    taken.incrementAndGet();
                    if (line.startsWith("DRIVE ") && !line.startsWith("DRIVE 0,0 ")) {
                        nonNeutral.incrementAndGet();
                    }
                });
                mute.set(false);
                Thread.sleep(1_000);   // a second of the new session, held: the bench's window, not a test's wait
                agents.set(false);
                driving.join();
                board.setTrace(null);
                reopen[0] = taken.get();
                reopen[1] = nonNeutral.get();
                reopen[2] = (int) (chair[0].sessions() - sessions);
                CountDownLatch closed = new CountDownLatch(1);
                rt.execute(() -> {
                    chair[0].close();
                    closed.countDown();
                });
                closed.await();
            }
            Thread.sleep(300);
            // The watchdog: a host that drives, then falls silent mid-stride.
            List<Double> watchdog = new ArrayList<>();
            SerialPort hp = SerialPort.getCommPort(host.toString());
            hp.setComPortParameters(115_200, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
            if (!hp.openPort()) {
                throw new IllegalStateException("cannot open " + host);
            }
            int seq = 0;
            long h0 = System.nanoTime();
            for (int i = 0; i < (full ? 50 : 20); i++) {
                motors.zeroAtNs = 0;
                long last = 0;
                for (int k = 0; k < 4; k++) {
                    // An ARM for the board's state (a watchdog trip since the last round), then DRIVEs.
                    int type = k == 0 ? Frame.Type.ARM : Frame.Type.DRIVE;
                    byte[] body = k == 0 ? BoardProtocol.arm(board.boot(), Math.max(1, board.disarmedBy())) : BoardProtocol.drive(400, 400);
                    byte[] b = codec.encode(new Frame(type, seq == 0 ? Frame.SYNC : 0, seq++ & 0xFFFF, (System.nanoTime() - h0) / 1_000_000, body));
                    hp.writeBytes(b, b.length);
                    last = System.nanoTime();
                    Thread.sleep(50);
                }
                long deadline = System.nanoTime() + 2_000_000_000L;
                while (motors.zeroAtNs == 0 && System.nanoTime() < deadline) {
                    Thread.sleep(1);
                }
                if (motors.zeroAtNs != 0) {
                    watchdog.add((motors.zeroAtNs - last) / 1e6);
                }
            }
            hp.closePort();
            stop.set(true);
            boardThread.join(1000);
            bp.closePort();
            if (Boolean.getBoolean("concord.serial.debug")) {
                for (int i = 0; i < sensor.size(); i++) {
                    if (sensor.get(i) > 2000) {
                        System.out.printf("sensor sample %d: %.0f us%n", i, sensor.get(i));
                    }
                }
                for (int i = 0; i < cmd.size(); i++) {
                    if (cmd.get(i) > 2000) {
                        System.out.printf("cmd sample %d: %.0f us%n", i, cmd.get(i));
                    }
                }
            }
            return new Outcome(cmd.stream().mapToDouble(Double::doubleValue).toArray(),
                    sensor.stream().limit(samples).mapToDouble(Double::doubleValue).toArray(),
                    watchdog.stream().mapToDouble(Double::doubleValue).toArray(), reopen[0], reopen[1], reopen[2]);
        }
    }

    /** The supervisor's resume, done by hand: ARMs until the board reads armed, then the commands go out. */
    private static void arm(AgentRuntime rt, SerialChair chair) throws InterruptedException {
        long by = System.nanoTime() + 10_000_000_000L;
        while (true) {
            CountDownLatch asked = new CountDownLatch(1);
            boolean[] armed = new boolean[1];
            rt.execute(() -> {
                chair.stop();
                armed[0] = chair.boardArmed();
                if (!armed[0]) {
                    chair.arm();
                } else {
                    chair.releaseMotion();
                }
                asked.countDown();
            });
            asked.await();
            if (armed[0]) {
                return;
            }
            if (System.nanoTime() > by) {
                throw new IllegalStateException("the bench's board did not arm within 10 s");
            }
            Thread.sleep(20);
        }
    }

    /** Samples of each kind not counted: the first STATEs and commands run while classes load and compile. */
    private static final int WARM_UP = 10;

    public static double percentile(double[] v, double p) {
        if (v.length == 0) {
            return Double.NaN;
        }
        double[] s = v.clone();
        Arrays.sort(s);
        return s[Math.min(s.length - 1, (int) Math.ceil(p / 100 * s.length) - 1)];
    }

    public static String describe(Outcome o) {
        return String.format(Locale.ROOT, "RESULT serial cmd_to_motor_us=%.0f cmd_to_motor_p99_us=%.0f sensor_to_agent_us=%.0f "
                        + "sensor_to_agent_p99_us=%.0f watchdog_stop_ms=%.1f watchdog_stop_p99_ms=%.1f samples=%d,%d,%d"
                        + " reopen_nonneutral_frames=%d reopen_frames=%d reopen_sessions=%d",
                percentile(o.cmdToMotorUs(), 50), percentile(o.cmdToMotorUs(), 99), percentile(o.sensorToAgentUs(), 50),
                percentile(o.sensorToAgentUs(), 99), percentile(o.watchdogStopMs(), 50), percentile(o.watchdogStopMs(), 99),
                o.cmdToMotorUs().length, o.sensorToAgentUs().length, o.watchdogStopMs().length, o.reopenNonNeutralFrames(),
                o.reopenFrames(), o.reopenSessions());
    }
}
