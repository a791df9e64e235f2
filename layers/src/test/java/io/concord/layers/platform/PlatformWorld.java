package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.security.PlatformKey;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * One simulated host running a platform on the virtual network: agents started, crashed,
 * restarted and stopped at will, and the invariants of the container layer checked.
 */
final class PlatformWorld implements AutoCloseable {
    static final String HOST = "h1";
    final Simulation sim;
    final AgentRuntime rt;
    final Platform platform;
    final Map<String, AID> live = new LinkedHashMap<>();
    final Set<String> everStarted = new HashSet<>();
    final List<String> violations = new ArrayList<>();
    final List<String> log = new ArrayList<>();

    static final class Idle extends Agent {
    }

    PlatformWorld(long seed, FaultPlan plan, Profile profile) {
        sim = new Simulation(seed, plan);
        sim.platformName("sim");
        rt = sim.newRuntime(HOST);
        SafetyStack.Builder sb = SafetyStack.builder().profile(profile);
        if (profile != Profile.CLOSED) {
            sb.platformKey(PlatformKey.of(new byte[32]));
        }
        if (profile == Profile.CLASS_7) {
            sb.identities(sharedIdentities());
        }
        platform = Platform.builder().runtime(rt).ports(new PortRange(7001, 200, 10)).safetyStack(sb.build()).build();
        // Every platform message accepted must come from an agent of this platform that was started.
        sim.trace().addListener((ns, node, event, detail) -> {
            if (event.equals("platform-accept")) {
                String from = detail.substring(detail.lastIndexOf(" from ") + 6);
                String nodePlatform = node.substring(node.indexOf('@') + 1);
                boolean member = nodePlatform.equals("sim") ? everStarted.contains(from) : from.endsWith("@" + nodePlatform);
                if (!member) {
                    violations.add(node + " accepted a platform message from the non-member " + from + ": " + detail);
                }
            }
        });
    }

    private static final Map<String, io.concord.layers.security.Identity> IDS = new java.util.concurrent.ConcurrentHashMap<>();

    /** Identities kept across restarts, as the directory store does. */
    static io.concord.layers.security.IdentityStore sharedIdentities() {
        return name -> IDS.computeIfAbsent(name, n -> io.concord.layers.security.Identity.generate(new java.security.SecureRandom()));
    }

    AID start(String name) {
        everStarted.add(name + "@sim");
        AID aid = platform.startAgent(name, new Idle());
        live.put(name, aid);
        return aid;
    }

    void crash(String name) {
        AID aid = live.remove(name);
        if (aid != null) {
            rt.crashAgent(aid);
        }
    }

    void stop(String name) {
        AID aid = live.remove(name);
        if (aid != null) {
            rt.agent(aid).doDelete();
        }
    }

    ContainerLayer layer(String name) {
        return Platform.containerLayer(rt, live.get(name));
    }

    List<String> containers() {
        List<String> out = new ArrayList<>();
        for (String n : live.keySet()) {
            ContainerLayer c = layer(n);
            if (c != null && c.role() == Role.CONTAINER) {
                out.add(n);
            }
        }
        return out;
    }

    /** True when there is exactly one container and every live agent holds its list, which lists exactly the live agents. */
    boolean converged() {
        List<String> cs = containers();
        if (cs.size() != 1) {
            return false;
        }
        ContainerLayer c = layer(cs.get(0));
        Set<String> expected = new TreeSet<>();
        for (String n : live.keySet()) {
            expected.add(n + "@sim");
        }
        Set<String> listed = new TreeSet<>();
        for (AgentEntry e : c.agents()) {
            listed.add(e.name());
        }
        if (!listed.equals(expected)) {
            return false;
        }
        List<AgentEntry> reference = List.copyOf(c.agents());
        for (String n : live.keySet()) {
            ContainerLayer l = layer(n);
            if (l == null || !List.copyOf(l.agents()).equals(reference) || !cs.get(0).concat("@sim").equals(l.containerName())) {
                return false;
            }
        }
        return true;
    }

    String describe() {
        StringBuilder b = new StringBuilder();
        for (String n : live.keySet()) {
            ContainerLayer l = layer(n);
            b.append(n).append(':').append(l == null ? "?" : l.role() + " c=" + l.containerName() + " t=" + l.term()
                    + " s=" + l.lalSequence() + " n=" + l.agents().size()).append('\n');
        }
        return b.toString();
    }

    @Override
    public void close() {
        sim.close();
    }
}
