package io.concord.sim.board;

import io.concord.layers.platform.Platform;
import io.concord.serial.SerialChair;

/** A host that opens the chair's port and drives it forward at 20 % until it is killed. */
public final class SerialHostMain {
    private SerialHostMain() {
    }

    public static void main(String[] args) throws Exception {
        Platform platform = Platform.builder().name("host").build();
        var rt = platform.runtime();
        rt.execute(() -> {
            SerialChair chair = SerialChair.open(rt, SerialChair.Settings.of(args[0], "chair"));
            chair.drive(0, 0);
            rt.schedule(rt.nowNs() + 300_000_000L, () -> {
                chair.drive(20, 20);
                System.out.println("driving");
            });
        });
        Thread.currentThread().join();
    }
}
