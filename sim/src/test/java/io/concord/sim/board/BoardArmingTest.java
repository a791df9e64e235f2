package io.concord.sim.board;

import io.concord.agents.chair.ChairSupervisor;
import io.concord.core.agent.AgentRuntime;
import io.concord.layers.Platform;
import io.concord.serial.SerialChair;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The board's own layer, independent of the host (docs/chair-safety.md, "three layers"): over a
 * real pty against the emulated board, after an e-stop's release and after a reboot the host's
 * heartbeat goes on (a STOP, then DRIVE 0, 0 every 50 ms) and the board stays unarmed, however
 * many of those it takes, until the supervisor resumes and the host sends its ARM. Shown to fail
 * with a board that arms on any neutral command, as version 2 did.
 */
class BoardArmingTest {

    @Test
    void afterAnEstopsReleaseAndAfterARebootOnlyTheResumeArmsTheBoard(@TempDir Path dir) throws Exception {
        onlyTheResumeArms(dir, false);
    }

    @Test
    void aBoardThatArmsOnNeutralIsArmedByTheHeartbeatAlone(@TempDir Path dir) {
        AssertionError e = assertThrows(AssertionError.class, () -> onlyTheResumeArms(dir, true));
        assertTrue(e.getMessage().contains("the heartbeat armed the board"), e.getMessage());
    }

    private static void onlyTheResumeArms(Path dir, boolean armOnNeutral) throws Exception {
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19");
             Platform platform = Platform.builder().name("host").build()) {
            if (armOnNeutral) {
                board.command("arm-on-neutral");
            }
            AgentRuntime rt = platform.runtime();
            SerialChair serial = Loops.call(rt, () -> SerialChair.open(rt, SerialChair.Settings.of(pty.host.toString(), "chair1")));
            ChairSupervisor sup = Loops.call(rt, () -> new ChairSupervisor(serial));
            Loops.call(rt, () -> {
                // As the control agent standing still does: a neutral command at every reading, which the heartbeat repeats.
                sup.setListener(r -> sup.stop());
                return null;
            });
            Pty.await(() -> Loops.call(rt, serial::online), 30_000, "the board's first STATE");
            resume(rt, sup, board, "at start");
            for (String fault : List.of("e-stop", "reboot")) {
                if (fault.equals("e-stop")) {
                    board.command("estop on");
                    Pty.await(() -> Loops.call(rt, sup::estopPressed), 10_000, "the host to see the e-stop");
                    board.command("estop off");
                    Pty.await(() -> !Loops.call(rt, sup::estopPressed), 10_000, "the host to see the release");
                } else {
                    board.command("reboot");
                    Pty.await(() -> Loops.call(rt, () -> sup.hold().cause()) == ChairSupervisor.Cause.REBOOT, 10_000,
                            "the host to hold for the reboot");
                }
                // A second of the heartbeat after it, counted in frames the board took (not waited for in time).
                long from = Long.parseLong(board.status().get("accepted"));
                board.awaitStatus(st -> Long.parseLong(st.get("accepted")) >= from + 20, 10_000, "20 host frames after the " + fault);
                Map<String, String> st = board.status();
                assertEquals("false", st.get("armed"), "after the " + fault + ", the heartbeat armed the board: " + st);
                assertEquals("0,0", st.get("motors"), st.toString());
                assertTrue(Loops.call(rt, () -> !sup.armed()), "the supervisor holds");
                resume(rt, sup, board, "after the " + fault);
            }
        }
    }

    private static void resume(AgentRuntime rt, ChairSupervisor sup, EmulatorProcess board, String when) throws Exception {
        assertNull(Loops.call(rt, () -> sup.resume("the test, as an operator " + when)));
        Pty.await(() -> Loops.call(rt, sup::armed), 10_000, "the supervisor armed " + when);
        assertEquals("true", board.status().get("armed"), "the board armed by the resume's ARM " + when);
    }
}
