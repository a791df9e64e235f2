package io.concord.sim.board;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The host frozen mid-drive for 250 ms (SIGSTOP, then SIGCONT: a long GC, a laptop's hiccup):
 * the board's watchdog trips, the host's next frame clears the fault before any STATE shows it,
 * and only the armed bit and the board's refusals tell the host. With its defences the host
 * pauses the task, decides to re-arm and drives on; without them it repeats the refused command
 * for good while the agents believe the chair drives.
 */
class HostFreezeTest {

    /** The host's process and what it says. */
    static final class Host implements AutoCloseable {
        final Process process;
        final List<String> log = Collections.synchronizedList(new ArrayList<>());

        Host(Path port, String defences, long deadlineMs, String... driverDefencesOff) throws IOException {
            process = driverDefencesOff.length == 0
                    ? JavaProcess.start(SafetyHostMain.class, port.toString(), defences, Long.toString(deadlineMs))
                    : JavaProcess.start(SafetyHostMain.class, port.toString(), defences, Long.toString(deadlineMs),
                    String.join(",", driverDefencesOff));
            Thread t = new Thread(() -> {
                try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                    for (String l; (l = r.readLine()) != null; ) {
                        log.add(l);
                    }
                } catch (IOException e) {
                    // ended
                }
            }, "host-out");
            t.setDaemon(true);
            t.start();
        }

        boolean said(String s) {
            synchronized (log) {
                return log.stream().anyMatch(l -> l.contains(s));
            }
        }

        /** Freezes the whole process for {@code ms}: one shell, so that the pause is what it says. */
        void freeze(long ms) throws Exception {
            long pid = process.pid();
            Process p = new ProcessBuilder("sh", "-c", "kill -STOP " + pid + "; sleep " + ms / 1000.0 + "; kill -CONT " + pid)
                    .redirectErrorStream(true).start();
            assertEquals(0, p.waitFor());
        }

        @Override
        public void close() {
            process.destroyForcibly();
        }
    }

    private static void drivingThenFrozen(Host host, EmulatorProcess board) throws Exception {
        Pty.await(() -> host.said("drives T1 to node 3"), 60_000, "the host to drive: " + host.log);
        board.awaitStatus(st -> Double.parseDouble(st.get("moved")) > 0.3 && !st.get("motors").equals("0,0"), 60_000,
                "the chair to drive");
        host.freeze(250);
    }

    @Test
    void aHostFrozenFor250MsMidDrivePausesTheTaskReArmsAndDrivesOn(@TempDir Path dir) throws Exception {
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19");
             Host host = new Host(pty.host, "all", 300)) {
            drivingThenFrozen(host, board);
            // Whichever the host hears first: its own driver, which sent nothing for over 150 ms, or the board's trip.
            Pty.await(() -> host.said("control-chair1: pauses T1: the host was frozen")
                    || host.said("control-chair1: pauses T1: the board's watchdog tripped"), 10_000, "the pause: " + host.log);
            Pty.await(() -> host.said("control-chair1: resumes T1"), 10_000, "the resume: " + host.log);
            double at = Double.parseDouble(board.status().get("moved"));
            board.awaitStatus(st -> Double.parseDouble(st.get("moved")) > at + 0.2, 30_000, "the chair to drive on");
            assertFalse(host.said("host: outcome"), "the transport goes on: " + host.log);
        }
    }

    /** A host frame the board took, from its trace: what (a DRIVE with its powers), the host's time in it, the board after it. */
    record Rx(String what, long t, boolean armed, String motors) {
        boolean neutral() {
            return what.equals("STOP") || what.equals("DRIVE 0,0");
        }
    }

    /** The board's trace so far (its {@code trace on} lines). */
    static List<Rx> rx(EmulatorProcess board) {
        List<Rx> out = new ArrayList<>();
        synchronized (board.log) {
            for (String l : board.log) {
                if (l.startsWith("rx ")) {
                    int seq = l.indexOf(" seq=");
                    java.util.Map<String, String> kv = new java.util.HashMap<>();
                    for (String f : l.substring(seq + 1).split(" ")) {
                        kv.put(f.substring(0, f.indexOf('=')), f.substring(f.indexOf('=') + 1));
                    }
                    out.add(new Rx(l.substring(3, seq), Long.parseLong(kv.get("t")), Boolean.parseBoolean(kv.get("armed")), kv.get("motors")));
                }
            }
        }
        return out;
    }

    /** The frames the host sent after it had sent nothing for over 150 ms of its own clock. */
    static List<Rx> afterAFreeze(List<Rx> rx) {
        List<Rx> out = new ArrayList<>();
        for (int i = 1; i < rx.size(); i++) {
            if (rx.get(i).t() - rx.get(i - 1).t() > 150) {
                out.add(rx.get(i));
            }
        }
        return out;
    }

    /** Driving, the board's trace on, then frozen for 170 ms: shorter than the board's watchdog. The frames after the freeze. */
    private static List<Rx> drivingThenFrozenFor170Ms(Host host, EmulatorProcess board) throws Exception {
        Pty.await(() -> host.said("drives T1 to node 3"), 60_000, "the host to drive: " + host.log);
        board.awaitStatus(st -> Double.parseDouble(st.get("moved")) > 0.3 && !st.get("motors").equals("0,0"), 60_000,
                "the chair to drive");
        board.command("trace on");
        Pty.await(() -> rx(board).size() >= 5, 10_000, "the board's trace");
        host.freeze(170);
        Pty.await(() -> !afterAFreeze(rx(board)).isEmpty(), 10_000, "a frame after the freeze: " + board.log);
        return afterAFreeze(rx(board));
    }

    @Test
    void aHostFrozenFor170MsMidDriveSendsNoCommandFromBeforeTheFreeze(@TempDir Path dir) throws Exception {
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19");
             Host host = new Host(pty.host, "all", 300)) {
            List<Rx> after = drivingThenFrozenFor170Ms(host, board);
            for (Rx r : after) {
                assertTrue(r.neutral(), "the first frame after the freeze is neutral: " + r + " in " + rx(board));
            }
            Pty.await(() -> host.said("control-chair1: pauses T1: the host was frozen")
                    || host.said("control-chair1: pauses T1: the board's watchdog tripped"), 10_000, "the pause: " + host.log);
            Pty.await(() -> host.said("control-chair1: resumes T1"), 10_000, "the resume: " + host.log);
            double at = Double.parseDouble(board.status().get("moved"));
            board.awaitStatus(st -> Double.parseDouble(st.get("moved")) > at + 0.2, 30_000, "the chair to drive on");
            for (Rx r : afterAFreeze(rx(board))) {
                assertTrue(r.neutral(), "and after any gap since: " + r);
            }
        }
    }

    @Test
    void withoutItsDefenceTheFirstFrameAfterA170MsFreezeIsTheCommandFromBeforeIt(@TempDir Path dir) throws Exception {
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19");
             Host host = new Host(pty.host, "all", 300, "NO_FROZEN_COMMAND")) {
            Rx first = drivingThenFrozenFor170Ms(host, board).get(0);
            assertFalse(first.neutral(), "the hazard: a command decided before the freeze goes out after it: " + first);
            assertTrue(first.what().startsWith("DRIVE "), first.toString());
        }
    }

    @Test
    void withoutItsDefencesAFrozenHostStallsTheTransportForGood(@TempDir Path dir) throws Exception {
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19");
             Host host = new Host(pty.host, "none", 1_000, "NO_FROZEN_COMMAND")) {
            drivingThenFrozen(host, board);
            long accepted = Long.parseLong(board.status().get("accepted"));
            // 40 heartbeats after the freeze: the board refuses every one and stays disarmed.
            board.awaitStatus(st -> Long.parseLong(st.get("accepted")) > accepted + 40, 30_000, "40 more host frames");
            var s = board.status();
            assertEquals("false", s.get("armed"), s.toString());
            assertEquals("0,0", s.get("motors"), s.toString());
            assertFalse(host.said("pauses T1"), String.join("\n", host.log));
            assertTrue(!host.said("host: outcome"), "and the agents believe the transport is under way");
        }
    }
}
