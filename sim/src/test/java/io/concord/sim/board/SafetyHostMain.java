package io.concord.sim.board;

import io.concord.agents.chair.ChairSupervisor;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.layers.Platform;
import io.concord.serial.SerialChair;
import io.concord.sim.Hospital;
import io.concord.sim.world.HospitalWorld;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.EnumSet;

/**
 * The ward's host in a process of its own, for the tests that freeze it: the wheelchair's agents on
 * the chair's port, a transport from node 19 to node 3 once they are ready; every line of their
 * log on standard output. Arguments: the port, {@code all} or {@code none} (the supervisor's
 * defences; or {@code all-but:NAME,...}, every {@link ChairSupervisor.Defence} but those), the command deadline in ms, and optionally the serial driver's defences to switch
 * off (comma-separated {@link SerialChair.Defence} names). On standard input: {@code resume}.
 */
public final class SafetyHostMain {
    private SafetyHostMain() {
    }

    public static void main(String[] args) throws Exception {
        String port = args[0];
        java.util.Set<ChairSupervisor.Defence> defences = args[1].equals("all") ? EnumSet.allOf(ChairSupervisor.Defence.class)
                : EnumSet.noneOf(ChairSupervisor.Defence.class);
        if (args[1].startsWith("all-but:")) {
            defences = EnumSet.allOf(ChairSupervisor.Defence.class);
            for (String d : args[1].substring("all-but:".length()).split(",")) {
                defences.remove(ChairSupervisor.Defence.valueOf(d.trim()));
            }
        }
        java.util.Set<ChairSupervisor.Defence> supervisorDefences = defences;
        long deadline = Long.parseLong(args[2]);
        java.util.Set<SerialChair.Defence> driver = EnumSet.allOf(SerialChair.Defence.class);
        if (args.length > 3) {
            for (String d : args[3].split(",")) {
                driver.remove(SerialChair.Defence.valueOf(d.trim()));
            }
        }
        HospitalMap map = HospitalMap.defaultHospital();
        Platform platform = Platform.builder().name("freeze").build();
        var rt = platform.runtime();
        java.util.function.Consumer<String> log = l -> {
            System.out.println(l);
            System.out.flush();
        };
        HospitalWorld doors = HospitalWorld.builder(map).seed(1).build();
        Hospital hospital = Hospital.start(platform, doors, log);
        doors.attach(rt);
        ChairSupervisor[] sup = new ChairSupervisor[1];
        java.util.concurrent.CountDownLatch opened = new java.util.concurrent.CountDownLatch(1);
        rt.execute(() -> {
            SerialChair serial = SerialChair.openWithDefences(rt, SerialChair.Settings.of(port, "chair1").withStart(doors.poseAt(19, 90))
                    .withCommandDeadlineMs(deadline), driver);
            sup[0] = ChairSupervisor.withDefences(serial, supervisorDefences);
            opened.countDown();
        });
        opened.await();
        hospital.addChair(platform, map, sup[0], log);
        MedicalAgent medical = new MedicalAgent(log);
        platform.startAgent("medical", medical);
        while (!ready(rt, hospital, sup[0])) {
            Thread.sleep(20);
        }
        log.accept("host: ready");
        medical.transport(19, 3, 0, 1).thenAccept(o -> log.accept("host: outcome " + o));
        try (BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8))) {
            for (String l; (l = in.readLine()) != null; ) {
                if (l.equals("resume")) {
                    hospital.control("chair1").resume(hospital.operatorKey().sign("resume", "chair1", rt.clock().epochMillis()));
                }
            }
        }
        System.exit(0);
    }

    private static boolean ready(io.concord.core.agent.AgentRuntime rt, Hospital h, ChairSupervisor s) {
        return Loops.call(rt, () -> h.ready() && s.armed());
    }
}
