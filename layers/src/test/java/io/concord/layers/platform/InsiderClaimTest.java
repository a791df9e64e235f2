package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.defence.Defence;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.frame.Frames;
import io.concord.layers.security.PlatformKey;
import org.junit.jupiter.api.Test;
import org.opentest4j.AssertionFailedError;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A key holder (the platform key and an identity of its own, not in the platform's lists) claims
 * container with a term far above the platform's, in frames "for any agent" written to every
 * agent's port: the container stays, the term stays, and the agents' messages keep arriving.
 * Without the claim check (each agent's own word counts only sealed to it), the same frames make
 * the container yield to a container that never answers.
 */
class InsiderClaimTest {

    static final class Counting extends Agent {
        final List<String> got = Collections.synchronizedList(new ArrayList<>());

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    AclMessage m = receive();
                    if (m == null) {
                        block();
                    } else {
                        got.add(m.getContent());
                    }
                }
            });
        }
    }

    static final class Puppet extends Agent {
    }

    @Test
    void aKeyHoldersClaimOfAHigherTermSplitsNothing() {
        run(new Defence[0]);
        AssertionFailedError e = assertThrows(AssertionFailedError.class, () -> run(Defence.CLAIM_CHECK),
                "without the claim check the key holder's claim reaches the agents");
        assertTrue(e.getMessage().startsWith("the same container"), e.getMessage());
    }

    private static void run(Defence... off) {
        try (Simulation sim = new Simulation(11, FaultPlan.NONE).platformName("sim")) {
            PlatformKey key = PlatformKey.of(new byte[32]);
            AgentRuntime h1 = sim.newRuntime("h1");
            AgentRuntime h2 = sim.newRuntime("h1"); // a second process on the same host
            Platform p1 = Platform.builder().runtime(h1).ports(new PortRange(7001, 20, 10)).withoutDefences(off)
                    .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(key)
                            .identities(PlatformWorld.sharedIdentities()).withoutDefences(off).build()).build();
            Platform p2 = Platform.builder().runtime(h2).ports(new PortRange(7001, 20, 10)).withoutDefences(off)
                    .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(key)
                            .identities(PlatformWorld.sharedIdentities()).withoutDefences(off).build()).build();
            p1.startAgent("c", new Puppet());
            sim.runFor(500);
            AID a = p1.startAgent("a", new Puppet());
            Counting counting = new Counting();
            AID b = p2.startAgent("b", counting);
            assertTrue(sim.runUntil(() -> agreed(h1, h2, a, b), 30_000), "the platform converges first");
            ContainerLayer la = Platform.containerLayer(h1, a);
            String container = la.containerName();
            long term = la.term();

            // The key holder: the platform key, a stack of its own, no container layer, not listed.
            AgentRuntime m = sim.newRuntime("hm", SafetyStack.builder().profile(Profile.CLASS_7).platformKey(key)
                    .identities(PlatformWorld.sharedIdentities()).build());
            Puppet x = new Puppet();
            AID xAid = m.startAgent("x", x);
            AgentEntry claimant = new AgentEntry(xAid.name(), xAid.addresses().get(0), 0, List.of());
            List<AID> targets = new ArrayList<>();
            String at = a.addresses().get(0);
            String hostPart = at.substring(0, at.lastIndexOf(':') + 1);
            for (int port = 7001; port < 7021; port++) {
                targets.add(new AID(Frames.ANY_LOCAL_NAME + "@sim", hostPart + port));
            }
            for (int round = 0; round < 5; round++) {
                m.execute(() -> {
                    for (AID t : targets) {
                        AclMessage claim = new AclMessage(Performative.INFORM).addReceiver(t);
                        claim.setOntology(Protocol.ONTOLOGY);
                        claim.setLanguage(Protocol.LANGUAGE);
                        claim.setProtocol(Protocol.P_DISCOVERY);
                        claim.setContent(new PlatformMessage.ContainerIs(term + 1_000, claimant, claimant).encode());
                        x.send(claim);
                    }
                });
                sim.runFor(200);
            }
            Agent sender = h1.agent(a);
            for (int i = 0; i < 20; i++) {
                String c = "m" + i;
                h1.execute(() -> sender.send(new AclMessage(Performative.INFORM).addReceiver(b).setContent(c)));
            }
            sim.runUntil(() -> counting.got.size() >= 20, 5_000);
            sim.runFor(1_000);
            ContainerLayer lb = Platform.containerLayer(h2, b);
            assertEquals(container + " t=" + term, la.containerName() + " t=" + la.term(),
                    "the same container of the same term, for a: " + la.role());
            assertEquals(container + " t=" + term, lb.containerName() + " t=" + lb.term(),
                    "the same container of the same term, for b");
            assertEquals(20, counting.got.size(), "a's messages reach b: " + counting.got);
        }
    }

    private static boolean agreed(AgentRuntime h1, AgentRuntime h2, AID a, AID b) {
        ContainerLayer la = Platform.containerLayer(h1, a);
        ContainerLayer lb = Platform.containerLayer(h2, b);
        return la != null && lb != null && la.containerName() != null && la.containerName().equals(lb.containerName())
                && la.agents().size() == 3 && lb.agents().size() == 3;
    }
}
