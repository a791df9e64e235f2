package io.concord.sim;

import io.concord.agents.map.HospitalMap;

import org.junit.jupiter.api.Test;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The hospital demo: on the virtual clock, across two JVMs on real sockets, and its options. */
class HospitalDemoTest {

    @Test
    void theScenarioRunsEndToEndOnTheVirtualClock() throws Exception {
        Path png = Path.of("target", "pictures", "hospital-demo.png");
        Files.deleteIfExists(png);
        HospitalDemo.Options o = HospitalDemo.parse(new String[] {"--virtual", "--picture", png.toString()});
        assertTrue(HospitalDemo.runVirtual(HospitalMap.defaultHospital(), o), "the patient reached node 9");
        assertTrue(Files.size(png) > 10_000);
    }

    /**
     * A virtual run recorded with {@code --record}: the console's hospital view every 250 ms of
     * hospital time, which the console's Replay tab plays back; the same seed writes the same
     * file, so a run seen to fail can be watched again as it was.
     */
    @Test
    void aVirtualRunsRecordingIsTheSameForTheSameSeed() throws Exception {
        List<List<String>> runs = new java.util.ArrayList<>();
        for (int i = 0; i < 2; i++) {
            Path file = Path.of("target", "recordings", "virtual-" + i + "-" + System.nanoTime() + ".jsonl");
            Files.createDirectories(file.getParent());
            HospitalDemo.Options o = HospitalDemo.parse(new String[] {"--virtual", "--seed", "7", "--tasks", "3-4:0:5",
                    "--picture", "target/pictures/hospital-recorded.png", "--record", file.toString()});
            assertTrue(HospitalDemo.runVirtual(HospitalMap.defaultHospital(), o));
            runs.add(Files.readAllLines(file));
        }
        assertEquals(runs.get(0), runs.get(1), "the same seed, the same recording");
        List<String> lines = runs.get(0);
        assertTrue(lines.size() > 20 && lines.stream().allMatch(l -> l.matches("\\{\"t\":\\d+,\"topic\":\"view-hospital\",\"data\":\\{.*\\}\\}")),
                lines.size() + " lines, the first: " + lines.get(0));
        java.util.regex.Pattern chair = java.util.regex.Pattern.compile("\"id\":\"chair-chair1\".*?\"x\":\"([-0-9.]+)\",\"y\":\"([-0-9.]+)\"");
        java.util.Set<String> places = new java.util.HashSet<>();
        for (String l : lines) {
            java.util.regex.Matcher m = chair.matcher(l);
            assertTrue(m.find(), "chair1 in every snapshot");
            places.add(m.group(1) + "," + m.group(2));
        }
        assertTrue(places.size() > 10, "the chair moves through the recording: " + places.size() + " places");
        // An existing file is never written over.
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(
                new String[] {"--virtual", "--record", Path.of("target", "recordings").resolve(Files.list(Path.of("target", "recordings"))
                        .filter(f -> f.getFileName().toString().startsWith("virtual-")).findFirst().orElseThrow().getFileName()).toString()}));
        assertTrue(e.getMessage().contains("exists already"), e.getMessage());
    }

    /** The demo's agents across two JVMs on loopback (real sockets, class 7), the world 20 times faster. */
    @Test
    void theScenarioRunsAcrossTwoJvmsOnRealSockets() throws Exception {
        Path png = Path.of("target", "pictures", "hospital-processes.png");
        Files.deleteIfExists(png);
        HospitalDemo.Options o = HospitalDemo.parse(new String[] {"--speed", "20", "--picture", png.toString()});
        java.util.List<String> lines = java.util.Collections.synchronizedList(new java.util.ArrayList<>());
        boolean done = HospitalDemo.runProcesses(o, lines::add);
        String transcript;
        synchronized (lines) {
            transcript = String.join("\n", lines.subList(Math.max(0, lines.size() - 60), lines.size()));
        }
        assertTrue(done, "the patient reached node 9; what the two JVMs printed last:\n" + transcript);
        assertTrue(Files.exists(png), "the ward drew the run");
    }

    @Test
    void optionsAreReadAndBadOnesSayWhatIsWrong() {
        HospitalDemo.Options o = HospitalDemo.parse(new String[] {"--chairs", "3", "--tasks", "3-9:3:60,14-31:1.5"});
        assertEquals(3, o.chairs());
        assertEquals(new HospitalDemo.TaskSpec(14, 31, 1.5, 60), o.tasks().get(1));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--speeed", "3"}))
                .getMessage().contains("unknown option '--speeed'"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--speed", "0"}))
                .getMessage().contains("(0, 1000]"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--seed"}))
                .getMessage().contains("needs a value"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--tasks", "3to9"}))
                .getMessage().contains("from-to"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--picture", "pom.xml/x.png"}))
                .getMessage().contains("is a file, not a directory"), "a picture nowhere to go is refused before the run, not lost after it");
        HospitalDemo.parse(new String[] {"--picture", "target/no-such-dir-yet/x.png"}); // its directories are made when it is written
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--picture", "."}))
                .getMessage().contains("cannot be written there"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--chairs", "0"}))
                .getMessage().contains("1 or more"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--record", "run.jsonl"}))
                .getMessage().contains("it needs --console [host:]port, or --virtual"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--virtual", "--record", "run.txt"}))
                .getMessage().contains("ending in .jsonl"));
        assertEquals(new HospitalDemo.TaskSpec(3, 9, 0, 60), HospitalDemo.parse(new String[] {"--tasks", "3-9"}).tasks().get(0),
                "the short form: priority 0, 60 s to load and unload");
        assertEquals("task '3-9:7': its priority is 0 to 3 (the dissertation's TP: 0, 1.5 or 3)",
                assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--tasks", "3-9:7"})).getMessage());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--tasks", "9-9"}))
                .getMessage().contains("already at node 9"));
        // Rooms by name, as the console's form takes them: A2 and B7 are nodes 3 and 9; an unknown room names the map's rooms.
        assertEquals(java.util.List.of(new HospitalDemo.TaskSpec(3, 9, 3, 60), new HospitalDemo.TaskSpec(14, 9, 0, 60)),
                HospitalDemo.parse(new String[] {"--tasks", "A2-Room B7:3:60,14-b7"}).tasks());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--tasks", "Z9-B7"}))
                .getMessage().matches("task .Z9-B7.: no node or room .Z9. in .*; rooms: A1, A2, A3.*"));
        HospitalDemo.Options far = HospitalDemo.parse(new String[] {"--tasks", "3-99"});
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.check(HospitalMap.defaultHospital(), far))
                .getMessage().startsWith("--tasks 3-99: the default hospital has no node 99; its nodes are [1, 2, 3,"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.check(HospitalMap.defaultHospital(), far))
                .getMessage().contains("; its rooms A1, A2, A3"), "a wrong node number names the rooms too");
        // An empty field is refused, not read as its default: 3-9: and 3-9::60 and 3- say what a task is.
        for (String empty : new String[] {"3-9:", "3-9::60", "3-", "-9", "3-9:3:"}) {
            assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--tasks", empty}))
                    .getMessage().contains("from-to[:priority[:unload]]"), empty);
        }
    }

    /** A chair starts at each of the map's parking places, in order; more chairs than places are refused, saying how many. */
    @Test
    void chairsStartAtTheMapsParkingPlaces() {
        HospitalMap map = HospitalMap.defaultHospital();
        assertEquals(List.of(19, 23, 24, 22, 1, 5, 11, 13, 2, 12), map.parking());
        HospitalDemo.check(map, HospitalDemo.parse(new String[] {"--chairs", "10"}));
        String why = assertThrows(IllegalArgumentException.class,
                () -> HospitalDemo.check(map, HospitalDemo.parse(new String[] {"--chairs", "11"}))).getMessage();
        assertTrue(why.startsWith("--chairs 11: the default hospital has 10 parking places"), why);
        HospitalMap none = HospitalMap.parse("""
                {"format": "concord-hospital-map/1", "name": "two nodes",
                 "nodes": [{"id": 1, "at": [0, 0]}, {"id": 2, "at": [3, 0]}], "edges": [{"from": 1, "to": 2}]}
                """, "two.json");
        why = assertThrows(IllegalArgumentException.class, () -> HospitalDemo.check(none, HospitalDemo.parse(new String[0]))).getMessage();
        assertTrue(why.contains("names no parking places"), why);
    }

    /** {@code --help} gets the usage (not "--help needs a value"), and an unknown option is called unknown, value or not. */
    @Test
    void helpIsAskedForAndAnUnknownOptionIsNamed() {
        assertTrue(HospitalDemo.wantsHelp(new String[] {"--help"}));
        assertTrue(HospitalDemo.wantsHelp(new String[] {"--chairs", "3", "-h"}));
        assertTrue(!HospitalDemo.wantsHelp(new String[] {"--chairs", "3"}));
        assertTrue(HospitalDemo.USAGE.contains("--chairs N") && HospitalDemo.USAGE.contains("--console"));
        assertEquals("unknown option '--speeed'",
                assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--speeed"})).getMessage());
        assertEquals("unknown argument 'fast'",
                assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"fast"})).getMessage());
        assertEquals("--chairs is given twice; give each option once",
                assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--chairs", "3", "--chairs", "4"})).getMessage());
        assertTrue(HospitalDemo.USAGE.contains("concord-demo.jar platform"), "the platform demo is in the usage");
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--operator-key", "k"}))
                .getMessage().contains("needs --console"));
        assertEquals("10 times faster than real time", HospitalDemo.pace(10));
        assertEquals("in real time", HospitalDemo.pace(1));
        assertEquals("2.5 times faster than real time", HospitalDemo.pace(2.5));
    }

    /**
     * The demo with its console, as an operator starts it (the launcher as a real process, its
     * ward and staff JVMs on loopback): after the staff's own transport is done the Medical agent
     * stays, and a transport asked at the console (its HTTP action, as the page posts it) is done
     * and reported in the staff's terminal; SIGTERM to the launcher then stops every JVM it
     * started.
     */
    @Test
    void withTheConsoleTheMedicalAgentStaysAndSigtermLeavesNoJvmBehind() throws Exception {
        Path recording = Path.of("target", "recordings", "demo-" + System.nanoTime() + ".jsonl");
        Files.createDirectories(recording.getParent());
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), Demo.class.getName(), "hospital",
                "--console", "127.0.0.1:0", "--speed", "20", "--tasks", "3-14:0:5", "--picture", "target/pictures/hospital-console-demo.png",
                "--record", recording.toString()));
        Process launcher = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        java.util.concurrent.BlockingQueue<String> lines = new java.util.concurrent.LinkedBlockingQueue<>();
        List<String> all = java.util.Collections.synchronizedList(new java.util.ArrayList<>());
        Thread reader = new Thread(() -> {
            try (java.io.BufferedReader r = launcher.inputReader()) {
                for (String line; (line = r.readLine()) != null; ) {
                    all.add(line);
                    lines.add(line);
                }
            } catch (java.io.IOException e) {
                // the launcher ended
            }
        });
        reader.setDaemon(true);
        reader.start();
        try {
            String console = until(lines, all, l -> l.contains("console: http://")).replaceFirst(".*console: (http://\\S+).*", "$1");
            until(lines, all, l -> l.contains(HospitalDemo.STAFF_DONE + " every transport was done"));
            List<ProcessHandle> children = launcher.descendants().toList();
            assertTrue(children.size() >= 2, "the ward's and the staff's JVMs: " + children);

            java.net.http.HttpResponse<String> asked = java.net.http.HttpClient.newHttpClient().send(
                    java.net.http.HttpRequest.newBuilder(java.net.URI.create(console + "api/views/hospital/transport"))
                            .header("X-Concord-Console", "1").header("Content-Type", "application/x-www-form-urlencoded")
                            .POST(java.net.http.HttpRequest.BodyPublishers.ofString("from=14&to=3&priority=0&unload=5")).build(),
                    java.net.http.HttpResponse.BodyHandlers.ofString());
            assertEquals(200, asked.statusCode(), asked.body());
            until(lines, all, l -> l.matches(".*medical: control-chair\\d+ reports T2 done.*"));

            // SIGTERM, as kill or a service manager sends it; through the handle, since Process.destroy()
            // also closes our end of the launcher's output, and what it prints on the way out would be lost.
            assertTrue(launcher.toHandle().destroy(), "SIGTERM sent");
            assertTrue(launcher.waitFor(120, java.util.concurrent.TimeUnit.SECONDS), "the launcher ended");
            reader.join(10_000);
            synchronized (all) {
                // Stopped from outside, the launcher says so (not "the ward stopped: exit code 143"),
                // and where the ward's picture went.
                assertTrue(all.stream().anyMatch(l -> l.matches("The ward's picture of the run: .*hospital-console-demo\\.png")),
                        "the ward's picture line: " + all.subList(Math.max(0, all.size() - 15), all.size()));
                assertEquals("Stopped: the ward and the staff's terminal were stopped with the launcher.", all.get(all.size() - 1));
                assertTrue(all.stream().noneMatch(l -> l.startsWith("The ward stopped")), "a stop from outside is no failure of the ward");
            }
            for (ProcessHandle child : children) {
                child.onExit().get(60, java.util.concurrent.TimeUnit.SECONDS);
                assertTrue(!child.isAlive(), "a JVM of the demo was left running: " + child.info());
            }
            // --record: the ward's console recorded the run from its start until SIGTERM, the second transport too.
            List<String> recorded = Files.readAllLines(recording);
            assertTrue(recorded.stream().anyMatch(l -> l.contains("\"topic\":\"view-hospital\"") && l.contains("desk-1")),
                    recorded.size() + " lines recorded, none with the transport asked at the console");
        } finally {
            launcher.descendants().forEach(ProcessHandle::destroyForcibly);
            launcher.destroyForcibly();
        }
    }

    /** Everything a process of the demo prints (standard output and error together), once it has ended. */
    private static List<String> runToTheEnd(String... args) throws Exception {
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), Demo.class.getName()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        try {
            List<String> out = new java.util.ArrayList<>();
            try (java.io.BufferedReader r = p.inputReader()) {
                for (String line; (line = r.readLine()) != null; ) {
                    out.add(line);
                }
            }
            assertTrue(p.waitFor(300, java.util.concurrent.TimeUnit.SECONDS), "the demo ended");
            assertEquals(0, p.exitValue(), "the demo succeeded:\n" + String.join("\n", out.subList(Math.max(0, out.size() - 30), out.size())));
            return out;
        } finally {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
        }
    }

    /** The launcher, run to its end: its exit code and what it printed; every JVM it started has ended too. */
    private record Ended(int exit, List<String> out) {
        String tail() {
            return String.join("\n", out.subList(Math.max(0, out.size() - 30), out.size()));
        }
    }

    private static Ended launch(java.util.function.Consumer<Process> meanwhile, String... args) throws Exception {
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), Demo.class.getName()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        List<ProcessHandle> seenChildren = new java.util.concurrent.CopyOnWriteArrayList<>();
        List<String> out = java.util.Collections.synchronizedList(new java.util.ArrayList<>());
        Thread reader = new Thread(() -> {
            try (java.io.BufferedReader r = p.inputReader()) {
                for (String line; (line = r.readLine()) != null; ) {
                    out.add(line);
                    p.descendants().forEach(d -> {
                        if (!seenChildren.contains(d)) {
                            seenChildren.add(d);
                        }
                    });
                }
            } catch (java.io.IOException e) {
                // ended
            }
        });
        reader.setDaemon(true);
        reader.start();
        try {
            meanwhile.accept(p);
            assertTrue(p.waitFor(300, java.util.concurrent.TimeUnit.SECONDS), "the launcher ended");
            reader.join(10_000);
            for (ProcessHandle child : seenChildren) {
                child.onExit().get(60, java.util.concurrent.TimeUnit.SECONDS);
                assertTrue(!child.isAlive(), "a JVM of the demo was left running: " + child.info());
            }
            return new Ended(p.exitValue(), List.copyOf(out));
        } finally {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
        }
    }

    /** A process's command line as /proc has it (arguments between NULs), or "" once it is gone. */
    private static String commandLine(ProcessHandle h) {
        try {
            return new String(Files.readAllBytes(Path.of("/proc", Long.toString(h.pid()), "cmdline")), java.nio.charset.StandardCharsets.UTF_8);
        } catch (java.io.IOException e) {
            return "";
        }
    }

    /** A serial port that does not exist: the demo stops with one line saying so, a non-zero exit, no JVM left behind. */
    @Test
    void aSerialPortThatDoesNotExistStopsTheDemoWithOneLine() throws Exception {
        Ended e = launch(p -> { }, "hospital", "--serial", "/dev/concord-no-such-port", "--picture", "target/pictures/noport.png");
        assertTrue(e.exit() != 0, "a non-zero exit: " + e.tail());
        assertTrue(e.out().stream().anyMatch(l -> l.startsWith("The ward could not start: ") && l.contains("/dev/concord-no-such-port")),
                e.tail());
        assertTrue(e.out().stream().noneMatch(l -> l.contains("ward ready") || l.contains("\tat ")), "no start, no stack trace: " + e.tail());
        // The launcher's shutdown hook runs at its own exit too; it says "Stopped" only when stopped from outside.
        assertTrue(e.out().stream().noneMatch(l -> l.startsWith("Stopped: ")), "an end of its own is no stop from outside: " + e.tail());
    }

    /** The console's port held by another program: the same. */
    @Test
    void aConsolePortInUseStopsTheDemoWithOneLine(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        try (java.net.ServerSocket taken = new java.net.ServerSocket(0, 50, java.net.InetAddress.getLoopbackAddress())) {
            Ended e = launch(p -> { }, "hospital", "--console", "127.0.0.1:" + taken.getLocalPort(), "--operator-key",
                    dir.resolve("op.key").toString(), "--picture", "target/pictures/portinuse.png");
            assertTrue(e.exit() != 0, "a non-zero exit: " + e.tail());
            assertTrue(e.out().stream().anyMatch(l -> l.startsWith("The ward could not start: --console 127.0.0.1:" + taken.getLocalPort())),
                    e.tail());
            assertTrue(e.out().stream().noneMatch(l -> l.contains("\tat ") || l.contains("Exception in thread")), "no stack trace: " + e.tail());
        }
    }

    /** A ward that dies mid-run (kill -9): the launcher says so, stops the staff's JVM and exits non-zero. */
    @Test
    void aWardThatDiesStopsTheDemo() throws Exception {
        Ended e = launch(p -> {
            long end = System.nanoTime() + java.util.concurrent.TimeUnit.SECONDS.toNanos(120);
            while (System.nanoTime() < end) {
                var ward = p.descendants().filter(d -> commandLine(d).contains("\0ward\0")).findFirst();
                if (ward.isPresent() && p.descendants().count() >= 2) {
                    ward.get().destroyForcibly();
                    return;
                }
                try {
                    Thread.sleep(20);   // a poll of the launcher's children, with a deadline
                } catch (InterruptedException stopped) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
        }, "hospital", "--speed", "5", "--picture", "target/pictures/warddies.png");
        assertTrue(e.exit() != 0, "a non-zero exit: " + e.tail());
        assertTrue(e.out().stream().anyMatch(l -> l.startsWith("The ward stopped: ")), e.tail());
    }

    /** The platform demo takes no options: one that is given is refused in one line, with the usage, and exit code 2. */
    @Test
    void thePlatformDemoRefusesAnOption() throws Exception {
        Ended e = launch(p -> { }, "platform", "--bogus");
        assertEquals(2, e.exit(), e.tail());
        assertEquals("platform takes no options; got '--bogus' (the hospital's options go without 'platform')", e.out().get(0));
    }

    /**
     * A clean start prints no warning: what is expected at start (the copies sent against loss, a
     * handshake's second answer) is counted, not warned about; a security reviewer reads a WARN as
     * an attack. The virtual hospital, and the platform demo (three JVMs, a failover), as real processes.
     */
    @Test
    void aVirtualRunAndThePlatformDemoPrintNoWarning() throws Exception {
        List<String> virtual = runToTheEnd("hospital", "--virtual", "--picture", "target/pictures/hospital-virtual-nowarn.png");
        assertTrue(virtual.stream().anyMatch(l -> l.contains("T1")), "the virtual run ran: " + virtual.size() + " lines");
        assertEquals(List.of(), virtual.stream().filter(l -> l.contains(" WARN ")).toList(), "warnings of a clean --virtual run");
        List<String> platform = runToTheEnd("platform");
        assertTrue(platform.stream().anyMatch(l -> l.contains("bought")), "the platform demo traded: " + platform);
        assertEquals(List.of(), platform.stream().filter(l -> l.contains(" WARN ")).toList(), "warnings of the platform demo");
    }

    /** The next line that matches, waiting for the launcher's output (a minute at most per line: a failure, not a timing). */
    private static String until(java.util.concurrent.BlockingQueue<String> lines, List<String> all,
                                java.util.function.Predicate<String> p) throws InterruptedException {
        while (true) {
            String l = lines.poll(180, java.util.concurrent.TimeUnit.SECONDS);
            if (l == null) {
                synchronized (all) {
                    throw new AssertionError("the demo never printed what was awaited; it printed last:\n"
                            + String.join("\n", all.subList(Math.max(0, all.size() - 40), all.size())));
                }
            }
            if (p.test(l)) {
                return l;
            }
        }
    }
}
