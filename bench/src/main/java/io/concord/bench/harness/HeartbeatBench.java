package io.concord.bench.harness;

import com.fazecast.jSerialComm.SerialPort;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.ChairSupervisor;
import io.concord.core.agent.AgentRuntime;
import io.concord.layers.Platform;
import io.concord.serial.Board;
import io.concord.serial.FrameCodec;
import io.concord.serial.SerialChair;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.LockSupport;

/**
 * The heartbeat a busy host gives the board, and how fast an e-stop reaches the agents: over a
 * real pty pair, the board's logic in a thread of its own on one end, the host's driver behind
 * its safety supervisor on a platform's loop on the other, the loop confirming a drive command at
 * every STATE as the control agent does. Measured quiet, then beside 4 busy loops (processes that
 * spin) on the machine's cores: the gaps between the heartbeat's frames as the host sends them and
 * as the board takes them (its watchdog trips past 200 ms), and how many times the command
 * deadline stopped the heartbeat. Then the e-stop: from its press at the board to the STOP the
 * host sends when its supervisor holds motion.
 */
public final class HeartbeatBench {
    private HeartbeatBench() {
    }

    /**
     * What it measured.
     *
     * @param hostQuietMs    gaps between heartbeat frames sent, quiet
     * @param hostLoadedMs   the same beside 4 busy loops
     * @param boardQuietMs   gaps between host frames taken by the board, quiet
     * @param boardLoadedMs  the same beside 4 busy loops
     * @param tripsQuiet     watchdog trips at the board, quiet
     * @param tripsLoaded    watchdog trips at the board beside the busy loops
     * @param estopToStopMs  e-stop pressed at the board to the host's STOP sent
     */
    public record Outcome(double[] hostQuietMs, double[] hostLoadedMs, double[] boardQuietMs, double[] boardLoadedMs,
                          long tripsQuiet, long tripsLoaded, double[] estopToStopMs) {
    }

    public static Outcome run(boolean full) throws Exception {
        long phaseMs = full ? 30_000 : 6_000;
        List<Process> busy = new ArrayList<>();
        try (PtyPair pty = new PtyPair("concord-heartbeat-bench")) {
            Path host = pty.host;
            SerialBench.Motors motors = new SerialBench.Motors();
            FrameCodec codec = new FrameCodec();
            SerialPort bp = pty.openBoard();
            long t0 = System.nanoTime();
            Board board = new Board(motors, codec, "bench", bytes -> bp.writeBytes(bytes, bytes.length));
            ConcurrentLinkedQueue<Runnable> onBoard = new ConcurrentLinkedQueue<>();
            AtomicBoolean stop = new AtomicBoolean();
            List<Double> boardGaps = Collections.synchronizedList(new ArrayList<>());
            long[] trips = new long[1];
            Thread boardThread = new Thread(() -> {
                byte[] buf = new byte[512];
                board.switchOn(1, 0);
                long lastTaken = -1;
                long taken = 0;
                boolean wasTripped = false;
                while (!stop.get()) {
                    for (Runnable r; (r = onBoard.poll()) != null; ) {
                        r.run();
                    }
                    int avail = bp.bytesAvailable();
                    int n = avail > 0 ? bp.readBytes(buf, Math.min(avail, buf.length)) : 0;
                    long nowNs = System.nanoTime();
                    long now = (nowNs - t0) / 1_000_000;
                    if (n > 0) {
                        board.onBytes(buf, 0, n, now);
                        if (board.accepted() != taken) {
                            taken = board.accepted();
                            if (lastTaken >= 0) {
                                boardGaps.add((nowNs - lastTaken) / 1e6);
                            }
                            lastTaken = nowNs;
                        }
                    }
                    board.tick(now);
                    if (board.tripped() && !wasTripped) {
                        trips[0]++;
                    }
                    wasTripped = board.tripped();
                    if (n <= 0) {
                        LockSupport.parkNanos(100_000);
                    }
                }
            }, "bench-board");
            boardThread.setDaemon(true);
            boardThread.start();

            double[] hostQuiet;
            double[] hostLoaded;
            double[] boardQuiet;
            double[] boardLoaded;
            long tripsQuiet;
            long tripsLoaded;
            List<Double> estop = new ArrayList<>();
            try (Platform platform = Platform.builder().name("bench").build()) {
                AgentRuntime rt = platform.runtime();
                CountDownLatch open = new CountDownLatch(1);
                SerialChair[] chair = new SerialChair[1];
                ChairSupervisor[] sup = new ChairSupervisor[1];
                long[] heldAtNs = new long[1];
                rt.execute(() -> {
                    chair[0] = SerialChair.open(rt, SerialChair.Settings.of(host.toString(), "bench"));
                    sup[0] = new ChairSupervisor(chair[0]);
                    sup[0].setListener(new ChairListener() {
                        @Override
                        public void onReadings(ChairReadings r) {
                            // As the control agent does: a command at every reading, resumed when it may.
                            if (sup[0].state() == ChairSupervisor.State.HELD && !sup[0].estopPressed() && chair[0].online()) {
                                sup[0].resume("bench");
                            }
                            sup[0].drive(20, 20);
                        }
                    });
                    sup[0].setObserver(new ChairSupervisor.Observer() {
                        @Override
                        public void onHold(ChairSupervisor.Hold hold) {
                            if (hold.cause() == ChairSupervisor.Cause.ESTOP) {
                                heldAtNs[0] = System.nanoTime();
                            }
                        }

                        @Override
                        public void onArmed(String decidedBy) {
                        }
                    });
                    open.countDown();
                });
                open.await(10, TimeUnit.SECONDS);
                awaitArmed(rt, sup[0]);
                Thread.sleep(1_000);   // the JIT's warm-up of the path, not measured
                int h0 = chair[0].heartbeatGapsMs().length;
                int b0 = boardGaps.size();
                long trips0 = trips[0];
                Thread.sleep(phaseMs);
                int h1 = chair[0].heartbeatGapsMs().length;
                int b1 = boardGaps.size();
                long trips1 = trips[0];
                int cores = Runtime.getRuntime().availableProcessors();
                for (int i = 0; i < 4; i++) {
                    busy.add(new ProcessBuilder("sh", "-c", "while :; do :; done").start());
                }
                Thread.sleep(phaseMs);
                int h2 = chair[0].heartbeatGapsMs().length;
                int b2 = boardGaps.size();
                long trips2 = trips[0];
                busy.forEach(Process::destroyForcibly);
                busy.clear();
                double[] all = chair[0].heartbeatGapsMs();
                hostQuiet = Arrays.copyOfRange(all, h0, h1);
                hostLoaded = Arrays.copyOfRange(all, h1, h2);
                Double[] bg;
                synchronized (boardGaps) {
                    bg = boardGaps.toArray(new Double[0]);
                }
                boardQuiet = Arrays.stream(bg, b0, b1).mapToDouble(Double::doubleValue).toArray();
                boardLoaded = Arrays.stream(bg, b1, b2).mapToDouble(Double::doubleValue).toArray();
                tripsQuiet = trips1 - trips0;
                tripsLoaded = trips2 - trips1;
                if (cores < 1) {
                    throw new IllegalStateException("no cores");
                }
                // The e-stop, quiet: pressed at the board, to the STOP the host sends on its hold.
                for (int i = 0; i < (full ? 30 : 10); i++) {
                    awaitArmed(rt, sup[0]);
                    Thread.sleep(100);
                    heldAtNs[0] = 0;
                    long[] pressed = new long[1];
                    onBoard.add(() -> {
                        pressed[0] = System.nanoTime();
                        board.estop(true, (System.nanoTime() - t0) / 1_000_000);
                    });
                    long deadline = System.nanoTime() + 2_000_000_000L;
                    while (heldAtNs[0] == 0 && System.nanoTime() < deadline) {
                        Thread.sleep(1);
                    }
                    if (heldAtNs[0] != 0) {
                        estop.add((heldAtNs[0] - pressed[0]) / 1e6);
                    }
                    onBoard.add(() -> board.estop(false, (System.nanoTime() - t0) / 1_000_000));
                }
                CountDownLatch closed = new CountDownLatch(1);
                rt.execute(() -> {
                    chair[0].close();
                    closed.countDown();
                });
                closed.await();
            }
            stop.set(true);
            boardThread.join(1000);
            bp.closePort();
            return new Outcome(hostQuiet, hostLoaded, boardQuiet, boardLoaded, tripsQuiet, tripsLoaded,
                    estop.stream().mapToDouble(Double::doubleValue).toArray());
        } finally {
            busy.forEach(Process::destroyForcibly);
        }
    }

    private static void awaitArmed(AgentRuntime rt, ChairSupervisor s) throws Exception {
        long end = System.nanoTime() + 10_000_000_000L;
        while (System.nanoTime() < end) {
            CompletableFuture<Boolean> f = new CompletableFuture<>();
            rt.execute(() -> f.complete(s.armed()));
            if (f.get(10, TimeUnit.SECONDS)) {
                return;
            }
            Thread.sleep(10);
        }
        throw new IllegalStateException("the chair was not armed within 10 s");
    }

    private static double max(double[] v) {
        return Arrays.stream(v).max().orElse(Double.NaN);
    }

    public static String describe(Outcome o) {
        return String.format(Locale.ROOT, "RESULT serial_heartbeat heartbeat_gap_p99_ms=%.1f heartbeat_gap_max_ms=%.1f "
                        + "heartbeat_gap_p99_loaded_ms=%.1f heartbeat_gap_max_loaded_ms=%.1f board_gap_p99_ms=%.1f "
                        + "board_gap_p99_loaded_ms=%.1f board_gap_max_loaded_ms=%.1f trips=%d trips_loaded=%d estop_to_stop_ms=%.1f "
                        + "estop_to_stop_p99_ms=%.1f samples=%d,%d,%d",
                SerialBench.percentile(o.hostQuietMs(), 99), max(o.hostQuietMs()), SerialBench.percentile(o.hostLoadedMs(), 99),
                max(o.hostLoadedMs()), SerialBench.percentile(o.boardQuietMs(), 99), SerialBench.percentile(o.boardLoadedMs(), 99),
                max(o.boardLoadedMs()), o.tripsQuiet(), o.tripsLoaded(), SerialBench.percentile(o.estopToStopMs(), 50),
                SerialBench.percentile(o.estopToStopMs(), 99), o.hostQuietMs().length, o.hostLoadedMs().length, o.estopToStopMs().length);
    }
}
