package io.concord.sim.board;

import io.concord.layers.Platform;
import io.concord.serial.SerialChair;

/** A host that opens the chair's port and drives it forward at 20 %, confirming at every reading, until it is killed. */
public final class SerialHostMain {
    private SerialHostMain() {
    }

    public static void main(String[] args) throws Exception {
        Platform platform = Platform.builder().name("host").build();
        var rt = platform.runtime();
        rt.execute(() -> {
            SerialChair chair = SerialChair.open(rt, SerialChair.Settings.of(args[0], "chair"));
            chair.drive(0, 0);
            long start = rt.nowNs();
            // As an agent does: a command at every reading (the driver's heartbeat repeats only a
            // command confirmed within its deadline); neutral first, then 20 % after 300 ms.
            chair.setListener(r -> {
                if (rt.nowNs() - start < 300_000_000L) {
                    chair.drive(0, 0);
                } else {
                    // No supervisor here: the host resumes itself, as a supervisor does: an ARM for
                    // the board's state, then, once a reading says armed, the agents' commands
                    // (a new session sends only neutral until then).
                    if (!chair.boardArmed()) {
                        chair.arm();
                        return;
                    }
                    if (chair.motionHeld()) {
                        chair.releaseMotion();
                    }
                    chair.drive(20, 20);
                }
            });
        });
        Thread.currentThread().join();
    }
}
