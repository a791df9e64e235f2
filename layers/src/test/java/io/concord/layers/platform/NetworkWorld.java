package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.core.acl.AID;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.security.PlatformKey;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/** Several simulated hosts, each a runtime with a platform, on one virtual network. */
final class NetworkWorld implements AutoCloseable {
    final Simulation sim;
    final Map<String, AgentRuntime> hosts = new LinkedHashMap<>();
    final Map<String, Platform> platforms = new LinkedHashMap<>();
    /** host -> agent name -> AID */
    final Map<String, Map<String, AID>> live = new LinkedHashMap<>();
    final Profile profile;
    final List<String> violations = new ArrayList<>();

    NetworkWorld(long seed, FaultPlan plan, Profile profile) {
        this.sim = new Simulation(seed, plan);
        this.profile = profile;
        sim.platformName("net");
        sim.trace().addListener((ns, node, event, detail) -> {
            if (event.equals("platform-gal-applied") && detail.startsWith("rogue")) {
                violations.add(node + " applied a list update from " + detail);
            }
        });
    }

    void addHost(String host) {
        addHost(host, NetworkConfig.defaults());
    }

    void addHost(String host, NetworkConfig network) {
        addHost(host, network, new byte[32]);
    }

    /** A host whose agents hold the given platform key (another key: another platform). */
    void addHost(String host, NetworkConfig network, byte[] key) {
        AgentRuntime rt = sim.newRuntime(host);
        SafetyStack.Builder sb = SafetyStack.builder().profile(profile);
        if (profile != Profile.CLOSED) {
            sb.platformKey(PlatformKey.of(key));
        }
        if (profile == Profile.CLASS_7) {
            sb.identities(PlatformWorld.sharedIdentities());
        }
        Platform p = Platform.builder().runtime(rt).ports(new PortRange(7001, 100, 10)).network(network)
                .safetyStack(sb.build()).build();
        hosts.put(host, rt);
        platforms.put(host, p);
        live.put(host, new LinkedHashMap<>());
    }

    AID start(String host, String name) {
        AID aid = platforms.get(host).startAgent(name, new PlatformWorld.Idle());
        live.get(host).put(name, aid);
        return aid;
    }

    void crashAgent(String host, String name) {
        AID aid = live.get(host).remove(name);
        if (aid != null) {
            hosts.get(host).crashAgent(aid);
        }
    }

    /** Every process of the host dies. */
    void crashHost(String host) {
        sim.crash(hosts.remove(host));
        platforms.remove(host);
        live.remove(host);
    }

    ContainerLayer layer(String host, String name) {
        return Platform.containerLayer(hosts.get(host), live.get(host).get(name));
    }

    String container(String host) {
        String found = null;
        for (String n : live.get(host).keySet()) {
            if (layer(host, n).role() == Role.CONTAINER) {
                if (found != null) {
                    return null;
                }
                found = n;
            }
        }
        return found;
    }

    private static Set<String> names(java.util.Collection<AgentEntry> es) {
        Set<String> s = new TreeSet<>();
        for (AgentEntry e : es) {
            s.add(e.name());
        }
        return s;
    }

    /** One container per host; each agent's LAL is its host's live agents and its GAL every other host's. */
    boolean converged() {
        for (String h : live.keySet()) {
            if (!live.get(h).isEmpty() && container(h) == null) {
                return false;
            }
        }
        for (String h : live.keySet()) {
            Set<String> local = new TreeSet<>();
            Set<String> remote = new TreeSet<>();
            for (String other : live.keySet()) {
                for (String n : live.get(other).keySet()) {
                    (other.equals(h) ? local : remote).add(n + "@net");
                }
            }
            for (String n : live.get(h).keySet()) {
                ContainerLayer l = layer(h, n);
                Set<String> lal = names(l.agents());
                Set<String> gal = names(l.globalAgents());
                if (!lal.equals(local) || !gal.equals(remote)) {
                    return false;
                }
            }
        }
        return true;
    }

    /** No agent's GAL lists a name its LAL holds. */
    void checkDisjoint() {
        for (String h : live.keySet()) {
            for (String n : live.get(h).keySet()) {
                ContainerLayer l = layer(h, n);
                Set<String> both = names(l.agents());
                both.retainAll(names(l.globalAgents()));
                if (!both.isEmpty()) {
                    violations.add(n + " on " + h + " lists " + both + " in both its LAL and its GAL");
                }
            }
        }
    }

    String describe() {
        StringBuilder b = new StringBuilder();
        for (String h : live.keySet()) {
            for (String n : live.get(h).keySet()) {
                ContainerLayer l = layer(h, n);
                b.append(h).append('/').append(n).append(": ").append(l.role()).append(" c=").append(l.containerName())
                        .append(" lal=").append(names(l.agents())).append(" gal=").append(names(l.globalAgents()))
                        .append(" fal=").append(l.facilitators()).append('\n');
            }
        }
        return b.toString();
    }

    @Override
    public void close() {
        sim.close();
    }
}
