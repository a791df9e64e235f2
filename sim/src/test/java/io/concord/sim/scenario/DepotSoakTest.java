package io.concord.sim.scenario;

import io.concord.agents.control.ControlAgent;
import io.concord.agents.control.TaskView;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.sim.maps.MapGenerator;
import io.concord.sim.maps.Shape;
import io.concord.testkit.FaultPlan;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * Depots (issue 47): generated hospitals whose lobby, where the first parking places are, joins
 * the corridor at one node ({@link Shape#withDepot()}), and every chair released at once: 5 and 10
 * chairs on the medium map, 20 on the large, as many transports as chairs asked for at the same
 * moment; every even seed on the same shape single-lane ({@link Shape#withOneLane()}: one lane on
 * every edge, the narrow passage and the dead-end wings as before). Every task ends, done or failed with its reason; nothing touches anything; and there is
 * no stall: a chair with a task that makes no progress (drives no 0.5 m, changes no phase) for 120 s
 * of hospital time has raised the fleet monitor's alarm (heard by the Medical agent). Each seed's
 * figures are printed with its trace hash. {@code -Dconcord.depot.seeds=N} runs N seeds (1 by
 * default, for CI), {@code -Dconcord.depot.first=S} starts elsewhere, {@code -Dconcord.depot.chairs=5,10}
 * picks the fleet sizes.
 */
class DepotSoakTest {
    static final long LIMIT_MS = 2 * 3_600_000L;
    static final long STALL_MS = 120_000;
    /** The monitor counts from the node a chair last left, the soak from its samples every 5 s: an alarm this late still counts. */
    static final long SLACK_MS = 15_000;

    record Result(long seed, String shape, int chairs, List<MedicalAgent.Outcome> outcomes, long contacts, List<String> stalls,
                  long alarms, long traceHash, long worldMs) {
    }

    static Result run(long seed, Shape shape, int chairs) {
        HospitalMap map = MapGenerator.map(seed, shape.withDepot());
        int[] rooms = GeneratedMapSoakTest.rooms(map);
        try (ScenarioTest.Run r = new ScenarioTest.Run(map, seed, FaultPlan.NONE, chairs, true, MedicalAgent.Settings.standard())) {
            SplittableRandom rnd = new SplittableRandom(seed);
            List<CompletableFuture<MedicalAgent.Outcome>> fs = new ArrayList<>();
            for (int t = 0; t < chairs; t++) {
                int from = rooms[rnd.nextInt(rooms.length)];
                int to = rooms[rnd.nextInt(rooms.length)];
                while (to == from) {
                    to = rooms[rnd.nextInt(rooms.length)];
                }
                fs.add(r.medical.transport(from, to, MedicalAgent.PRIORITIES[rnd.nextInt(3)], 20));
            }
            // Watch every chair with a task: progress is 0.5 m driven or a new phase.
            Map<String, double[]> last = new HashMap<>();
            List<long[]> quiet = new ArrayList<>(); // chair index, since, when seen
            List<String> names = new ArrayList<>();
            List<String> alarmed = new ArrayList<>(); // "chair@t": each alarm with the watch's time it was heard by
            int heard = 0;
            long step = 5_000;
            long t = 0;
            while (t < LIMIT_MS && !fs.stream().allMatch(CompletableFuture::isDone)) {
                r.sim.runFor(step);
                t += step;
                List<MedicalAgent.Alarm> now = r.medical.alarms();
                for (; heard < now.size(); heard++) {
                    alarmed.add(now.get(heard).chair() + "@" + t);
                }
                for (ControlAgent c : r.hospital.controls()) {
                    String name = c.getLocalName();
                    TaskView active = c.tasks().stream()
                            .filter(v -> v.state().compareTo(TaskView.State.TO_PICKUP) >= 0 && v.state().compareTo(TaskView.State.UNLOADING) <= 0)
                            .findFirst().orElse(null);
                    if (active == null) {
                        last.remove(name);
                        continue;
                    }
                    var p = c.pose();
                    double[] l = last.get(name);
                    if (l == null || Math.hypot(p.x() - l[0], p.y() - l[1]) > 0.5 || l[3] != active.state().ordinal()) {
                        last.put(name, new double[] {p.x(), p.y(), t, active.state().ordinal(), 0});
                    } else if (t - l[2] >= STALL_MS && l[4] == 0) {
                        l[4] = 1; // once a quiet spell
                        if (!names.contains(name)) {
                            names.add(name);
                        }
                        quiet.add(new long[] {names.indexOf(name), (long) l[2], t});
                    }
                }
            }
            r.sim.runFor(5_000);
            List<MedicalAgent.Outcome> out = new ArrayList<>();
            for (var f : fs) {
                out.add(f.isDone() ? f.join() : null);
            }
            // A quiet spell is a stall unless the monitor raised its alarm for that chair in it.
            List<MedicalAgent.Alarm> alarms = r.medical.alarms();
            List<String> stalls = new ArrayList<>();
            for (long[] q : quiet) {
                String name = names.get((int) q[0]);
                long from = q[1];
                long until = q[1] + STALL_MS + SLACK_MS;
                boolean told = alarmed.stream().anyMatch(a -> a.startsWith(name + "@")
                        && Long.parseLong(a.substring(a.indexOf('@') + 1)) >= from && Long.parseLong(a.substring(a.indexOf('@') + 1)) <= until);
                if (!told) {
                    stalls.add(name + " quiet from " + q[1] / 1000 + " s (seen at " + q[2] / 1000 + " s), no alarm");
                }
            }
            boolean clean = out.stream().allMatch(o -> o != null && o.done()) && r.world.collisionCount() == 0 && stalls.isEmpty();
            if (!clean) {
                r.log.add("(at the end) traffic holds " + r.hospital.traffic().holders() + ", waits " + r.hospital.traffic().waits());
                r.writeLogs("depot-" + shape.name() + "-" + chairs + "-seed-" + seed);
            }
            return new Result(seed, shape.name(), chairs, out, r.world.collisionCount(), stalls, alarms.size(), r.sim.trace().hash(),
                    r.world.worldTimeNs() / 1_000_000);
        }
    }

    @Test
    void chairsReleasedAtOnceFromDepotsDoEveryTaskWithoutStalls() {
        int seeds = Integer.getInteger("concord.depot.seeds", 1);
        long first = Long.getLong("concord.depot.first", 1);
        int[] counts = java.util.Arrays.stream(System.getProperty("concord.depot.chairs", "5,10,20").split(","))
                .mapToInt(Integer::parseInt).toArray();
        List<String> report = new ArrayList<>();
        List<String> failures = new ArrayList<>();
        for (long seed = first; seed < first + seeds; seed++) {
            for (int chairs : counts) {
                Shape shape = chairs <= Shape.medium().parking() / 2 ? Shape.medium() : Shape.large();
                if (seed % 2 == 0) {
                    shape = shape.withOneLane(); // every other seed single-lane: no chair passes another anywhere
                }
                Result r = run(seed, shape, chairs);
                String line = String.format(Locale.ROOT, "depot seed %d: %s, %d chairs at once, %d/%d done, %d failed, %d contacts, %d stalls, "
                                + "%d alarms, %.0f s, trace %016x", seed, r.shape(), chairs,
                        r.outcomes().stream().filter(o -> o != null && o.done()).count(), chairs,
                        r.outcomes().stream().filter(o -> o != null && !o.done()).count(), r.contacts(), r.stalls().size(), r.alarms(),
                        r.worldMs() / 1e3, r.traceHash());
                System.out.println(line);
                report.add(line);
                String where = "seed " + seed + ", " + chairs + " chairs (log in target/scenario)";
                // Every seed runs, and every failure is listed at the end: a long soak is read whole.
                for (MedicalAgent.Outcome o : r.outcomes()) {
                    if (o == null) {
                        failures.add(where + ": a task did not end: " + r.outcomes());
                        break;
                    }
                    if (!o.done() && (o.reason() == null || o.reason().isBlank())) {
                        failures.add(where + ": failed without a reason: " + o);
                    }
                }
                if (r.contacts() != 0) {
                    failures.add(where + ": " + r.contacts() + " contacts");
                }
                if (!r.stalls().isEmpty()) {
                    failures.add(where + ": stalls " + r.stalls());
                }
            }
        }
        System.out.println(String.join("\n", report));
        assertEquals(List.of(), failures, String.join("\n", failures));
    }
}
