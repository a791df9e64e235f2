package io.concord.sim;

import io.concord.agents.map.Area;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Node;
import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.traffic.TrafficRules;
import io.concord.agents.proto.Services;
import io.concord.console.Console;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.Platform;
import io.concord.layers.authority.OperatorKey;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.platform.ServiceDescription;
import io.concord.serial.PairingKey;
import io.concord.serial.SerialChair;
import io.concord.sim.render.HospitalPicture;
import io.concord.sim.world.AugmentedChair;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;

/**
 * The hospital demo: the dissertation's scenario run by the wheelchair's agents on a Concord
 * platform with no main container. By default two JVMs on this machine: the ward (the world, a
 * door agent for every door, a planner and a control agent for every chair) and the staff's
 * terminal (the Medical agent), which find each other by port binding and agree on a container
 * among themselves. The Medical agent asks for a patient to be taken from node 3 to node 9; the
 * chairs' agents plan, ask the doors, propose; the best proposal wins and its chair drives the
 * route through the doors. The conversation is printed as it happens and a picture of the run is
 * written at the end. {@code --virtual} runs it all in one JVM on the test kit's virtual clock.
 */
public final class HospitalDemo {
    private static final PrintStream OUT = System.out;
    private HospitalDemo() {
    }

    /**
     * A transport to ask for.
     *
     * @param from     node where the patient is
     * @param to       node where the patient goes
     * @param priority TP
     * @param unloadS  seconds to load and to unload
     */
    record TaskSpec(int from, int to, double priority, double unloadS) {
        /** A task of node numbers only ({@code 3-9:3:60}). */
        static TaskSpec parse(String s) {
            return parse(s, null);
        }

        /**
         * A task whose ends are node numbers or, with a map, rooms by name ({@code A2-B7:3:60},
         * as {@link HospitalMap#nodeNamed} takes them), given as the rooms' nodes.
         */
        static TaskSpec parse(String s, java.util.function.Supplier<HospitalMap> map) {
            String[] p = s.trim().split(":", -1);
            String[] ends = p[0].split("-", -1);
            if (ends.length != 2 || p.length > 3 || java.util.Arrays.stream(p).anyMatch(String::isBlank)
                    || java.util.Arrays.stream(ends).anyMatch(String::isBlank)) {
                throw new IllegalArgumentException("a task is from-to[:priority[:unload]], nodes or rooms, e.g. 3-9:3:60 or A2-B7:3:60; got '" + s + "'");
            }
            int[] node = new int[2];
            for (int i = 0; i < 2; i++) {
                String e = ends[i].trim();
                if (e.matches("\\d{1,9}")) {
                    node[i] = Integer.parseInt(e);
                } else if (map == null) {
                    throw new IllegalArgumentException("a task is from-to[:priority[:unload]] with node numbers, e.g. 3-9:3:60; got '" + s + "'");
                } else {
                    try {
                        node[i] = map.get().nodeNamed(e);
                    } catch (IllegalArgumentException x) {
                        throw new IllegalArgumentException("task '" + s + "': " + x.getMessage());
                    }
                }
            }
            TaskSpec t;
            try {
                t = new TaskSpec(node[0], node[1], p.length > 1 ? Double.parseDouble(p[1]) : 0,
                        p.length > 2 ? Double.parseDouble(p[2]) : 60);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("a task is from-to[:priority[:unload]], its priority and unload numbers, e.g. 3-9:3:60; got '" + s + "'");
            }
            if (!(t.priority() >= 0 && t.priority() <= 3)) {
                throw new IllegalArgumentException("task '" + s + "': its priority is 0 to 3 (the dissertation's TP: 0, 1.5 or 3)");
            }
            if (!(t.unloadS() >= 0 && t.unloadS() <= 3_600)) {
                throw new IllegalArgumentException("task '" + s + "': seconds to load and unload are 0 to 3600");
            }
            if (t.from() == t.to()) {
                throw new IllegalArgumentException("task '" + s + "': the patient is already at node " + t.to());
            }
            return t;
        }

        @Override
        public String toString() {
            return from + "-" + to + ":" + priority + ":" + unloadS;
        }
    }

    /** Settings of a run. */
    record Options(long seed, double speed, boolean virtual, Path map, Path picture, int chairs, List<TaskSpec> tasks,
                   double maxSeconds, String serial, boolean augmented, String console, Path pairKey, Path record,
                   Path operatorKey) {
        /** The options a child JVM of the demo gets: the ward alone records (its console does). */
        List<String> childArgs(String role) {
            List<String> a = new ArrayList<>(List.of("--seed", Long.toString(seed), "--speed", Double.toString(speed),
                    "--chairs", Integer.toString(chairs), "--picture", picture.toAbsolutePath().toString(),
                    "--max-seconds", Double.toString(maxSeconds), "--tasks", String.join(",", tasks.stream().map(TaskSpec::toString).toList())));
            if (map != null) {
                a.addAll(List.of("--map", map.toAbsolutePath().toString()));
            }
            if (serial != null) {
                a.addAll(List.of("--serial", serial));
            }
            if (augmented) {
                a.add("--augmented");
            }
            if (pairKey != null) {
                a.addAll(List.of("--pair-key", pairKey.toAbsolutePath().toString()));
            }
            if (console != null) {
                a.addAll(List.of("--console", console));
            }
            if (operatorKey != null) {
                a.addAll(List.of("--operator-key", operatorKey.toAbsolutePath().toString()));
            }
            if (record != null && role.equals("ward")) {
                a.addAll(List.of("--record", record.toAbsolutePath().toString()));
            }
            return a;
        }
    }

    static final String USAGE = "usage: java -jar concord-demo.jar [hospital] [--speed X] [--virtual] [--seed N] [--chairs N]"
            + " [--tasks 3-9:3:60,A2-B7,...] [--map file.json] [--picture file.png] [--max-seconds S]"
            + " [--serial PORT [--augmented] [--pair-key FILE]] [--console [host:]port [--operator-key FILE]] [--record FILE.jsonl]\n"
            + "   or: java -jar concord-demo.jar platform   (the platform demo: three JVMs started with Boot, a book trade, a failover)\n"
            + "(each option with its default: README.md, \"The two commands\")";

    /** True if the arguments ask for the usage ({@code --help}, {@code -h}). */
    static boolean wantsHelp(String[] args) {
        return Arrays.stream(args).anyMatch(a -> a.equals("--help") || a.equals("-h"));
    }

    public static void main(String[] args) throws Exception {
        if (wantsHelp(args)) {
            System.out.println(USAGE);
            System.exit(0);
            return;
        }
        String role = args.length > 0 && (args[0].equals("ward") || args[0].equals("staff")) ? args[0] : null;
        Options o;
        HospitalMap map;
        try {
            o = parse(role == null ? args : Arrays.copyOfRange(args, 1, args.length));
            map = o.map() == null ? HospitalMap.defaultHospital() : HospitalMap.load(o.map());
            check(map, o);
        } catch (IllegalArgumentException e) {
            System.err.println(e.getMessage());
            System.err.println(USAGE);
            System.exit(2);
            return;
        }
        boolean ok;
        if (role != null) {
            // A ward or staff JVM of the launcher's ends with it, however it ends (even kill -9): a
            // ward left behind would keep its ports, its console, and a real chair.
            ProcessHandle.current().parent().ifPresent(parent -> parent.onExit().thenRun(() -> {
                System.err.println(role + ": the demo's launcher has ended; so does this JVM");
                System.exit(1);
            }));
        }
        if ("ward".equals(role)) {
            try {
                ward(map, o);
            } catch (Exception e) {
                // One line, no stack trace: the launcher prints it and stops every JVM of the demo.
                System.out.println(WARD_FAILED + " " + oneLine(e));
                System.out.flush();
                System.exit(3);
            }
            return;
        } else if ("staff".equals(role)) {
            ok = staff(o);
        } else if (o.virtual()) {
            ok = runVirtual(map, o);
        } else {
            ok = runProcesses(o);
        }
        System.exit(ok ? 0 : 1);
    }

    /** An option's value: the next argument, which must be there. */
    private static String value(String option, String v) {
        if (v == null) {
            throw new IllegalArgumentException(option + " needs a value");
        }
        return v;
    }

    static Options parse(String[] args) {
        long seed = 2010;
        double speed = 10;
        boolean virtual = false;
        Path map = null;
        Path picture = Path.of("hospital.png");
        int chairs = 1;
        List<TaskSpec> tasks = new ArrayList<>(List.of(new TaskSpec(3, 9, 3, 60)));
        String taskList = null;
        double max = 1800;
        String serial = null;
        boolean augmented = false;
        String console = null;
        Path pairKey = null;
        Path record = null;
        Path operatorKey = null;
        java.util.Set<String> given = new java.util.HashSet<>();
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a.startsWith("--") && !given.add(a)) {
                throw new IllegalArgumentException(a + " is given twice; give each option once");
            }
            if (a.equals("--virtual")) {
                virtual = true;
                continue;
            }
            if (a.equals("--augmented")) {
                augmented = true;
                continue;
            }
            String v = i + 1 < args.length ? args[i + 1] : null;
            try {
                switch (a) {
                    case "--seed" -> seed = Long.parseLong(value(a, v));
                    case "--speed" -> speed = Double.parseDouble(value(a, v));
                    case "--map" -> map = Path.of(value(a, v));
                    case "--picture" -> picture = Path.of(value(a, v));
                    case "--chairs" -> chairs = Integer.parseInt(value(a, v));
                    case "--max-seconds" -> max = Double.parseDouble(value(a, v));
                    case "--serial" -> serial = value(a, v);
                    case "--console" -> console = value(a, v);
                    case "--pair-key" -> pairKey = Path.of(value(a, v));
                    case "--record" -> record = Path.of(value(a, v));
                    case "--operator-key" -> operatorKey = Path.of(value(a, v));
                    case "--tasks" -> taskList = value(a, v);
                    default -> throw new IllegalArgumentException(a.startsWith("-") ? "unknown option '" + a + "'"
                            : "unknown argument '" + a + "'");
                }
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(a + " needs a number, got '" + v + "'");
            }
            i++;
        }
        if (!(speed > 0 && speed <= 1000)) {
            throw new IllegalArgumentException("--speed must be in (0, 1000], got " + speed);
        }
        // The picture's directories are made when it is written; what cannot be made or written is refused now, not after the run.
        Path existing = picture.toAbsolutePath().getParent();
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        if (existing == null || !Files.isDirectory(existing)) {
            throw new IllegalArgumentException("--picture " + picture + ": " + existing
                    + " is a file, not a directory, so the picture cannot go there; name a file in a directory");
        }
        if (!Files.isWritable(existing) || Files.isDirectory(picture) || (Files.exists(picture) && !Files.isWritable(picture))) {
            throw new IllegalArgumentException("--picture " + picture + ": it cannot be written there; name a file you may write");
        }
        if (chairs < 1) {
            throw new IllegalArgumentException("--chairs must be 1 or more (up to the map's parking places), got " + chairs);
        }
        if (serial != null && virtual) {
            throw new IllegalArgumentException("--serial drives a chair in real time over its port: it cannot run with --virtual");
        }
        if (augmented && serial == null) {
            throw new IllegalArgumentException("--augmented adds the simulated world to a real chair's readings: it needs --serial PORT");
        }
        if (pairKey != null && serial == null) {
            throw new IllegalArgumentException("--pair-key is the key the chair's board is paired with: it needs --serial PORT");
        }
        if (pairKey != null) {
            PairingKey.read(pairKey);   // a missing or short key stops the demo here, with why
        }
        if (serial != null) {
            speed = 1;   // the board (real or emulated) keeps real time
        }
        if (console != null && virtual) {
            throw new IllegalArgumentException("--console shows the hospital as it runs in real time: it cannot run with --virtual");
        }
        if (operatorKey != null && console == null) {
            throw new IllegalArgumentException("--operator-key is the key the console signs an operator's resume with: it needs --console [host:]port");
        }
        if (operatorKey != null && Files.exists(operatorKey)) {
            OperatorKey.load(operatorKey);   // not a key, or one others may read: stops the demo here, with why
        }
        if (console != null && operatorKey == null) {
            operatorKey = defaultOperatorKey();
        }
        if (console != null) {
            try {
                Console.Config.parse(console);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("--console: " + e.getMessage());
            }
        }
        if (record != null) {
            String n = record.getFileName().toString();
            if (!n.matches("[A-Za-z0-9][A-Za-z0-9._-]{0,100}\\.jsonl")) {
                throw new IllegalArgumentException("--record names a file of letters, digits, '.', '_' and '-' ending in .jsonl "
                        + "(the console lists it from its directory), got '" + n + "'");
            }
            if (!virtual && console == null) {
                throw new IllegalArgumentException("--record writes what the console shows: it needs --console [host:]port, or --virtual");
            }
            if (Files.exists(record)) {
                throw new IllegalArgumentException("--record: " + record + " exists already; give another file");
            }
        }
        if (taskList != null) {
            // Read once every option is: a room's name is looked up on the map --map names (wherever it came on the line).
            Path mapFile = map;
            HospitalMap[] loaded = new HospitalMap[1];
            java.util.function.Supplier<HospitalMap> theMap = () -> loaded[0] != null ? loaded[0]
                    : (loaded[0] = mapFile == null ? HospitalMap.defaultHospital() : HospitalMap.load(mapFile));
            tasks = new ArrayList<>();
            for (String t : taskList.split(",")) {
                tasks.add(TaskSpec.parse(t, theMap));
            }
        }
        return new Options(seed, speed, virtual, map, picture, chairs, tasks, max, serial, augmented, console, pairKey, record, operatorKey);
    }

    /** The map has a parking place for each chair: where it starts, in the map's order. */
    static void check(HospitalMap map, Options o) {
        String which = o.map() == null ? "the default hospital" : o.map().toString();
        if (map.parking().isEmpty()) {
            throw new IllegalArgumentException(which + " names no parking places, where the demo's chairs start: add"
                    + " \"parking\": [node ids] to it (docs/hospital-map.md)");
        }
        for (TaskSpec t : o.tasks()) {
            for (int n : new int[] {t.from(), t.to()}) {
                if (!map.hasNode(n)) {
                    throw new IllegalArgumentException("--tasks " + t.from() + "-" + t.to() + ": " + which + " has no node " + n
                            + "; its nodes are " + map.nodes().stream().map(x -> x.id()).sorted().toList()
                            + (map.roomNames().isEmpty() ? "" : "; its rooms " + String.join(", ", map.roomNames())));
                }
            }
        }
        if (o.chairs() > map.parking().size()) {
            throw new IllegalArgumentException("--chairs " + o.chairs() + ": " + which + " has " + map.parking().size()
                    + " parking places " + map.parking() + ", one for each chair to start at; ask for fewer chairs or add places"
                    + " to its \"parking\"");
        }
    }

    private static String area(HospitalMap map, int node) {
        if (!map.hasNode(node)) {
            return "no such node";
        }
        Node n = map.node(node);
        String room = map.areaAt(n.at()).map(Area::name).orElse("no area");
        String ward = map.wardAt(n.at()).map(Area::name).orElse(null);
        return ward == null || ward.equals(room) ? room : room + ", " + ward;
    }

    private static void intro(HospitalMap map, Options o) {
        OUT.println("Concord hospital demo: " + map);
        if (!map.warnings().isEmpty()) {
            OUT.println("Warning: on this map a chair may touch walls or doors (docs/hospital-map.md, \"What a chair needs\"), "
                    + map.warnings().size() + (map.warnings().size() == 1 ? " place:" : " places:"));
            map.warnings().forEach(w -> OUT.println("  - " + w));
        }
        for (TaskSpec t : o.tasks()) {
            OUT.printf(Locale.ROOT, "Task: a patient from node %d (%s) to node %d (%s), priority %.1f, %.0f s to load and unload.%n",
                    t.from(), area(map, t.from()), t.to(), area(map, t.to()), t.priority(), t.unloadS());
        }
        OUT.println(o.chairs() + (o.chairs() == 1 ? " chair waits" : " chairs wait") + " at the map's parking places "
                + map.parking().subList(0, o.chairs()) + ".");
        if (o.chairs() > 1) {
            OUT.println("The traffic agent queues the chairs at each node of their routes and lets a chair into a node only"
                    + " when it is first there: they follow each other down corridors, pass each other in two-lane ones, and never meet.");
        }
        if (o.serial() != null) {
            OUT.println("chair1 is driven over the serial port " + o.serial() + " (a real chair's board, or the emulator), in real time"
                    + (o.pairKey() == null ? ", unpaired (no MAC: --pair-key FILE pairs it)." : ", paired with the key in " + o.pairKey()
                    + " (every frame carries a MAC)."));
        }
    }

    // ---- one JVM on the virtual clock ----------------------------------------------------------

    /** Everything in one JVM on the test kit's virtual clock: deterministic from the seed. */
    static boolean runVirtual(HospitalMap map, Options o) {
        intro(map, o);
        OUT.println("The platform, the agents and the world run on the test kit's virtual clock and network, as fast as the CPU allows.");
        HospitalWorld[] seen = new HospitalWorld[1];
        Consumer<String> log = line -> OUT.printf(Locale.ROOT, "  t=%7.1f s  %s%n", seen[0] == null ? 0 : seen[0].worldTimeNs() / 1e9, line);
        try (VirtualHospital h = new VirtualHospital(map, o.seed(), FaultPlan.NONE, o.chairs(), TrafficRules.IN_ORDER,
                MedicalAgent.Settings.standard(), log)) {
            seen[0] = h.world;
            Simulation sim = h.sim;
            HospitalWorld world = h.world;
            MedicalAgent medical = h.medical;
            h.ready();
            List<CompletableFuture<MedicalAgent.Outcome>> fs = new ArrayList<>();
            for (TaskSpec t : o.tasks()) {
                fs.add(medical.transport(t.from(), t.to(), t.priority(), t.unloadS()));
            }
            long t0 = System.nanoTime(); // wall time, printed beside the hospital's: the demo's own figure, not the platform's clock
            if (o.record() == null) {
                sim.runUntil(() -> fs.stream().allMatch(CompletableFuture::isDone), (long) (o.maxSeconds() * 1000));
            } else {
                record(h, o, () -> fs.stream().allMatch(CompletableFuture::isDone));
            }
            double wall = (System.nanoTime() - t0) / 1e9;
            writePicture(world, o);
            OUT.printf(Locale.ROOT, "%n%.1f s of hospital in %.1f s of wall time; %d collisions.%n", world.worldTimeNs() / 1e9, wall,
                    world.collisionCount());
            return report(fs);
        }
    }

    /**
     * Runs the virtual hospital, writing the console's hospital view every {@link #RECORD_STEP_MS}
     * of hospital time, as the console records it ({@code {"t":ms,"topic":"view-hospital","data":...}}):
     * the console plays the file back with its slider. The same seed writes the same file.
     */
    private static void record(VirtualHospital h, Options o, java.util.function.BooleanSupplier done) {
        HospitalView view = new HospitalView(h.world, h.hospital, null);
        long end = (long) (o.maxSeconds() * 1000);
        try (java.io.BufferedWriter out = Files.newBufferedWriter(o.record(), StandardCharsets.UTF_8, java.nio.file.StandardOpenOption.CREATE_NEW)) {
            for (long ms = 0; ms <= end; ms += RECORD_STEP_MS) {
                out.write("{\"t\":" + h.world.worldTimeNs() / 1_000_000 + ",\"topic\":\"view-hospital\",\"data\":" + view.snapshot() + "}\n");
                if (done.getAsBoolean()) {
                    break;
                }
                h.sim.runFor(RECORD_STEP_MS);
            }
        } catch (IOException e) {
            throw new java.io.UncheckedIOException("--record: cannot write " + o.record() + ": " + e.getMessage(), e);
        }
        OUT.println("Recording: " + o.record().toAbsolutePath() + " (open it in the console's Replay tab from its directory)");
    }

    /** How often a virtual run's recording takes the hospital view, in hospital time. */
    static final long RECORD_STEP_MS = 250;

    static HospitalWorld world(HospitalMap map, Options o) {
        HospitalWorld world = HospitalWorld.builder(map).seed(o.seed()).build();
        for (int i = o.serial() == null ? 0 : 1; i < o.chairs(); i++) {
            world.addChair("chair" + (i + 1), ChairConfig.standard().withWatchdog(0.3), world.poseAt(map.parking().get(i), 90));
        }
        return world;
    }

    private static void writePicture(HospitalWorld world, Options o) {
        HospitalPicture.write(world, o.picture(), String.format(Locale.ROOT, "%s: seed %d, t = %.1f s", world.map().name(),
                o.seed(), world.worldTimeNs() / 1e9));
        OUT.println("Picture: " + o.picture().toAbsolutePath());
    }

    private static boolean report(List<CompletableFuture<MedicalAgent.Outcome>> fs) {
        boolean all = true;
        for (CompletableFuture<MedicalAgent.Outcome> f : fs) {
            if (!f.isDone()) {
                OUT.println("A transport did not end in time.");
                all = false;
                continue;
            }
            MedicalAgent.Outcome out = f.join();
            OUT.println(out.done() ? out.task() + ": done by " + out.chair() + (out.auctions() > 1 ? " after " + out.auctions() + " auctions" : "")
                    : out.task() + ": not done: " + out.reason());
            all &= out.done();
        }
        return all;
    }

    // ---- two JVMs on real sockets ----------------------------------------------------------------

    /** The ward and the staff's terminal as two JVMs; true if every transport was done. */
    static boolean runProcesses(Options o) throws Exception {
        return runProcesses(o, line -> { });
    }

    /** As {@link #runProcesses(Options)}, and each line the two JVMs print also goes to {@code seen}. */
    static boolean runProcesses(Options o, Consumer<String> seen) throws Exception {
        HospitalMap map = o.map() == null ? HospitalMap.defaultHospital() : HospitalMap.load(o.map());
        intro(map, o);
        OUT.printf(Locale.ROOT, "This launcher starts two JVMs on this machine: the ward (world, doors' and chairs' agents) and the "
                + "staff's terminal (the Medical agent). No address is configured: they find each other by port binding on 127.0.0.1 "
                + "(7001 and up) and elect a container. The world runs %s. The ward's lines carry hospital time (t=...), "
                + "the staff's the seconds since its JVM started.%n%n", pace(o.speed()));
        Process ward = spawn("ward", o);
        List<Process> children = new CopyOnWriteArrayList<>(List.of(ward));
        List<Thread> pumps = new CopyOnWriteArrayList<>();
        long launched = System.currentTimeMillis();
        // Whoever ends the run first says how it ended: the launcher's own end, or the hook when it was stopped from
        // outside (the hook also runs at the launcher's own exit, and is then silent).
        java.util.concurrent.atomic.AtomicBoolean settled = new java.util.concurrent.atomic.AtomicBoolean();
        // Stopped (Ctrl-C, kill), the launcher stops its JVMs first: a ward left running would keep driving a real chair.
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            boolean fromOutside = settled.compareAndSet(false, true);
            for (Process p : children) {
                p.destroy();
            }
            for (Process p : children) {
                try {
                    if (!p.waitFor(20, TimeUnit.SECONDS)) {
                        p.destroyForcibly();
                    }
                } catch (InterruptedException e) {
                    p.destroyForcibly();
                }
            }
            if (!fromOutside) {
                return;
            }
            drain(pumps);
            pictureLine(o, launched);
            OUT.println("Stopped: the ward and the staff's terminal were stopped with the launcher.");
        }, "demo-stop-children"));
        CompletableFuture<String> wardStart = new CompletableFuture<>();
        AtomicReference<String> wardFailure = new AtomicReference<>();
        pumps.add(pump(ward, "ward ", line -> {
            seen.accept("[ward ] " + line);
            if (line.contains("ward ready")) {
                wardStart.complete(null);
            } else if (line.startsWith(WARD_FAILED)) {
                wardFailure.set(line.substring(WARD_FAILED.length()).trim());
            }
        }));
        ward.onExit().thenRun(() -> wardStart.complete(wardFailure.get() != null ? wardFailure.get()
                : "its JVM ended (exit code " + ward.exitValue() + ")"));
        String failed;
        try {
            failed = wardStart.get(60, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            failed = "it did not start within 60 s";
        }
        if (failed != null) {
            ward.destroyForcibly().waitFor(20, TimeUnit.SECONDS);
            if (!settled.compareAndSet(false, true)) {
                return false;   // stopped from outside while the ward started: the hook says so
            }
            OUT.println("The ward could not start: " + failed);
            return false;
        }
        Process staff = spawn("staff", o);
        children.add(0, staff);
        // With a console the staff's JVM stays after its transports (the Medical agent takes those
        // asked at the console); it says how its own went in one line.
        CompletableFuture<Boolean> batch = new CompletableFuture<>();
        pumps.add(pump(staff, "staff", line -> {
            seen.accept("[staff] " + line);
            if (line.startsWith(STAFF_DONE)) {
                batch.complete(line.startsWith(STAFF_DONE + " every transport was done"));
            }
        }));
        staff.onExit().thenRun(() -> batch.complete(staff.exitValue() == 0));
        // A ward that dies ends the demo: the staff's transports could only wait for it.
        ward.onExit().thenRun(() -> {
            if (batch.complete(false)) {
                wardFailure.compareAndSet(null, "its JVM ended (exit code " + ward.exitValue() + ")");
            }
        });
        boolean ok;
        try {
            ok = batch.get((long) (o.maxSeconds() / o.speed()) + 120, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            ok = false;
        }
        if (o.console() != null && ward.isAlive() && staff.isAlive()) {
            OUT.println("The staff's transports ended; the ward, its console and the Medical agent go on (ask for more "
                    + "transports there). Ctrl-C stops them.");
            ward.waitFor();
        }
        // A ward that ended before the launcher stops it died: so told, whichever JVM's end was seen
        // first (the staff's JVM may end on the ward's death before the ward's own exit is reported).
        if (!ward.isAlive()) {
            wardFailure.compareAndSet(null, "its JVM ended (exit code " + ward.exitValue() + ")");
        }
        for (Process p : List.of(staff, ward)) {
            p.destroy();   // the ward's shutdown hook writes the picture
            if (!p.waitFor(20, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
        drain(pumps);   // the JVMs' last lines (the ward's picture, its link's counts) before the launcher's own
        if (!settled.compareAndSet(false, true)) {
            return false;   // stopped from outside: the hook says so, it is no failure of the ward
        }
        pictureLine(o, launched);
        if (wardFailure.get() != null) {
            OUT.println("The ward stopped: " + wardFailure.get());
            return false;
        }
        OUT.println(ok ? "Every transport of --tasks was done." : "Not every transport of --tasks was done.");
        return ok;
    }

    /** What the ward's JVM says, before it exits, when it cannot start or goes on no longer: the reason follows. */
    static final String WARD_FAILED = "ward: cannot go on:";

    /** A failure in one line: its message, else its class; the cause's message where the failure only wraps it. */
    static String oneLine(Throwable e) {
        Throwable t = e instanceof java.util.concurrent.ExecutionException || e instanceof java.util.concurrent.CompletionException
                ? (e.getCause() == null ? e : e.getCause()) : e;
        String m = t.getMessage();
        return (m == null || m.isBlank() ? t.getClass().getSimpleName() : m).replace('\n', ' ');
    }

    /** What the staff's JVM says when its own transports have ended: then "every transport was done" or "not every...". */
    static final String STAFF_DONE = "staff: its transports ended:";

    private static Process spawn(String role, Options o) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), "-Dorg.slf4j.simpleLogger.defaultLogLevel=warn"));
        // The parent's -D options (concord.home, the idle strategy, a log level) hold in its children too.
        for (String arg : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (arg.startsWith("-D")) {
                cmd.add(arg);
            }
        }
        cmd.addAll(List.of(Demo.class.getName(), role));
        cmd.addAll(o.childArgs(role));
        return new ProcessBuilder(cmd).redirectErrorStream(true).start();
    }

    /** Where the ward's picture of this run went, if it wrote one. */
    private static void pictureLine(Options o, long launched) {
        try {
            if (Files.exists(o.picture()) && Files.getLastModifiedTime(o.picture()).toMillis() >= launched - 1_000) {
                OUT.println("The ward's picture of the run: " + o.picture().toAbsolutePath());
            }
        } catch (IOException e) {
            // no picture to tell of
        }
    }

    /** Waits a little for each pump to have printed its JVM's last lines. */
    private static void drain(List<Thread> pumps) {
        for (Thread t : pumps) {
            try {
                t.join(5_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    private static Thread pump(Process p, String prefix, Consumer<String> watch) {
        Thread t = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    synchronized (OUT) {
                        OUT.println("[" + prefix + "] " + line);
                    }
                    watch.accept(line);
                }
            } catch (IOException e) {
                // the process ended
            }
        }, "demo-" + prefix.trim());
        t.setDaemon(true);
        t.start();
        return t;
    }

    /** "10 times faster than real time", "in real time", "2.5 times faster than real time", "half as fast as real time". */
    static String pace(double speed) {
        if (speed == 1) {
            return "in real time";
        }
        String x = speed == Math.rint(speed) ? String.format(Locale.ROOT, "%.0f", speed) : String.format(Locale.ROOT, "%.2f", speed)
                .replaceAll("0+$", "").replaceAll("\\.$", "");
        return speed > 1 ? x + " times faster than real time" : x + " times as fast as real time";
    }

    /** Where the demo keeps the operator key when {@code --operator-key} names none: {@code ~/.concord/operator.key}. */
    static Path defaultOperatorKey() {
        return Path.of(System.getProperty("user.home"), ".concord", "operator.key");
    }

    /** The ward's JVM: the world, the doors' and the chairs' agents, until it is stopped. */
    static void ward(HospitalMap map, Options o) throws Exception {
        Platform platform = Platform.builder().name("hospital").build();
        AgentRuntime rt = platform.runtime();
        HospitalWorld world = world(map, o);
        Consumer<String> log = line -> OUT.printf(Locale.ROOT, "t=%7.1f s  %s%n", world.worldTimeNs() / 1e9, line);
        Hospital hospital = Hospital.start(platform, world, log);
        if (o.operatorKey() != null) {
            // The console signs a held chair's resume with this key; the chairs' agents trust it.
            hospital.operatorKey(OperatorKey.loadOrCreate(o.operatorKey(), System.getProperty("user.name", "operator").replaceAll("[^A-Za-z0-9 ._@:-]", "-"), OUT::println));
        }
        world.attach(rt, o.speed());
        AtomicReference<Console> console = new AtomicReference<>();
        if (o.console() != null) {
            HospitalView.FrontDesk desk = new HospitalView.FrontDesk();
            platform.startAgent("desk", desk);
            Console.Config cc = Console.Config.parse(o.console());
            if (o.record() != null) {
                cc = cc.withRecordings(o.record().toAbsolutePath().getParent());
            }
            Console c;
            try {
                c = Console.start(platform, cc);
            } catch (RuntimeException e) {
                platform.close();
                throw new IllegalStateException("--console " + o.console() + ": " + oneLine(e)
                        + " (another program holds the port? give another: --console 127.0.0.1:7790)", e);
            }
            c.addView(new HospitalView(world, hospital, desk));
            OUT.println("console: " + c.uri() + "  (the hospital, the platform, the safety counters and the sniffer)");
            if (o.record() != null) {
                OUT.println("recording to " + c.startRecording(o.record().getFileName().toString()).toAbsolutePath()
                        + " (the console's Replay tab plays it back)");
                console.set(c);
            }
        }
        AtomicReference<SerialChair> serialChair = new AtomicReference<>();
        if (o.serial() != null) {
            // chair1 is on its serial port; the world keeps the doors (and any other chairs). A port
            // that cannot be opened stops the ward (and the demo) with why.
            CompletableFuture<Void> opened = new CompletableFuture<>();
            rt.execute(() -> {
                try {
                    SerialChair c = SerialChair.open(rt,
                            SerialChair.Settings.of(o.serial(), "chair1").withStart(world.poseAt(map.parking().get(0), 90))
                                    .withKey(o.pairKey() == null ? null : PairingKey.read(o.pairKey())));
                    serialChair.set(c);
                    hospital.addChair(platform, map, o.augmented() ? new AugmentedChair(c, world) : c, log);
                    opened.complete(null);
                } catch (RuntimeException e) {
                    opened.completeExceptionally(e);
                }
            });
            try {
                opened.get(30, TimeUnit.SECONDS);
            } catch (java.util.concurrent.ExecutionException | TimeoutException e) {
                platform.close();
                throw e;
            }
        }
        CountDownLatch stopped = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            Console recording = console.get();
            if (recording != null) {
                OUT.println("recorded " + recording.stopRecording());
            }
            CountDownLatch drawn = new CountDownLatch(1);
            rt.execute(() -> {
                try {
                    SerialChair s = serialChair.get();
                    if (s != null) {
                        s.close();   // a STOP now, rather than the board's watchdog 200 ms after the last frame
                        OUT.println(s.name() + "'s link: " + s.accepted() + " board frames taken, " + s.framesSent() + " sent, "
                                + s.sessions() + " session(s); dropped: " + (s.drops().total() == 0 ? "none" : s.drops()));
                    }
                    writePicture(world, o);
                    OUT.printf(Locale.ROOT, "%.1f s of hospital; %d collisions.%n", world.worldTimeNs() / 1e9, world.collisionCount());
                } finally {
                    drawn.countDown();
                }
            });
            try {
                drawn.await(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            platform.close();
            stopped.countDown();
        }));
        AtomicInteger ready = new AtomicInteger();
        while (ready.get() == 0) {
            CountDownLatch asked = new CountDownLatch(1);
            rt.execute(() -> {
                if (hospital.ready()) {
                    ready.set(1);
                }
                asked.countDown();
            });
            asked.await();
            Thread.sleep(100);   // a person's patience, not a test's timing: the ward waits for its own agents
        }
        OUT.println("ward ready: " + world.doors().size() + " door agents, " + o.chairs() + (o.chairs() == 1 ? " chair" : " chairs") + " with a planner and a control agent each");
        stopped.await();
    }

    /** The staff's JVM: the Medical agent asks for the transports and waits for them. */
    static boolean staff(Options o) throws Exception {
        Platform platform = Platform.builder().name("hospital").build();
        AgentRuntime rt = platform.runtime();
        // Wall time: the staff's terminal prints how long each line took a person to see, and gives up after a minute.
        long start = System.nanoTime();
        MedicalAgent medical = new MedicalAgent(line -> OUT.printf(Locale.ROOT, "%6.1f s  %s%n", (System.nanoTime() - start) / 1e9, line));
        if (o.operatorKey() != null && Files.exists(o.operatorKey())) {
            // The console's operator (the ward made its key before this JVM started) may cancel the staff's transports too.
            medical.operators(io.concord.layers.authority.Operators.of(OperatorKey.load(o.operatorKey()).operator()));
        }
        platform.startAgent("medical", medical);
        // Wait until the yellow pages list every chair.
        while (true) {
            CompletableFuture<Integer> n = new CompletableFuture<>();
            rt.execute(() -> n.complete(Platform.of(medical).searchCopy(ServiceDescription.ofType(Services.TRANSPORT)).size()));
            if (n.get(10, TimeUnit.SECONDS) >= o.chairs()) {
                break;
            }
            if (System.nanoTime() - start > 60e9) {
                OUT.println("No chair appeared in the yellow pages within 60 s: is the ward running, with the same platform key?");
                platform.close();
                return false;
            }
            Thread.sleep(100);   // a person's patience: the staff waits for the chairs to be listed
        }
        CompletableFuture<Void> container = new CompletableFuture<>();
        rt.execute(() -> {
            OUT.println("staff: the chairs are in the yellow pages; container: " + Platform.of(medical).container());
            container.complete(null);
        });
        container.get(10, TimeUnit.SECONDS);
        List<CompletableFuture<MedicalAgent.Outcome>> fs = new ArrayList<>();
        for (TaskSpec t : o.tasks()) {
            fs.add(medical.transport(t.from(), t.to(), t.priority(), t.unloadS()));
        }
        try {
            CompletableFuture.allOf(fs.toArray(new CompletableFuture[0])).get((long) (o.maxSeconds() / o.speed()) + 60, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            OUT.println("staff: not every transport ended in time");
        }
        boolean ok = report(fs);
        OUT.println(STAFF_DONE + (ok ? " every transport was done" : " not every transport was done")
                + (o.console() == null ? "" : "; the Medical agent stays for transports asked at the console"));
        if (o.console() != null) {
            // Until the launcher stops this JVM (Ctrl-C, SIGTERM, or its own end): the Medical agent
            // answers the console's front desk and reports what it asked for.
            new CountDownLatch(1).await();
        }
        platform.close();
        return ok;
    }
}
