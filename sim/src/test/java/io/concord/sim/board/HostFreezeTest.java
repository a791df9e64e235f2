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

        Host(Path port, String defences, long deadlineMs) throws IOException {
            process = JavaProcess.start(SafetyHostMain.class, port.toString(), defences, Long.toString(deadlineMs));
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
            Pty.await(() -> host.said("control-chair1: pauses T1: the board's watchdog tripped"), 10_000, "the pause: " + host.log);
            Pty.await(() -> host.said("control-chair1: resumes T1"), 10_000, "the resume: " + host.log);
            double at = Double.parseDouble(board.status().get("moved"));
            board.awaitStatus(st -> Double.parseDouble(st.get("moved")) > at + 0.2, 30_000, "the chair to drive on");
            assertFalse(host.said("host: outcome"), "the transport goes on: " + host.log);
        }
    }

    @Test
    void withoutItsDefencesAFrozenHostStallsTheTransportForGood(@TempDir Path dir) throws Exception {
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19");
             Host host = new Host(pty.host, "none", 1_000)) {
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
