package io.concord.sim.scenario;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.sim.maps.MapGenerator;
import io.concord.sim.maps.Shape;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The fleet on maps nobody drew by hand: generated hospitals of each kind (30 nodes, no ring; 60
 * with a ring ward and a wing; 120 with three wards and two wings; each with a bottleneck corridor,
 * dead ends and doors of every kind), seed after seed, with 3 to 20 chairs (as many as the map
 * parks) and 10 transports between random rooms. Every task ends done or failed with a reason,
 * nothing touches anything, nobody is left holding a task or waiting for a route. The map, the
 * chairs and the tasks all come from the seed, so a seed replays. {@code -Dconcord.genmaps.seeds=200}
 * runs 200 seeds (3 by default, one of each kind, for CI); seed {@code s} uses kind {@code s mod 3}.
 */
class GeneratedMapSoakTest {

    private static final List<Shape> KINDS = List.of(Shape.small(), Shape.medium(), Shape.large());

    /** The nodes of a map's rooms: where patients are fetched and taken. */
    static int[] rooms(HospitalMap map) {
        return map.roomNodes().stream().mapToInt(Integer::intValue).toArray();
    }

    /** Seed {@code s}: its kind, and from 3 to 20 chairs as the map parks them. */
    static FleetSoakTest.Result run(long seed) {
        Shape kind = KINDS.get((int) (seed % KINDS.size()));
        HospitalMap map = MapGenerator.map(seed, kind);
        int chairs = Math.min(map.parking().size(), 3 + (int) ((seed * 7) % 18));
        return FleetSoakTest.run(map, rooms(map), seed, chairs, true);
    }

    @Test
    void chairsDoTheirTasksWithoutTouchingAnythingOnGeneratedMaps() {
        long first = Long.getLong("concord.genmaps.first", 1);
        int seeds = Integer.getInteger("concord.genmaps.seeds", 3);
        List<String> report = new ArrayList<>();
        for (long seed = first; seed < first + seeds; seed++) {
            FleetSoakTest.Result r = run(seed);
            String where = "seed " + seed + " (" + KINDS.get((int) (seed % KINDS.size())).name() + ", " + r.chairs()
                    + " chairs; log and picture in target/scenario, target/fleet)";
            for (MedicalAgent.Outcome o : r.outcomes()) {
                assertNotNull(o, where + ": a task did not end: " + r.outcomes());
                assertTrue(o.done() || (o.reason() != null && !o.reason().isBlank()), where + ": failed without a reason: " + o);
            }
            assertEquals(List.of(), r.collisions(), where + ": contacts");
            assertEquals(List.of(), r.busy(), where + ": a chair still holds a task");
            assertEquals(List.of(), r.waits(), where + ": a chair still waits for a route");
            report.add(String.format(Locale.ROOT, "seed %d: %s, %d chairs, %d/10 done, %.0f s, %d moved aside, trace %016x", seed,
                    KINDS.get((int) (seed % KINDS.size())).name(), r.chairs(),
                    r.outcomes().stream().filter(MedicalAgent.Outcome::done).count(), r.worldMs() / 1e3, r.moves(), r.traceHash()));
        }
        System.out.println(String.join("\n", report));
    }

    /**
     * Twenty chairs and fifty transports asked for at once on the large generated hospital: each
     * task is awarded at its first auction (twenty bidders, fifty auctions running side by side;
     * the tasks queued on a chair are kept alive by its progress reports), no chair is left out
     * (each takes at least one; the nearer chairs take more, as the utility wants), and every one
     * is done, with no contact and nobody left waiting. How fast the auctions are is the
     * benchmark's ({@code bench/run quick fleet}).
     */
    @Test
    void twentyChairsTakeFiftyTransportsAskedAtOnce() {
        HospitalMap map = MapGenerator.map(37, Shape.large());
        int[] rooms = rooms(map);
        try (ScenarioTest.Run r = new ScenarioTest.Run(map, 37, io.concord.testkit.FaultPlan.NONE, 20, true,
                MedicalAgent.Settings.standard())) {
            java.util.SplittableRandom random = new java.util.SplittableRandom(37);
            List<java.util.concurrent.CompletableFuture<MedicalAgent.Outcome>> fs = new ArrayList<>();
            while (fs.size() < 50) {
                int from = rooms[random.nextInt(rooms.length)];
                int to = rooms[random.nextInt(rooms.length)];
                if (from != to) {
                    fs.add(r.medical.transport(from, to, random.nextInt(4), 20));
                }
            }
            boolean ended = r.sim.runUntil(() -> fs.stream().allMatch(java.util.concurrent.CompletableFuture::isDone), 4 * 3_600_000L);
            r.writeLogs("fifty-at-once");
            if (!ended || r.world.collisionCount() > 0) {
                io.concord.sim.render.HospitalPicture.write(r.world, java.nio.file.Path.of("target", "fleet", "fifty-at-once.png"),
                        null, r.hospital.traffic().holders());
            }
            assertTrue(ended, "every transport ended; waits: " + r.hospital.traffic().waits());
            java.util.Map<String, Integer> perChair = new java.util.TreeMap<>();
            for (var f : fs) {
                MedicalAgent.Outcome o = f.join();
                assertTrue(o.done(), o.toString());
                // Awarded at its first auction, unless its chair found the way to the patient walled
                // in by idle chairs and gave it back: then once more (the idle chair beside the patient takes it).
                boolean walled = r.log.stream().anyMatch(l -> l.startsWith("medical: ") && l.contains(" failed " + o.task() + ": cannot reach the patient")
                        && l.contains("walled in"));
                assertEquals(walled ? 2 : 1, o.auctions(), "awarded at its first auction (or its second, walled in): " + o);
                perChair.merge(o.chair(), 1, Integer::sum);
            }
            assertEquals(20, perChair.size(), "no chair left idle while transports wait: " + perChair);
            assertEquals(0, r.world.collisionCount(), "no contact: " + r.world.collisions());
            assertEquals(List.of(), r.hospital.traffic().waits());
        }
    }

    @Test
    void aSeedOnAGeneratedMapReplaysBitForBit() {
        FleetSoakTest.Result a = run(4);
        FleetSoakTest.Result b = run(4);
        assertEquals(a.traceHash(), b.traceHash(), "the same seed, the same map and the same trace");
    }
}
