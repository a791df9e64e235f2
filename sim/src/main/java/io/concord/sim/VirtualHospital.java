package io.concord.sim;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.traffic.TrafficRules;
import io.concord.agents.traffic.TrafficSettings;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.layers.Platform;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;

import java.util.function.Consumer;

/**
 * A whole hospital in one JVM on the test kit's virtual clock and network, deterministic from its
 * seed: the world with its chairs at the map's first parking places, one platform (the safety
 * stack's closed profile) with the traffic agent, the doors' and the chairs' agents, and a Medical
 * agent. The demo's virtual run, the scenario tests and the fleet benchmark start it the same way.
 * Call {@link #ready()} before asking for transports (every planner knows every door).
 */
public final class VirtualHospital implements AutoCloseable {
    public final Simulation sim;
    public final AgentRuntime runtime;
    public final Platform platform;
    public final HospitalWorld world;
    public final Hospital hospital;
    public final MedicalAgent medical;

    /**
     * @param traffic the traffic agent's rules, or null for none
     * @param log     told every agent's log line
     */
    public VirtualHospital(HospitalMap map, long seed, FaultPlan plan, int chairs, TrafficRules traffic,
                           MedicalAgent.Settings medicalSettings, Consumer<String> log) {
        this(map, seed, plan, chairs, traffic == null ? null : TrafficSettings.standard().withRules(traffic), medicalSettings, log);
    }

    /** @param traffic the traffic agent's settings (its rules, the fleet monitor's limit), or null for none */
    public VirtualHospital(HospitalMap map, long seed, FaultPlan plan, int chairs, TrafficSettings traffic,
                           MedicalAgent.Settings medicalSettings, Consumer<String> log) {
        this(map, seed, plan, chairs, traffic, medicalSettings, log, ChairConfig.standard().withWatchdog(0.3),
                HospitalWorld.builder(map).seed(seed));
    }

    /**
     * @param chair every chair's model (the hospital's: {@code ChairConfig.standard().withWatchdog(0.3)})
     * @param world the world's settings, on {@code map} and {@code seed}
     */
    public VirtualHospital(HospitalMap map, long seed, FaultPlan plan, int chairs, TrafficSettings traffic,
                           MedicalAgent.Settings medicalSettings, Consumer<String> log, ChairConfig chair, HospitalWorld.Builder worldSettings) {
        if (chairs > map.parking().size()) {
            throw new IllegalArgumentException(chairs + " chairs, but " + map.name() + " parks " + map.parking().size());
        }
        sim = new Simulation(seed, plan);
        sim.platformName("hospital");
        runtime = sim.newRuntime("h1");
        platform = Platform.builder().runtime(runtime).ports(new PortRange(7001, 200, 10))
                .safetyStack(SafetyStack.builder().profile(Profile.CLOSED).build()).build();
        world = worldSettings.build();
        for (int i = 0; i < chairs; i++) {
            world.addChair("chair" + (i + 1), chair, world.poseAt(map.parking().get(i), 90));
        }
        world.attach(runtime);
        hospital = Hospital.start(platform, world, log, traffic);
        medical = new MedicalAgent(medicalSettings, log).operators(hospital.wardOperators());
        platform.startAgent("medical", medical);
    }

    /** Runs the hospital until every planner knows every door (at most a minute of its time); false if that did not happen. */
    public boolean ready() {
        return sim.runUntil(hospital::ready, 60_000);
    }

    @Override
    public void close() {
        sim.close();
    }
}
