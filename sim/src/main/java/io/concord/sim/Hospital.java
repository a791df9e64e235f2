package io.concord.sim;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.control.ControlAgent;
import io.concord.agents.door.DoorAgent;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.plan.PlannerAgent;
import io.concord.agents.traffic.TrafficAgent;
import io.concord.agents.traffic.TrafficRules;
import io.concord.agents.traffic.TrafficSettings;
import io.concord.layers.Platform;
import io.concord.layers.authority.Operator;
import io.concord.layers.authority.OperatorKey;
import io.concord.layers.authority.Operators;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.SimChair;
import io.concord.sim.world.WorldDoor;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

/**
 * The hospital's agents on a platform: the traffic agent ({@code traffic}), a door agent for every
 * door of the world ({@code door-<id>}), and for every chair a planner ({@code planner-<chair>})
 * and a control agent ({@code control-<chair>}). The Medical agent runs wherever the staff are, on
 * any runtime of the same platform.
 */
public final class Hospital {
    private TrafficAgent traffic;
    private final Map<String, DoorAgent> doors = new LinkedHashMap<>();
    private final Map<String, PlannerAgent> planners = new LinkedHashMap<>();
    private final Map<String, ControlAgent> controls = new LinkedHashMap<>();
    /** The console's operator key: the ward's operators are this one and {@link #operators}'s. */
    private volatile OperatorKey operatorKey = OperatorKey.generate("an operator at the console");
    private volatile List<Operator> operators = List.of();

    private Hospital() {
    }

    /**
     * The operator key the console of this ward signs with (a held chair's resume), which every
     * control agent of the ward trusts; by default one made for this run, held in memory only (the
     * console of this process is then the only operator). The demo's is {@code --operator-key file}.
     */
    public Hospital operatorKey(OperatorKey key) {
        this.operatorKey = java.util.Objects.requireNonNull(key, "key");
        trust();
        return this;
    }

    /** The console's operator key ({@link #operatorKey(OperatorKey)}). */
    public OperatorKey operatorKey() {
        return operatorKey;
    }

    /** Other operators the ward's control agents trust, beside the console's key (their orders come by {@code resume-request}). */
    public Hospital operators(List<Operator> others) {
        this.operators = List.copyOf(others);
        trust();
        return this;
    }

    private void trust() {
        for (ControlAgent a : controls.values()) {
            a.operators(wardOperators());
        }
    }

    /**
     * The operators this ward's control agents trust (the console's key and {@link #operators(List)}):
     * give them to the Medical agent ({@code MedicalAgent.operators}) so that an operator's signed
     * cancel withdraws any transport.
     */
    public Operators wardOperators() {
        List<Operator> all = new ArrayList<>(operators);
        all.add(operatorKey.operator());
        return Operators.of(all);
    }

    /** Starts the traffic agent, the door agents and every chair's agents on the platform. */
    public static Hospital start(Platform platform, HospitalWorld world, Consumer<String> log) {
        return start(platform, world, log, true);
    }

    /**
     * As {@link #start(Platform, HospitalWorld, Consumer)}; with {@code traffic} false there is no
     * traffic agent, and chairs keep apart by their range sensors alone (for one chair, or to show
     * what the traffic agent does).
     */
    public static Hospital start(Platform platform, HospitalWorld world, Consumer<String> log, boolean traffic) {
        return start(platform, world, log, traffic ? TrafficRules.IN_ORDER : null);
    }

    /**
     * As {@link #start(Platform, HospitalWorld, Consumer)}, with a traffic agent keeping these rules
     * ({@link TrafficRules#WHOLE_ROUTES} to compare with in the benchmark), or none if null.
     */
    public static Hospital start(Platform platform, HospitalWorld world, Consumer<String> log, TrafficRules rules) {
        return start(platform, world, log, rules == null ? null : TrafficSettings.standard().withRules(rules));
    }

    /** As {@link #start(Platform, HospitalWorld, Consumer)}, with a traffic agent of these settings, or none if null. */
    public static Hospital start(Platform platform, HospitalWorld world, Consumer<String> log, TrafficSettings traffic) {
        Hospital h = new Hospital();
        if (traffic != null) {
            h.traffic = new TrafficAgent(world.map(), log, traffic);
            platform.startAgent("traffic", h.traffic);
        }
        for (WorldDoor d : world.doors()) {
            DoorAgent a = new DoorAgent(d, DoorAgent.Settings.standard(), log);
            platform.startAgent("door-" + d.id(), a);
            h.doors.put(d.id(), a);
        }
        for (SimChair c : world.chairs()) {
            h.addChair(platform, world, c, log);
        }
        return h;
    }

    /** Starts the planner and the control agent of a chair of the world. */
    public void addChair(Platform platform, HospitalWorld world, SimChair c, Consumer<String> log) {
        addChair(platform, world.map(), c, log);
    }

    /**
     * Starts the planner and the control agent of any chair: a simulated one, or a real or
     * emulated one over its serial link ({@code io.concord.serial.SerialChair}).
     */
    public void addChair(Platform platform, HospitalMap map, ChairDriver c,
                         Consumer<String> log) {
        PlannerAgent p = new PlannerAgent(map, c.name(), log);
        platform.startAgent("planner-" + c.name(), p);
        planners.put(c.name(), p);
        ControlAgent a = new ControlAgent(c, map, log);
        a.operators(wardOperators());
        platform.startAgent("control-" + c.name(), a);
        controls.put(c.name(), a);
    }

    /** The traffic agent, or null if started without one. */
    public TrafficAgent traffic() {
        return traffic;
    }

    /** The door agent of a door. */
    public DoorAgent door(String id) {
        return doors.get(id);
    }

    /** The planner of a chair. */
    public PlannerAgent planner(String chair) {
        return planners.get(chair);
    }

    /** The control agent of a chair. */
    public ControlAgent control(String chair) {
        return controls.get(chair);
    }

    /** Every control agent. */
    public List<ControlAgent> controls() {
        return new ArrayList<>(controls.values());
    }

    /** True once every planner knows every door (the yellow pages have spread). */
    public boolean ready() {
        for (PlannerAgent p : planners.values()) {
            if (p.knownDoors().size() < doors.size() || p.knownDoors().stream().anyMatch(k -> k.state().equals("unknown"))) {
                return false;
            }
        }
        return true;
    }
}
