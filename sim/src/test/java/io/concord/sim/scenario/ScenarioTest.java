package io.concord.sim.scenario;

import io.concord.agents.chair.Pose;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.traffic.TrafficRules;
import io.concord.core.agent.AgentRuntime;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.Platform;
import io.concord.sim.Hospital;
import io.concord.sim.VirtualHospital;
import io.concord.sim.render.HospitalPicture;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.SimChair;

import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The dissertation's scenario (7.2.6), end to end on the test kit's virtual clock and network. */
class ScenarioTest {
    static final HospitalMap MAP = HospitalMap.defaultHospital();

    /** A hospital on one simulated host: world, doors, chairs' agents, Medical agent. */
    static final class Run implements AutoCloseable {
        final Simulation sim;
        final AgentRuntime rt;
        final Platform platform;
        final HospitalWorld world;
        final Hospital hospital;
        final MedicalAgent medical;
        final List<String> log = new ArrayList<>();
        final List<String> delivered = new ArrayList<>();

        Run(long seed, FaultPlan plan, int chairs) {
            this(seed, plan, chairs, true);
        }

        Run(long seed, FaultPlan plan, int chairs, boolean traffic) {
            this(seed, plan, chairs, traffic, MedicalAgent.Settings.standard());
        }

        Run(long seed, FaultPlan plan, int chairs, boolean traffic, MedicalAgent.Settings medicalSettings) {
            this(MAP, seed, plan, chairs, traffic, medicalSettings);
        }

        /** A run on {@code map}: its chairs start at the map's first parking places. */
        Run(HospitalMap map, long seed, FaultPlan plan, int chairs, boolean traffic, MedicalAgent.Settings medicalSettings) {
            this(map, seed, plan, chairs, traffic ? TrafficRules.IN_ORDER : null, medicalSettings);
        }

        /** A run on {@code map} whose traffic agent keeps {@code rules} (none if null). */
        Run(HospitalMap map, long seed, FaultPlan plan, int chairs, TrafficRules traffic, MedicalAgent.Settings medicalSettings) {
            this(map, seed, plan, chairs, traffic == null ? null : io.concord.agents.traffic.TrafficSettings.standard().withRules(traffic),
                    medicalSettings);
        }

        /** A run on {@code map} whose traffic agent has these settings (none if null). */
        Run(HospitalMap map, long seed, FaultPlan plan, int chairs, io.concord.agents.traffic.TrafficSettings traffic,
            MedicalAgent.Settings medicalSettings) {
            VirtualHospital v = new VirtualHospital(map, seed, plan, chairs, traffic, medicalSettings, log::add);
            sim = v.sim;
            rt = v.runtime;
            platform = v.platform;
            world = v.world;
            hospital = v.hospital;
            medical = v.medical;
            sim.trace().addListener((ns, node, event, detail) -> {
                if (event.equals("deliver") && !detail.contains("from ams@") && !node.startsWith("ams")) {
                    delivered.add(node.substring(0, node.indexOf('@')) + " <- " + detail.substring(0, detail.indexOf(" conv=")));
                }
            });
            assertTrue(v.ready(), "every planner knows every door");
        }

        void writeLogs(String name) {
            try {
                java.nio.file.Files.createDirectories(Path.of("target", "scenario"));
                java.nio.file.Files.write(Path.of("target", "scenario", name + ".log"), log);
                java.nio.file.Files.write(Path.of("target", "scenario", name + ".messages"), delivered);
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        }

        @Override
        public void close() {
            sim.close();
        }
    }

    @Test
    void theChairFetchesThePatientFromNode3AndTakesThemToNode9() {
        try (Run r = new Run(2010, FaultPlan.NONE, 1)) {
            CompletableFuture<MedicalAgent.Outcome> f = r.medical.transport(3, 9, 3, 60);
            boolean ended = r.sim.runUntil(f::isDone, 600_000);
            HospitalPicture.write(r.world, Path.of("target", "pictures", "scenario.png"));
            r.writeLogs("scenario");
            assertTrue(ended, "the transport ended; log:\n" + String.join("\n", tail(r.log, 40)));
            MedicalAgent.Outcome o = f.join();
            assertTrue(o.done(), o + "\n" + String.join("\n", tail(r.log, 40)));
            SimChair c = r.world.chair("chair1");
            Pose p = c.truePose();
            assertTrue(p.distanceTo(40.5, 6) < 0.2, "at node 9: " + p);
            assertEquals(0, r.world.collisionCount(), "no collision: " + r.world.collisions());
            // Figures 6.4 and 6.3: the CFP, two plans each agreed and given, the doors' consent, the
            // proposal and its acceptance, and at the end the INFORM of the task done.
            assertInOrder(r.delivered,
                    "control-chair1 <- CFP from medical@hospital",
                    "planner-chair1 <- REQUEST from control-chair1@hospital",
                    "control-chair1 <- AGREE from planner-chair1@hospital",
                    "door-WA <- REQUEST from planner-chair1@hospital",
                    "planner-chair1 <- CONFIRM from door-WA@hospital",
                    "planner-chair1 <- CONFIRM from door-A2@hospital",
                    "control-chair1 <- INFORM-REF from planner-chair1@hospital",
                    "planner-chair1 <- REQUEST from control-chair1@hospital",
                    "control-chair1 <- AGREE from planner-chair1@hospital",
                    "planner-chair1 <- CONFIRM from door-WB@hospital",
                    "planner-chair1 <- CONFIRM from door-B7@hospital",
                    "control-chair1 <- INFORM-REF from planner-chair1@hospital",
                    "medical <- PROPOSE from control-chair1@hospital",
                    "control-chair1 <- ACCEPT-PROPOSAL from medical@hospital",
                    "door-WA <- REQUEST from control-chair1@hospital",
                    "control-chair1 <- INFORM from door-WA@hospital",
                    "door-A2 <- REQUEST from control-chair1@hospital",
                    "door-WB <- REQUEST from control-chair1@hospital",
                    "door-B7 <- REQUEST from control-chair1@hospital",
                    "medical <- INFORM from control-chair1@hospital");
            assertTrue(r.log.contains("control-chair1: at node 3: the patient gets on (60 s)"));
        }
    }

    /** The expected lines appear in this order (others may come between). */
    static void assertInOrder(List<String> actual, String... expected) {
        int i = 0;
        for (String line : actual) {
            if (i < expected.length && line.equals(expected[i])) {
                i++;
            }
        }
        assertEquals(expected.length, i, "missing, in order: '" + (i < expected.length ? expected[i] : "") + "'");
    }

    static List<String> tail(List<String> l, int n) {
        return l.subList(Math.max(0, l.size() - n), l.size());
    }
}
