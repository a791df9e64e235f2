package io.concord.sim.board;

import io.concord.agents.chair.ChairFault;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.core.agent.AgentRuntime;
import io.concord.layers.Platform;
import io.concord.serial.BoardProtocol;
import io.concord.serial.Frame;
import io.concord.serial.FrameCodec;
import io.concord.serial.SerialChair;
import io.concord.sim.Hospital;
import io.concord.sim.world.HospitalWorld;

import com.fazecast.jSerialComm.SerialPort;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The serial chair over a real pty pair (socat), with the board emulator in a process of its
 * own and the physics of the simulation behind it: what a real chair's cable would carry.
 */
class SerialLinkTest {
    static final HospitalMap MAP = HospitalMap.defaultHospital();

    private static <T> T onLoop(AgentRuntime rt, java.util.function.Supplier<T> s) throws InterruptedException {
        return Loops.call(rt, s);
    }

    /** True if a line of the log (written by the loop meanwhile) starts so. */
    private static boolean said(List<String> log, String start) {
        synchronized (log) {
            return log.stream().anyMatch(l -> l.startsWith(start));
        }
    }

    private static String tail(List<String> log) {
        synchronized (log) {
            return String.join("\n", log.subList(Math.max(0, log.size() - 30), log.size()));
        }
    }

    /** Waits until the planner knows every door and the chair is online. */
    private static void awaitReady(AgentRuntime rt, Hospital hospital, io.concord.agents.chair.ChairDriver chair) {
        Pty.await(() -> {
            try {
                return onLoop(rt, hospital::ready) && onLoop(rt, chair::online);
            } catch (InterruptedException e) {
                throw new AssertionError(e);
            }
        }, 30_000, "the planner to know the doors and the chair to be online");
    }

    @Test
    void theControlAgentDrivesTheEmulatedChairFrom19To3OverANoisyLink(@TempDir Path dir) throws Exception {
        List<String> log = java.util.Collections.synchronizedList(new ArrayList<>());
        try (Pty pty = new Pty(dir);
             EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19", "--corrupt", "0.02", "--duplicate", "0.02",
                     "--reorder", "0.02", "--garbage", "0.02");
             Platform platform = Platform.builder().name("hospital").build()) {
            AgentRuntime rt = platform.runtime();
            // The doors live in the host's world (the emulated chair's world has open doorways): the door
            // agents move them as they would real doors.
            HospitalWorld doors = HospitalWorld.builder(MAP).seed(1).build();
            Hospital hospital = Hospital.start(platform, doors, log::add);
            doors.attach(rt);
            SerialChair chair = onLoop(rt, () -> SerialChair.open(rt, SerialChair.Settings.of(pty.host.toString(), "chair1")
                    .withStart(doors.poseAt(19, 90))));
            hospital.addChair(platform, MAP, chair, log::add);
            MedicalAgent medical = new MedicalAgent(log::add);
            platform.startAgent("medical", medical);
            awaitReady(rt, hospital, chair);
            CompletableFuture<MedicalAgent.Outcome> f = medical.transport(19, 3, 0, 1);
            Pty.await(f::isDone, 240_000, "the transport");
            assertTrue(f.join().done(), f.join() + "\n" + tail(log));
            Map<String, String> s = board.status();
            double x = Double.parseDouble(s.get("x"));
            double y = Double.parseDouble(s.get("y"));
            assertTrue(Math.hypot(x - 7.5, y - 15.6) < 0.4, "the emulated chair is at node 3: " + s);
            var drops = chair.drops();
            assertTrue(drops.get("corrupt") > 0 && drops.get("repeated") > 0 && drops.get("out-of-order") > 0,
                    "corrupt, repeated and reordered frames were dropped and counted: " + drops);
            assertTrue(said(log, "control-chair1: at node 3"), tail(log));
        }
    }

    @Test
    void inTheAugmentedModeTheChairStopsAtAVirtualObstacle(@TempDir Path dir) throws Exception {
        List<String> log = java.util.Collections.synchronizedList(new ArrayList<>());
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19");
             Platform platform = Platform.builder().name("hospital").build()) {
            AgentRuntime rt = platform.runtime();
            HospitalWorld virtual = HospitalWorld.builder(MAP).seed(1).build();
            // A trolley across the lobby's way out, in the host's world only: the emulated chair's
            // world has nothing there.
            virtual.addBox("trolley", new io.concord.agents.map.Point(24, 6.0), 1.6, 0.5, 0);
            Hospital hospital = Hospital.start(platform, virtual, log::add);
            virtual.attach(rt);
            io.concord.agents.chair.ChairDriver chair = onLoop(rt, () -> new io.concord.sim.world.AugmentedChair(
                    SerialChair.open(rt, SerialChair.Settings.of(pty.host.toString(), "chair1").withStart(virtual.poseAt(19, 90))), virtual));
            hospital.addChair(platform, MAP, chair, log::add);
            MedicalAgent medical = new MedicalAgent(log::add);
            platform.startAgent("medical", medical);
            awaitReady(rt, hospital, chair);
            medical.transport(19, 3, 0, 1);
            Pty.await(() -> said(log, "control-chair1: stops: something"), 60_000,
                    "the chair to stop for the virtual trolley");
            Map<String, String> s = board.status();
            double y = Double.parseDouble(s.get("y"));
            assertTrue(Double.parseDouble(s.get("moved")) > 0.2, "it set off: " + s);
            assertTrue(y < 6.0 - 0.25 - 0.6, "it stopped before the trolley, which only the host's world has: " + s);
        }
    }

    @Test
    void aHostKilledWithSigkillLeavesTheMotorsAtZero(@TempDir Path dir) throws Exception {
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19")) {
            Process host = JavaProcess.start(SerialHostMain.class, pty.host.toString());
            try {
                board.awaitStatus(st -> st.get("motors").equals("200,200") && Double.parseDouble(st.get("moved")) > 0.05, 30_000,
                        "the host to drive the chair");
                host.destroyForcibly().waitFor();
                board.awaitStatus(st -> st.get("tripped").equals("true"), 5_000, "the board's watchdog");
                Map<String, String> s = board.status();
                assertEquals("0,0", s.get("motors"), s.toString());
                assertEquals("false", s.get("armed"));
            } finally {
                host.destroyForcibly();
            }
        }
    }

    @Test
    void theAdapterUnpluggedAndPluggedInAgainTheDriverReportsOfflineAndComesBack(@TempDir Path dir) throws Exception {
        List<String> events = java.util.Collections.synchronizedList(new ArrayList<>());
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19");
             Platform platform = Platform.builder().name("host").build()) {
            AgentRuntime rt = platform.runtime();
            SerialChair chair = onLoop(rt, () -> {
                SerialChair c = SerialChair.open(rt, SerialChair.Settings.of(pty.host.toString(), "chair"));
                c.setListener(new ChairListener() {
                    @Override
                    public void onReadings(ChairReadings r) {
                        if (r.faults().contains(ChairFault.LINK)) {
                            events.add("link fault");
                        } else if (events.isEmpty() || !events.get(events.size() - 1).equals("reading")) {
                            events.add("reading");
                        }
                    }

                    @Override
                    public void onOnline(boolean up) {
                        events.add(up ? "online" : "offline");
                    }
                });
                return c;
            });
            Pty.await(() -> events.contains("reading"), 10_000, "readings");
            pty.unplug();
            Pty.await(() -> events.contains("offline"), 10_000, "the driver to report the link down");
            pty.start();
            Pty.await(() -> events.lastIndexOf("online") > events.indexOf("offline") && events.get(events.size() - 1).equals("reading"),
                    15_000, "the driver to come back: " + events);
            assertEquals(List.of("online", "reading", "link fault", "offline", "online", "reading"), events);
            assertTrue(onLoop(rt, chair::online));
            assertEquals("concord-board-emulator 3", chair.firmware());
        }
    }

    @Test
    void aNonNeutralCommandAtSwitchOnDoesNotMoveTheChair(@TempDir Path dir) throws Exception {
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19")) {
            SerialPort p = SerialPort.getCommPort(pty.host.toString());
            p.setComPortParameters(115_200, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
            assertTrue(p.openPort());
            try {
                FrameCodec codec = new FrameCodec();
                long t0 = System.nanoTime();
                int[] seq = {0};
                java.util.function.BiConsumer<Integer, byte[]> send = (type, body) -> {
                    byte[] b = codec.encode(new Frame(type, seq[0] == 0 ? Frame.SYNC : 0, seq[0]++, (System.nanoTime() - t0) / 1_000_000, body));
                    p.writeBytes(b, b.length);
                };
                // Full power from the first frame on, at the heartbeat's rate, for a second.
                for (int i = 0; i < 20; i++) {
                    send.accept(Frame.Type.DRIVE, BoardProtocol.drive(500, 500));
                    Thread.sleep(50);   // the host's heartbeat pace, not a wait for an outcome
                }
                Map<String, String> s = board.status();
                assertEquals("0,0", s.get("motors"), s.toString());
                assertTrue(Double.parseDouble(s.get("moved")) < 0.01, "the chair stands: " + s);
                assertEquals("false", s.get("armed"));
                // Neither a STOP nor a DRIVE of 0, 0 arms it (version 3): a heartbeat cannot.
                for (int i = 0; i < 10; i++) {
                    send.accept(i == 0 ? Frame.Type.STOP : Frame.Type.DRIVE, i == 0 ? new byte[0] : BoardProtocol.drive(0, 0));
                    Thread.sleep(50);   // the heartbeat's pace
                }
                send.accept(Frame.Type.DRIVE, BoardProtocol.drive(500, 500));
                Map<String, String> neutral = board.status();
                assertEquals("false", neutral.get("armed"), "neutral frames do not arm: " + neutral);
                assertEquals("0,0", neutral.get("motors"), neutral.toString());
                // The supervisor's resume: an ARM for the board's state as its STATE shows it.
                send.accept(Frame.Type.ARM, BoardProtocol.arm(Long.parseLong(neutral.get("boot")), BoardProtocol.DISARMED_SWITCH_ON));
                send.accept(Frame.Type.DRIVE, BoardProtocol.drive(500, 500));
                board.awaitStatus(st -> st.get("motors").equals("500,500"), 5_000, "the board to take the drive after an ARM");
            } finally {
                p.closePort();
            }
        }
    }

    @Test
    void aBoardPairedWithAnotherKeyIsNeverTakenAndTheSameKeyDrives(@TempDir Path dir) throws Exception {
        java.nio.file.Path boardKey = dir.resolve("board.key");
        java.nio.file.Path otherKey = dir.resolve("other.key");
        java.nio.file.Files.writeString(boardKey, "000102030405060708090a0b0c0d0e0f\n");
        java.nio.file.Files.writeString(otherKey, "0f0e0d0c0b0a09080706050403020100\n");
        try (Pty pty = new Pty(dir); EmulatorProcess board = new EmulatorProcess(pty.board, "--at", "19", "--pair-key", boardKey.toString());
             Platform platform = Platform.builder().name("host").build()) {
            AgentRuntime rt = platform.runtime();
            SerialChair wrong = onLoop(rt, () -> SerialChair.open(rt, SerialChair.Settings.of(pty.host.toString(), "chair")
                    .withKey(io.concord.serial.PairingKey.read(otherKey))));
            Pty.await(() -> wrong.drops().get("mac") > 20, 10_000, "the host to drop the board's frames: " + wrong.drops());
            assertTrue(!onLoop(rt, wrong::online), "a board paired with another key is never online");
            String why = onLoop(rt, wrong::whyOffline);
            assertTrue(why != null && why.contains("fails its MAC check") && why.contains("--pair-key"), why);
            board.awaitStatus(st -> st.get("drops").contains("mac="), 10_000, "the board to drop the host's frames");
            assertEquals("false", board.status().get("armed"));
            onLoop(rt, () -> {
                wrong.close();
                return null;
            });
            SerialChair right = onLoop(rt, () -> SerialChair.open(rt, SerialChair.Settings.of(pty.host.toString(), "chair")
                    .withKey(io.concord.serial.PairingKey.read(boardKey))));
            Pty.await(() -> {
                try {
                    return onLoop(rt, right::online);
                } catch (InterruptedException e) {
                    throw new AssertionError(e);
                }
            }, 10_000, "the paired host to be online");
        }
    }

    @Test
    void aPairingKeyTooShortOrMissingIsRefusedWithWhy(@TempDir Path dir) throws Exception {
        java.nio.file.Path shortKey = dir.resolve("short.key");
        java.nio.file.Files.writeString(shortKey, "00010203");
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> io.concord.serial.PairingKey.read(shortKey));
        assertTrue(e.getMessage().contains("holds 4 bytes; it needs 16 or more"), e.getMessage());
        e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> io.concord.serial.PairingKey.read(dir.resolve("none.key")));
        assertTrue(e.getMessage().startsWith("there is no pairing key file"), e.getMessage());
    }

    /** A board that speaks another version of the protocol: refused, said why, nothing it says taken. */
    @Test
    void aBoardOfAnotherProtocolVersionIsRefusedWithAClearMessage(@TempDir Path dir) throws Exception {
        try (Pty pty = new Pty(dir); Platform platform = Platform.builder().name("host").build()) {
            SerialPort p = SerialPort.getCommPort(pty.board.toString());
            p.setComPortParameters(115_200, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
            assertTrue(p.openPort());
            try {
                AgentRuntime rt = platform.runtime();
                List<String> events = java.util.Collections.synchronizedList(new ArrayList<>());
                SerialChair chair = onLoop(rt, () -> {
                    SerialChair c = SerialChair.open(rt, SerialChair.Settings.of(pty.host.toString(), "chair"));
                    c.setListener(new ChairListener() {
                        @Override
                        public void onReadings(ChairReadings r) {
                            events.add("reading");
                        }

                        @Override
                        public void onEvent(io.concord.agents.chair.ChairEvent e) {
                            events.add(e.kind().toString());
                        }
                    });
                    return c;
                });
                FrameCodec codec = new FrameCodec();
                var layout = io.concord.agents.chair.ChairLayout.standard();
                // A version-2 board: its HELLO has type 0x82.
                byte[] hello = codec.encode(new Frame(Frame.Type.OLD_HELLO, 0, 0, 0, BoardProtocol.hello(2, 1, "old board", layout)));
                p.writeBytes(hello, hello.length);
                int[] mm = new int[layout.sensors().size()];
                for (int i = 1; i <= 5; i++) {
                    byte[] st = codec.encode(new Frame(Frame.Type.STATE, 0, i, i * 50L, BoardProtocol.state(new BoardProtocol.State(1, 0, 0, mm,
                            false, false, true, BoardProtocol.ARMED, 24_000, java.util.Set.of(), null))));
                    p.writeBytes(st, st.length);
                }
                Pty.await(() -> chair.incompatible() != null && chair.drops().get("incompatible") >= 5, 10_000,
                        "the host to refuse the board: " + chair.drops());
                assertTrue(chair.incompatible().contains("the board speaks version 1 or 2 of the chair protocol (its HELLO has type 0x82)"),
                        chair.incompatible());
                assertTrue(chair.incompatible().contains("this host speaks version 3"), chair.incompatible());
                assertTrue(!onLoop(rt, chair::online), "never online");
                assertEquals(List.of("INCOMPATIBLE"), events);
            } finally {
                p.closePort();
            }
        }
    }
}
