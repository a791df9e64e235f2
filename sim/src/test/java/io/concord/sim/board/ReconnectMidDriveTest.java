package io.concord.sim.board;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.ChairEvent;
import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.ChairSupervisor;
import io.concord.core.agent.AgentRuntime;
import io.concord.layers.Platform;
import io.concord.serial.SerialChair;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.LockSupport;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Issue 51's first hazard over a real pty pair, the board emulator in a process of its own: the
 * chair drives at 600,600, the board's frames stop reaching the host ({@code mute}) while it still
 * hears the host's heartbeat (so it stays armed and does not trip), the host takes the link for
 * lost and opens the port again at once, and the new session's SYNC PING is lost on the wire
 * ({@code drop-sync}): the board never disarms. The agents' loop is busy when the link goes down
 * (it runs the supervisor's hold only once the driver has sent three frames on the new session),
 * so that the driver's own defence is all there is. With it, nothing but neutral reaches the
 * board until the supervisor resumes; without it the new session's third frame is the last DRIVE,
 * and the board drives on it during the hold.
 */
class ReconnectMidDriveTest {

    /**
     * Between the serial chair and the supervisor: the loop kept busy from the link's loss until
     * the driver sent {@code frames} frames on the new session.
     */
    static final class BusyLoop implements ChairDriver {
        final SerialChair serial;
        final int frames;
        volatile boolean waited;
        volatile boolean timedOut;
        /** The session the last reading came on. */
        private long session;
        private ChairListener listener;

        BusyLoop(SerialChair serial, int frames) {
            this.serial = serial;
            this.frames = frames;
            serial.setListener(new ChairListener() {
                @Override
                public void onReadings(ChairReadings r) {
                    session = serial.sessions();
                    listener.onReadings(r);
                }

                @Override
                public void onOnline(boolean up) {
                    listener.onOnline(up);
                }

                @Override
                public void onEvent(ChairEvent e) {
                    if (e.kind() == ChairEvent.Kind.LINK_LOST && !waited) {
                        waited = true;
                        long end = System.nanoTime() + 10_000_000_000L;
                        // The port is closed now; the reader opens it again at once: a new session.
                        while (!(serial.sessions() > session && serial.sessionFramesSent() >= BusyLoop.this.frames)
                                && System.nanoTime() < end) {
                            LockSupport.parkNanos(1_000_000);  // the loop is busy: polling what the driver sent
                        }
                        timedOut = System.nanoTime() >= end;
                    }
                    listener.onEvent(e);
                }
            });
        }

        @Override
        public String name() {
            return serial.name();
        }

        @Override
        public ChairLayout layout() {
            return serial.layout();
        }

        @Override
        public void drive(double l, double r) {
            serial.drive(l, r);
        }

        @Override
        public void stop() {
            serial.stop();
        }

        @Override
        public void holdMotion() {
            serial.holdMotion();
        }

        @Override
        public void releaseMotion() {
            serial.releaseMotion();
        }

        @Override
        public void arm() {
            serial.arm();
        }

        @Override
        public ChairReadings latest() {
            return serial.latest();
        }

        @Override
        public boolean online() {
            return serial.online();
        }

        @Override
        public boolean reportsArming() {
            return true;
        }

        @Override
        public String whyOffline() {
            return serial.whyOffline();
        }

        @Override
        public void setListener(ChairListener l) {
            this.listener = l;
        }
    }

    /** The frames the board took on the host's second session: those after the trace's CONFIGURE (the trace starts mid-drive). */
    static List<HostFreezeTest.Rx> secondSession(EmulatorProcess board) {
        List<HostFreezeTest.Rx> rx = HostFreezeTest.rx(board);
        int configures = 0;
        List<HostFreezeTest.Rx> out = new ArrayList<>();
        for (HostFreezeTest.Rx r : rx) {
            if (configures >= 1) {
                out.add(r);
            }
            if (r.what().equals("CONFIGURE")) {
                configures++;
            }
        }
        return out;
    }

    /**
     * Drives at 600,600 (the agents confirm it every 20 ms, readings or not), then the reconnect
     * with the SYNC lost; {@code body} checks once the board took the new session's first frames
     * after its CONFIGURE.
     */
    private static ChairSupervisor reconnectMidDrive(Path dir, Set<SerialChair.Defence> driverDefences, Body body) throws Exception {
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19");
             Platform platform = Platform.builder().name("host").build()) {
            AgentRuntime rt = platform.runtime();
            SerialChair serial = Loops.call(rt, () -> SerialChair.openWithDefences(rt, SerialChair.Settings.of(pty.host.toString(), "chair1"),
                    driverDefences));
            BusyLoop busy = new BusyLoop(serial, 3);
            ChairSupervisor sup = Loops.call(rt, () -> new ChairSupervisor(busy));
            Loops.call(rt, () -> {
                sup.setListener(r -> { });
                return null;
            });
            Pty.await(() -> Loops.call(rt, serial::online), 30_000, "the board's first STATE");
            assertNull(Loops.call(rt, () -> sup.resume("the test, as the control agent at start")));
            Pty.await(() -> Loops.call(rt, sup::armed), 10_000, "armed");
            AtomicBoolean agents = new AtomicBoolean(true);
            Thread drive = new Thread(() -> {
                while (agents.get()) {
                    rt.execute(() -> sup.drive(60, 60));
                    LockSupport.parkNanos(20_000_000);  // the agents' cadence, not a wait for an outcome
                }
            }, "agents");
            drive.setDaemon(true);
            drive.start();
            try {
                board.awaitStatus(st -> st.get("motors").equals("600,600"), 10_000, "the board to drive at 600,600");
                board.command("trace on");
                board.command("drop-sync");
                board.command("mute 700");
                Pty.await(() -> board.said("SYNC PING was lost"), 10_000,
                        "the new session's SYNC lost on the wire: " + board.log);
                // Over socat's pty pair a port closed and opened again at once carries a few frames
                // only (socat stops forwarding the end that was closed), so the link does not come
                // back here: what counts is what the board took first on the new session.
                Pty.await(() -> busy.waited && secondSession(board).size() >= 2, 20_000,
                        "the new session's first frames: " + board.log);
                assertTrue(!busy.timedOut, "the driver sent " + busy.frames + " frames on the new session while the loop was busy");
                body.check(board, sup, rt);
            } finally {
                agents.set(false);
            }
            return sup;
        }
    }

    interface Body {
        void check(EmulatorProcess board, ChairSupervisor sup, AgentRuntime rt) throws Exception;
    }

    @Test
    void aReconnectMidDriveWithTheSyncLostSendsOnlyNeutralUntilTheResume(@TempDir Path dir) throws Exception {
        reconnectMidDrive(dir, EnumSet.allOf(SerialChair.Defence.class), (board, sup, rt) -> {
            List<HostFreezeTest.Rx> session = secondSession(board);
            assertEquals("STOP", session.get(0).what(), "the new session's third frame: " + session);
            for (HostFreezeTest.Rx r : session) {
                assertTrue(r.neutral(), "only neutral while held: " + r + " in " + session);
                assertEquals("0,0", r.motors(), "the board, which missed the SYNC, stops: " + r);
            }
            assertTrue(session.get(0).armed(), "the board never disarmed: only the host's defence stood: " + session);
            assertNotEquals(ChairSupervisor.State.ARMED, Loops.call(rt, sup::state));
            assertEquals(ChairSupervisor.Cause.LINK, Loops.call(rt, () -> sup.hold().cause()));
            assertEquals("0,0", board.status().get("motors"));
        });
    }

    /** A run that cannot show the hazard: the board's own 200 ms watchdog disarmed it before the new session's first frame. */
    private static final class Inconclusive extends Exception {
        Inconclusive(String why) {
            super(why);
        }
    }

    @Test
    void withoutItsDefenceTheLastDriveReachesTheBoardDuringTheHold(@TempDir Path dir) throws Exception {
        // On a loaded machine the reconnect can take longer than the board's watchdog (200 ms), which
        // then disarms the board itself: that run shows nothing about the host's defence, and is run
        // again (at most three times in all).
        List<String> inconclusive = new ArrayList<>();
        for (int attempt = 1; attempt <= 3; attempt++) {
            Path at = java.nio.file.Files.createDirectories(dir.resolve("attempt-" + attempt));
            try {
                reconnectMidDrive(at, EnumSet.complementOf(EnumSet.of(SerialChair.Defence.NEUTRAL_UNTIL_RESUMED)), (board, sup, rt) -> {
                    List<HostFreezeTest.Rx> session = secondSession(board);
                    HostFreezeTest.Rx first = session.get(0);
                    assertEquals("DRIVE 600,600", first.what(), "the hazard: the last DRIVE is the new session's third frame: " + session);
                    if (!first.armed()) {
                        throw new Inconclusive("the board had disarmed itself before " + first);
                    }
                    assertEquals("600,600", first.motors(), "and driven on: " + first);
                    assertNotEquals(ChairSupervisor.State.ARMED, Loops.call(rt, sup::state), "while the supervisor holds");
                });
                return;
            } catch (Inconclusive e) {
                inconclusive.add(e.getMessage());
            }
        }
        org.junit.jupiter.api.Assertions.fail("taken by a board that missed the SYNC: in no run of three was the board still armed: " + inconclusive);
    }
}
