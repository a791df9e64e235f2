package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.testkit.FaultPlan;
import io.concord.layers.Profile;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Network discovery in deterministic simulation: 2 to 4 hosts with their own containers on one
 * virtual network; loss, duplication, reordering; partitions that heal, links that go down and up,
 * a host's container crashing, a whole host crashing and coming back, and a forger sending list
 * updates without the secret. After quiet time: every agent's LAL holds its host's live agents and
 * its GAL every other host's, so every live agent resolves every live agent by name; no GAL lists
 * an agent of the LAL; no update without the right secret was ever applied.
 */
class NetworkSimulationTest {
    /** The trace hash of the last scenario that converged (test thread only). */
    static long lastTraceHash;

    @Test
    void manySeedsConverge() {
        int seeds = Integer.getInteger("concord.net.seeds", 300);
        long first = Long.getLong("concord.net.seed", 1);
        List<String> failures = new ArrayList<>();
        for (long seed = first; seed < first + seeds && failures.size() < 3; seed++) {
            String f = scenario(seed);
            if (f != null) {
                failures.add("seed " + seed + ": " + f);
            }
        }
        assertTrue(failures.isEmpty(), "failing seeds (replay with -Dconcord.net.seed=N -Dconcord.net.seeds=1):\n"
                + String.join("\n", failures));
    }

    /**
     * Once the hosts agree, a change of one host's list reaches the other hosts' agents as that
     * change (a gal-delta of the agents added, or removed), not as the whole list again: the whole
     * list at every change cost N agents times N entries, and ran a simulated network of 2,000
     * agents out of memory. (A member that misses a change is sent the whole list when its
     * confirmation shows it behind: manySeedsConverge runs that under loss.)
     */
    @Test
    void aChangeOfOneHostsListReachesTheOthersAsThatChange() {
        try (NetworkWorld w = new NetworkWorld(5, FaultPlan.NONE, Profile.CLASS_3)) {
            java.util.Map<String, Integer> accepted = accepted(w, "h2", "gal");
            for (String h : List.of("h1", "h2", "h3")) {
                w.addHost(h);
                // (A change of more than half the list goes whole: h1 is the larger host.)
                for (int i = 0; i < (h.equals("h1") ? 10 : 4); i++) {
                    w.start(h, h + "a" + i);
                }
            }
            settle(w);
            accepted.clear();
            w.start("h1", "h1new");
            settle(w);
            assertEquals(java.util.Map.of("delta", 3), accepted, "each of h2's three members got the one new entry as a change (its container makes the list)");
            accepted.clear();
            w.crashHost("h3");
            settle(w);
            assertEquals(java.util.Map.of("delta", 3), accepted, "and the lost host's agents as a removal");
        }
    }

    /**
     * The same for a host's own list: once its agents agree, a newcomer is sent the whole LAL and
     * every other member only the new entry (a lal-delta), and an agent's loss reaches the members
     * as a removal. The whole LAL at every change cost N members times N entries while N agents
     * joined one by one: 1,000 agents in one JVM took 77 s to converge.
     */
    @Test
    void aChangeOfAHostsOwnListReachesItsMembersAsThatChange() {
        try (NetworkWorld w = new NetworkWorld(6, FaultPlan.NONE, Profile.CLASS_3)) {
            java.util.Map<String, Integer> accepted = accepted(w, "", "lal");
            w.addHost("h1");
            for (int i = 0; i < 10; i++) {
                w.start("h1", "a" + i);
            }
            settle(w);
            accepted.clear();
            w.start("h1", "anew");
            settle(w);
            assertEquals(java.util.Map.of("delta", 9, "whole", 1), accepted,
                    "the nine members that held the list got the one new entry; the newcomer the whole list");
            accepted.clear();
            String victim = w.container("h1").equals("a3") ? "a4" : "a3";
            w.crashAgent("h1", victim);
            settle(w);
            assertEquals(java.util.Map.of("delta", 9), accepted, "and a lost agent as a removal");
        }
    }

    /** Runs until the hosts agree, and a second more for what is still on its way. */
    private static void settle(NetworkWorld w) {
        assertTrue(w.sim.runUntil(w::converged, 30_000), w::describe);
        w.sim.runFor(1_000);
    }

    /**
     * Counts, by "whole" and "delta", the lists ({@code list}, {@code list-delta}) accepted by the
     * agents whose names start with {@code nodes}.
     */
    private static java.util.Map<String, Integer> accepted(NetworkWorld w, String nodes, String list) {
        java.util.Map<String, Integer> accepted = new java.util.TreeMap<>();
        w.sim.trace().addListener((ns, node, event, detail) -> {
            if (event.equals("platform-accept") && node.startsWith(nodes)
                    && (detail.contains(" " + list + "-delta ") || detail.contains(" " + list + " "))) {
                accepted.merge(detail.contains(" " + list + "-delta ") ? "delta" : "whole", 1, Integer::sum);
            }
        });
        return accepted;
    }

    static String scenario(long seed) {
        SplittableRandom r = new SplittableRandom(seed * 0x9E3779B97F4A7C15L + 1);
        int hosts = 2 + r.nextInt(3);
        Profile profile = seed % 20 == 0 ? Profile.CLASS_7 : seed % 5 == 2 ? Profile.CLASS_3 : Profile.CLOSED;
        FaultPlan plan = FaultPlan.lossy(r.nextDouble() * 0.1, r.nextDouble() * 0.1, r.nextDouble() * 0.1, 0)
                .withLatency(100_000 + r.nextInt(3_000_000), r.nextInt(1_000_000));
        try (NetworkWorld w = new NetworkWorld(seed, plan, profile)) {
            List<String> log = new ArrayList<>();
            for (int h = 1; h <= hosts; h++) {
                w.addHost("h" + h);
                int n = 1 + r.nextInt(5);
                for (int i = 0; i < n; i++) {
                    w.start("h" + h, "h" + h + "a" + i);
                }
            }
            int events = r.nextInt(5);
            int restarts = 0;
            for (int e = 0; e < events; e++) {
                w.sim.runFor(200 + r.nextInt(2_000));
                List<String> hs = new ArrayList<>(w.live.keySet());
                String h = hs.get(r.nextInt(hs.size()));
                switch (r.nextInt(5)) {
                    case 0 -> {
                        String other = hs.get(r.nextInt(hs.size()));
                        if (!other.equals(h)) {
                            w.sim.network().partition(h, other);
                            log.add("partition " + h + "|" + other);
                            w.sim.runFor(500 + r.nextInt(3_000));
                            w.sim.network().healAll();
                            log.add("heal");
                        }
                    }
                    case 1 -> {
                        w.sim.network().setHostDown(h, true);
                        log.add("down " + h);
                        w.sim.runFor(500 + r.nextInt(3_000));
                        w.sim.network().setHostDown(h, false);
                        log.add("up " + h);
                    }
                    case 2 -> {
                        String c = w.container(h);
                        if (c != null && w.live.get(h).size() > 1) {
                            w.crashAgent(h, c);
                            log.add("crash container " + c);
                        }
                    }
                    case 3 -> {
                        if (w.live.size() > 2) {
                            w.crashHost(h);
                            log.add("crash host " + h);
                            String back = "h" + (hosts + (++restarts));
                            w.addHost(back);
                            w.start(back, back + "a0");
                            w.start(back, back + "a1");
                            log.add("new host " + back);
                        }
                    }
                    default -> {
                        forge(w, h);
                        log.add("forged update to " + h);
                    }
                }
            }
            w.sim.network().setFaultPlan(FaultPlan.NONE);
            if (!w.sim.runUntil(w::converged, 8_000)) {
                return "no convergence (" + hosts + " hosts, " + profile + ", " + log + "):\n" + w.describe();
            }
            w.checkDisjoint();
            if (!w.violations.isEmpty()) {
                return w.violations.get(0);
            }
            // The seed's trace hash, kept in the surefire report: a refactoring that must not
            // change behaviour leaves every seed's hash as it was.
            lastTraceHash = w.sim.trace().hash();
            System.out.printf("seed %d trace %016x%n", seed, lastTraceHash);
            return null;
        }
    }

    /** A platform member with the key but not the secret sends list updates to a host's container. */
    private static void forge(NetworkWorld w, String host) {
        String c = w.container(host);
        if (c == null) {
            return;
        }
        String other = w.live.keySet().stream().filter(x -> !x.equals(host)).findFirst().orElse(null);
        if (other == null || w.live.get(other).isEmpty()) {
            return;
        }
        AID rogue = w.start(other, "rogue" + w.sim.clock().nanoTime());
        AclMessage m = new AclMessage(Performative.INFORM_REF);
        m.addReceiver(w.live.get(host).get(c)); // with its address: the rogue has not joined yet
        m.setOntology("concord-platform");
        m.setProtocol(Protocol.P_NETWORK);
        m.setContent("gal-update secret=00000000000000000000000000000000 term=99 seq=99 page=0 pages=1\n"
                + "ghost@net udp://h9:7001 1 -");
        w.hosts.get(other).agent(rogue).send(m);
        w.sim.runFor(50);
        w.crashAgent(other, rogue.localName());
    }

    @Test
    void anUpdateWithoutTheSecretIsDiscardedAndCounted() {
        try (NetworkWorld w = new NetworkWorld(3, FaultPlan.NONE, Profile.CLOSED)) {
            w.addHost("h1");
            w.addHost("h2");
            w.start("h1", "x");
            w.start("h2", "y");
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            forge(w, "h1");
            w.sim.runFor(1_000);
            assertTrue(w.hosts.get("h1").drops().getOrDefault("bad-secret", 0L) > 0, w.hosts.get("h1").drops().toString());
            assertTrue(w.violations.isEmpty(), w.violations.toString());
            assertTrue(w.converged(), w.describe());
            assertEquals(List.of("y@net"), w.layer("h1", "x").globalAgents().stream().map(AgentEntry::name).toList());
        }
    }

    @Test
    void byNameAndThroughTheDfAcrossHostsAndAfterAHostsContainerChanges() {
        try (NetworkWorld w = new NetworkWorld(5, FaultPlan.lossy(0.05, 0.05, 0.05, 0), Profile.CLASS_7)) {
            w.addHost("h1");
            w.addHost("h2");
            w.addHost("h3");
            w.start("h1", "buyer");
            PlatformServicesTest.Inbox seller = new PlatformServicesTest.Inbox();
            w.live.get("h2").put("seller", w.platforms.get("h2").startAgent("seller", seller));
            w.start("h2", "other");
            w.start("h3", "third");
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());

            var sellerAgent = w.hosts.get("h2").agent(w.live.get("h2").get("seller"));
            var reg = Platform.of(sellerAgent).register(ServiceDescription.of("book-selling", "dune"));
            assertTrue(w.sim.runUntil(reg::isDone, 5_000));
            var buyer = w.hosts.get("h1").agent(w.live.get("h1").get("buyer"));
            assertTrue(w.sim.runUntil(() -> !Platform.of(buyer).searchCopy(ServiceDescription.ofType("book-selling")).isEmpty(), 5_000),
                    "the DF search on h1 does not find the service registered on h2");
            var atDf = Platform.of(buyer).searchAtDf(ServiceDescription.ofType("book-selling"));
            assertTrue(w.sim.runUntil(atDf::isDone, 5_000));
            assertEquals(List.of("seller@net"), atDf.join().stream().map(AgentEntry::name).toList());

            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(AID.local("seller", "net"));
            m.setContent("across");
            buyer.send(m);
            assertTrue(w.sim.runUntil(() -> !seller.got.isEmpty(), 5_000));
            assertEquals("buyer@net", seller.got.get(0).getSender().name());

            // h2's container dies: h2 re-joins under its new container; the others drop the old one.
            String old = w.container("h2");
            w.crashAgent("h2", old);
            assertTrue(w.sim.runUntil(w::converged, 10_000), w.describe());
            assertEquals(List.of(w.container("h2") + "@net"), w.layer("h3", "third").facilitators().stream()
                    .filter(f -> f.startsWith("seller") || f.startsWith("other")).toList());
        }
    }

    @Test
    void withoutBroadcastSeedsConnectTheHostsAndTheyLearnOfEachOtherThroughThem() {
        try (NetworkWorld w = new NetworkWorld(8, FaultPlan.lossy(0.05, 0, 0, 0), Profile.CLOSED)) {
            NetworkConfig unicast = NetworkConfig.defaults().withBroadcast(false);
            w.addHost("h1", unicast);
            for (int h = 2; h <= 4; h++) {
                w.addHost("h" + h, unicast.withSeeds(List.of("h1:7000")));
            }
            for (int h = 1; h <= 4; h++) {
                w.start("h" + h, "h" + h + "a");
                w.start("h" + h, "h" + h + "b");
            }
            assertTrue(w.sim.runUntil(w::converged, 10_000), w.describe());
            // h4 was seeded with h1 only; it reached h2 and h3 through what h1 knew.
            assertEquals(3, w.layer("h4", "h4a").facilitators().size() + w.layer("h4", "h4b").facilitators().size());
        }
    }

    @Test
    void announcementsUnderAnotherKeyAreDroppedAndCountedAndNeverMakeAFacilitator() {
        try (NetworkWorld w = new NetworkWorld(12, FaultPlan.NONE, Profile.CLASS_3)) {
            w.addHost("h1");
            w.addHost("h2");
            byte[] other = new byte[32];
            other[0] = 1;
            w.addHost("intruder", NetworkConfig.defaults(), other);
            w.start("h1", "a");
            w.start("h2", "b");
            w.start("intruder", "x");
            // The intruder's host is not part of the platform: only h1 and h2 must agree.
            w.live.remove("intruder");
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            w.sim.runFor(2_000);
            assertTrue(w.converged(), w.describe());
            assertEquals(List.of("b@net"), w.layer("h1", "a").globalAgents().stream().map(AgentEntry::name).toList());
            // Another key's id: skipped as another platform's frames before any tag is computed.
            assertTrue(w.hosts.get("h1").drops().getOrDefault("foreign-key", 0L) > 0, w.hosts.get("h1").drops().toString());
            assertEquals(List.of("b@net"), w.layer("h1", "a").facilitators());
        }
    }
}
