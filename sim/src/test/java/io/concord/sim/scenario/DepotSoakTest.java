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
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Depots: generated maps whose lobby joins the corridor at one node, every chair released at once (issue 47). */
class DepotSoakTest {
    static final long LIMIT_MS = 2 * 3_600_000L;

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
            // Watch every chair with a task: a stall is 120 s without progress (a phase, or 0.3 m driven).
            Map<String, double[]> last = new HashMap<>();
            List<String> stalls = new ArrayList<>();
            long step = 5_000;
            long t = 0;
            while (t < LIMIT_MS && !fs.stream().allMatch(CompletableFuture::isDone)) {
                r.sim.runFor(step);
                t += step;
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
                    if (l == null || Math.hypot(p.x() - l[0], p.y() - l[1]) > 0.3 || l[3] != active.state().ordinal()) {
                        last.put(name, new double[] {p.x(), p.y(), t, active.state().ordinal()});
                    } else if (t - l[2] >= 120_000 && l[2] >= 0) {
                        stalls.add(name + " at " + t / 1000 + " s: " + active + " waits for " + c.waitingFor());
                        l[2] = -1e18; // once
                    }
                }
            }
            r.sim.runFor(5_000);
            List<MedicalAgent.Outcome> out = new ArrayList<>();
            for (var f : fs) {
                out.add(f.isDone() ? f.join() : null);
            }
            r.writeLogs("depot-" + shape.name() + "-" + chairs + "-seed-" + seed);
            return new Result(seed, shape.name(), chairs, out, r.world.collisionCount(), stalls, 0, r.sim.trace().hash(),
                    r.world.worldTimeNs() / 1_000_000);
        }
    }

    @Test
    void depotsDrain() {
        int seeds = Integer.getInteger("concord.depot.seeds", 1);
        List<String> report = new ArrayList<>();
        long first = Long.getLong("concord.depot.first", 1);
        int[] counts = java.util.Arrays.stream(System.getProperty("concord.depot.chairs", "5,10,20").split(",")).mapToInt(Integer::parseInt).toArray();
        for (long seed = first; seed < first + seeds; seed++) {
            for (int chairs : counts) {
                Shape shape = chairs <= 10 ? Shape.medium() : Shape.large();
                Result r = run(seed, shape, chairs);
                report.add(String.format(Locale.ROOT, "seed %d %s %d chairs: %d/%d done, %d contacts, %d stalls %s, %.0f s, trace %016x",
                        seed, shape.name(), chairs, r.outcomes().stream().filter(o -> o != null && o.done()).count(), chairs, r.contacts(),
                        r.stalls().size(), r.stalls(), r.worldMs() / 1e3, r.traceHash()));
                System.out.println(report.get(report.size() - 1));
            }
        }
        System.out.println(String.join("\n", report));
    }
}
