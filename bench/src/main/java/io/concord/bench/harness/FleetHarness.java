package io.concord.bench.harness;

import io.concord.agents.control.ControlAgent;
import io.concord.agents.control.TaskView;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.traffic.TrafficRules;
import io.concord.sim.VirtualHospital;
import io.concord.sim.maps.MapGenerator;
import io.concord.sim.maps.Shape;
import io.concord.sim.world.SimChair;
import io.concord.testkit.FaultPlan;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The fleet's scale curve: a generated hospital (30, 60 or 120 nodes), N chairs, and a stream of
 * transports between random rooms that keeps one and a half per chair outstanding (a new one as
 * each ends), for a stretch of simulated time, on the test kit's virtual clock. Measured: transports
 * done per simulated hour, the patients' wait (from the request to the chair at their door: mean and
 * p95), the traffic agent's decisions (wall time a call of its rules, p99), chair-hours spent
 * standing still with a task under way (waiting for a route, a turn, a door), contacts, and CPU
 * per simulated hour. Every run is deterministic from its seed.
 */
public final class FleetHarness {
    private static final Pattern REQUESTED = Pattern.compile("^medical: transport (T\\d+) from node");
    private static final Pattern LOADING = Pattern.compile("^medical: (T\\d+) on control-chair\\d+: loading at node");
    private static final Pattern PROPOSES = Pattern.compile("^medical: (control-chair\\d+) proposes cost ([0-9.]+), path [0-9.]+ for (T\\d+)");
    private static final Pattern ACCEPT = Pattern.compile("^medical: ACCEPT (control-chair\\d+) for (T\\d+)");

    public record Outcome(String map, int nodes, int chairs, TrafficRules rules, double simHours, int done, int failed,
                          double waitMeanS, double waitP95S, double decisionP99Us, long decisions, double chairHoursWaiting,
                          long contacts, double cpuSPerSimHour, long movedAside, long deadlocks, long deadlockedReviews,
                          Map<String, Double> waitingFor, long stalls, long alarms, double pastMedianS, double pastP95S) {
        public double donePerHour() {
            return done / simHours;
        }
    }

    private FleetHarness() {
    }

    /** The rooms of a map: where patients are fetched and taken. */
    static int[] rooms(HospitalMap map) {
        return map.roomNodes().stream().mapToInt(Integer::intValue).toArray();
    }

    /** The generated map of a shape the curve uses (the same seed each time). */
    public static HospitalMap map(Shape shape) {
        return MapGenerator.map(37, shape);
    }

    /** One point of the curve: {@code chairs} chairs on {@code map} for {@code simSeconds} of hospital time. */
    public static Outcome run(HospitalMap map, int chairs, TrafficRules rules, double simSeconds, long seed) {
        int[] rooms = rooms(map);
        Map<String, Long> requestedMs = new HashMap<>();
        List<Double> waitsS = new ArrayList<>();
        // A ride past its estimate: from the award to the delivery, less the cost the winner proposed
        // (its seconds until the patient is delivered).
        Map<String, Double> proposed = new HashMap<>();
        Map<String, double[]> awarded = new HashMap<>(); // task -> {award ms, estimate s}
        List<Double> pastS = new ArrayList<>();
        long[] now = {0};
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        try (VirtualHospital h = new VirtualHospital(map, seed, FaultPlan.NONE, chairs, rules, MedicalAgent.Settings.standard(),
                line -> {
                    Matcher m = REQUESTED.matcher(line);
                    if (m.find()) {
                        requestedMs.put(m.group(1), now[0]);
                        return;
                    }
                    m = PROPOSES.matcher(line);
                    if (m.find()) {
                        proposed.put(m.group(3) + " " + m.group(1), Double.parseDouble(m.group(2)));
                        return;
                    }
                    m = ACCEPT.matcher(line);
                    if (m.find()) {
                        Double cost = proposed.get(m.group(2) + " " + m.group(1));
                        if (cost != null) {
                            awarded.put(m.group(2), new double[] {now[0], cost});
                        }
                        return;
                    }
                    m = LOADING.matcher(line);
                    if (m.find()) {
                        Long t0 = requestedMs.remove(m.group(1));
                        if (t0 != null) {
                            waitsS.add((now[0] - t0) / 1000.0);
                        }
                    }
                })) {
            if (!h.ready()) {
                throw new IllegalStateException("the planners of " + map.name() + " did not learn its doors");
            }
            SplittableRandom random = new SplittableRandom(seed);
            int outstanding = (chairs * 3 + 1) / 2;
            List<CompletableFuture<MedicalAgent.Outcome>> open = new ArrayList<>();
            int[] counts = new int[2];
            long cpu0 = cpu.getCurrentThreadCpuTime();
            long start = h.world.worldTimeNs() / 1_000_000;
            long end = start + (long) (simSeconds * 1000);
            double waitingChairS = 0;
            Map<String, Double> waitingFor = new java.util.TreeMap<>();
            // Stalls (issue 47): a chair with a task quiet (no 0.5 m driven, no new phase) for 120 s
            // whose quiet spell the fleet monitor did not report (an alarm in it, or within 15 s of its limit).
            Map<String, double[]> quiet = new HashMap<>();
            List<String[]> spells = new ArrayList<>();
            Map<String, List<Long>> alarmedAt = new HashMap<>();
            int alarmsHeard = 0;
            while (true) {
                now[0] = h.world.worldTimeNs() / 1_000_000;
                if (now[0] >= end) {
                    break;
                }
                open.removeIf(f -> {
                    if (!f.isDone()) {
                        return false;
                    }
                    counts[f.join().done() ? 0 : 1]++;
                    double[] a = awarded.remove(f.join().task());
                    if (f.join().done() && a != null) {
                        pastS.add((now[0] - a[0]) / 1000.0 - a[1]);
                    }
                    return true;
                });
                while (open.size() < outstanding) {
                    int from = rooms[random.nextInt(rooms.length)];
                    int to = rooms[random.nextInt(rooms.length)];
                    if (from != to) {
                        open.add(h.medical.transport(from, to, random.nextInt(6), 20));
                    }
                }
                h.sim.runFor(1_000);
                long tNow = h.world.worldTimeNs() / 1_000_000;
                List<MedicalAgent.Alarm> heard = h.medical.alarms();
                for (; alarmsHeard < heard.size(); alarmsHeard++) {
                    alarmedAt.computeIfAbsent(heard.get(alarmsHeard).chair(), k -> new ArrayList<>()).add(tNow);
                }
                for (ControlAgent c : h.hospital.controls()) {
                    TaskView active = c.tasks().stream().filter(t -> t.state().compareTo(TaskView.State.TO_PICKUP) >= 0
                            && t.state().compareTo(TaskView.State.UNLOADING) <= 0).findFirst().orElse(null);
                    if (active == null) {
                        quiet.remove(c.getLocalName());
                    } else {
                        var pose = c.pose();
                        double[] q = quiet.get(c.getLocalName());
                        if (q == null || Math.hypot(pose.x() - q[0], pose.y() - q[1]) > 0.5 || q[3] != active.state().ordinal()) {
                            quiet.put(c.getLocalName(), new double[] {pose.x(), pose.y(), tNow, active.state().ordinal(), 0});
                        } else if (tNow - q[2] >= 120_000 && q[4] == 0) {
                            q[4] = 1;
                            spells.add(new String[] {c.getLocalName(), Long.toString((long) q[2])});
                        }
                    }
                }
                for (ControlAgent c : h.hospital.controls()) {
                    SimChair chair = h.world.chair(c.getLocalName().substring("control-".length()));
                    double[] p = chair.powers();
                    boolean driving = c.tasks().stream().anyMatch(t -> t.state() == TaskView.State.TO_PICKUP
                            || t.state() == TaskView.State.TO_DROPOFF);
                    if (driving && p[0] == 0 && p[1] == 0) {
                        waitingChairS += 1;
                        waitingFor.merge(why(c.waitingFor()), 1 / 3600.0, Double::sum);
                    }
                }
            }
            long stalls = spells.stream().filter(sp -> {
                long from = Long.parseLong(sp[1]);
                return alarmedAt.getOrDefault(sp[0], List.of()).stream().noneMatch(a -> a >= from && a <= from + 135_000);
            }).count();
            double cpuS = (cpu.getCurrentThreadCpuTime() - cpu0) / 1e9;
            double hours = (now[0] - start) / 3.6e6;
            long[] decisions = h.hospital.traffic() == null ? new long[0] : h.hospital.traffic().decisionTimesNs();
            double[] us = new double[decisions.length];
            for (int i = 0; i < us.length; i++) {
                us[i] = decisions[i] / 1000.0;
            }
            double[] w = waitsS.stream().mapToDouble(Double::doubleValue).toArray();
            return new Outcome(map.name(), map.nodes().size(), chairs, rules, hours, counts[0], counts[1],
                    w.length == 0 ? Double.NaN : java.util.Arrays.stream(w).average().orElse(0), SerialBench.percentile(w, 95),
                    SerialBench.percentile(us, 99), h.hospital.traffic() == null ? 0 : h.hospital.traffic().decisions(),
                    waitingChairS / 3600, h.world.collisionCount(), cpuS / hours,
                    h.hospital.traffic() == null ? 0 : h.hospital.traffic().moves(),
                    h.hospital.traffic() == null ? 0 : h.hospital.traffic().deadlocks(),
                    h.hospital.traffic() == null ? 0 : h.hospital.traffic().deadlockReviewsUnbroken(), waitingFor, stalls,
                    h.medical.alarms().size(), SerialBench.percentile(pastS.stream().mapToDouble(Double::doubleValue).toArray(), 50),
                    SerialBench.percentile(pastS.stream().mapToDouble(Double::doubleValue).toArray(), 95));
        }
    }

    /** Fifty transports asked for at once of twenty chairs: how fast and how evenly they are awarded. */
    public record Burst(int chairs, int tasks, double awardSimS, double awardWallMs, long firstAuction, int minPerChair,
                        int maxPerChair, int chairsUsed, double allDoneSimS, int done, long contacts) {
    }

    /** {@code tasks} transports between random rooms asked for at once of {@code chairs} chairs on {@code map}. */
    public static Burst burst(HospitalMap map, int chairs, int tasks, long seed) {
        int[] rooms = rooms(map);
        int[] accepts = {0};
        long[] awardedWallNs = {0};
        long[] awardedSimMs = {0};
        VirtualHospital[] hh = new VirtualHospital[1];
        try (VirtualHospital h = new VirtualHospital(map, seed, FaultPlan.NONE, chairs, TrafficRules.IN_ORDER,
                MedicalAgent.Settings.standard(), line -> {
                    if (line.startsWith("medical: ACCEPT ") && ++accepts[0] == tasks) {
                        awardedWallNs[0] = System.nanoTime();
                        awardedSimMs[0] = hh[0].sim.clock().nanoTime() / 1_000_000;
                    }
                })) {
            hh[0] = h;
            if (!h.ready()) {
                throw new IllegalStateException("the planners of " + map.name() + " did not learn its doors");
            }
            SplittableRandom random = new SplittableRandom(seed);
            List<CompletableFuture<MedicalAgent.Outcome>> fs = new ArrayList<>();
            long t0Sim = h.sim.clock().nanoTime() / 1_000_000;
            long t0 = System.nanoTime();
            while (fs.size() < tasks) {
                int from = rooms[random.nextInt(rooms.length)];
                int to = rooms[random.nextInt(rooms.length)];
                if (from != to) {
                    fs.add(h.medical.transport(from, to, random.nextInt(4), 20));
                }
            }
            h.sim.runUntil(() -> fs.stream().allMatch(CompletableFuture::isDone), 6 * 3_600_000L);
            Map<String, Integer> perChair = new TreeMap<>();
            int done = 0;
            long first = 0;
            for (CompletableFuture<MedicalAgent.Outcome> f : fs) {
                if (f.isDone() && f.join().done()) {
                    done++;
                    first += f.join().auctions() == 1 ? 1 : 0;
                    perChair.merge(f.join().chair(), 1, Integer::sum);
                }
            }
            return new Burst(chairs, tasks, (awardedSimMs[0] - t0Sim) / 1000.0, (awardedWallNs[0] - t0) / 1e6, first,
                    perChair.values().stream().mapToInt(Integer::intValue).min().orElse(0),
                    perChair.values().stream().mapToInt(Integer::intValue).max().orElse(0), perChair.size(),
                    (h.sim.clock().nanoTime() / 1_000_000 - t0Sim) / 1000.0, done, h.world.collisionCount());
        }
    }

    public static String describe(Burst b) {
        return String.format(Locale.ROOT, "RESULT fleet_burst chairs=%d tasks=%d all_awarded_sim_s=%.3f all_awarded_wall_ms=%.0f "
                        + "first_auction=%d per_chair=%d..%d chairs_used=%d all_done_sim_s=%.0f done=%d contacts=%d", b.chairs(), b.tasks(),
                b.awardSimS(), b.awardWallMs(), b.firstAuction(), b.minPerChair(), b.maxPerChair(), b.chairsUsed(), b.allDoneSimS(),
                b.done(), b.contacts());
    }

    /** What a standing chair waits for, in a few words. */
    static String why(String waitsFor) {
        if (waitsFor == null) {
            return "stopped (sensors, a turn)";
        }
        if (waitsFor.startsWith("its route")) {
            return "route not granted";
        }
        if (waitsFor.startsWith("its turn")) {
            return "behind a chair";
        }
        if (waitsFor.startsWith("door")) {
            return "a door";
        }
        return waitsFor;
    }

    public static String describe(Outcome o) {
        return String.format(Locale.ROOT, "RESULT fleet map=%s nodes=%d chairs=%d rules=%s done_per_hour=%.1f failed=%d wait_mean_s=%.0f "
                        + "wait_p95_s=%.0f decision_p99_us=%.1f chair_hours_waiting=%.2f contacts=%d cpu_s_per_sim_hour=%.1f moved_aside=%d "
                        + "stalls=%d alarms=%d ride_past_estimate_median_s=%.0f ride_past_estimate_p95_s=%.0f waiting_for=%s",
                o.map(), o.nodes(), o.chairs(), o.rules(), o.donePerHour(), o.failed(), o.waitMeanS(), o.waitP95S(),
                o.decisionP99Us(), o.chairHoursWaiting(), o.contacts(), o.cpuSPerSimHour(), o.movedAside(), o.stalls(), o.alarms(),
                o.pastMedianS(), o.pastP95S(), hours(o.waitingFor()));
    }

    /** Chair-hours by reason, to two places. */
    public static String hours(Map<String, Double> byReason) {
        StringBuilder b = new StringBuilder();
        byReason.forEach((k, v) -> b.append(b.length() == 0 ? "" : ", ").append(k).append(String.format(Locale.ROOT, " %.2f", v)));
        return b.toString();
    }

    /** The series of a chart: one per map and rules, chairs to {@code value}. */
    public static Map<String, TreeMap<Integer, Double>> series(List<Outcome> outcomes, java.util.function.ToDoubleFunction<Outcome> value) {
        Map<String, TreeMap<Integer, Double>> out = new java.util.LinkedHashMap<>();
        for (Outcome o : outcomes) {
            // One line a map: the depot and single-lane variants of a shape have the same nodes as the shape.
            String name = o.nodes() + (o.map().contains("+depot") ? " + depot" : o.map().contains("+one-lane") ? " one-lane" : " nodes") + ", "
                    + (o.rules() == TrafficRules.IN_ORDER ? "in order" : "whole routes");
            out.computeIfAbsent(name, k -> new TreeMap<>()).put(o.chairs(), value.applyAsDouble(o));
        }
        return out;
    }
}
