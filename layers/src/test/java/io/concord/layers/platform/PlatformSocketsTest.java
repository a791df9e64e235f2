package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.PortRange;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

/** Twenty agents in one JVM on real UDP sockets, class 7: one platform, messaging by name, failover. */
class PlatformSocketsTest {

    /** Answers every REQUEST; completes a future on the first INFORM it gets. */
    static final class Echo extends Agent {
        final CompletableFuture<AclMessage> informed = new CompletableFuture<>();

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour() {
                @Override
                public void action() {
                    AclMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                    } else if (m.getPerformative() == Performative.REQUEST) {
                        AclMessage r = m.createReply();
                        r.setPerformative(Performative.INFORM);
                        r.setContent("echo:" + m.getContent());
                        myAgent.send(r);
                    } else if (m.getPerformative() == Performative.INFORM) {
                        informed.complete(m);
                    }
                }
            });
        }
    }

    /** Completes when the condition holds over the agents' layers, checked on the loop at every change. */
    private static CompletableFuture<Void> when(Platform p, List<AID> agents, java.util.function.Predicate<List<ContainerLayer>> cond) {
        CompletableFuture<Void> f = new CompletableFuture<>();
        p.runtime().execute(() -> {
            List<ContainerLayer> layers = new ArrayList<>();
            for (AID a : agents) {
                layers.add(Platform.containerLayer(p.runtime(), a));
            }
            Runnable check = () -> {
                if (!f.isDone() && cond.test(layers)) {
                    f.complete(null);
                }
            };
            for (ContainerLayer l : layers) {
                l.addListener(x -> check.run());
            }
            check.run();
        });
        return f;
    }

    private static boolean agreed(List<ContainerLayer> layers, int n) {
        long containers = layers.stream().filter(l -> l.role() == ContainerLayer.Role.CONTAINER).count();
        if (containers != 1) {
            return false;
        }
        ContainerLayer c = layers.stream().filter(l -> l.role() == ContainerLayer.Role.CONTAINER).findFirst().orElseThrow();
        for (ContainerLayer l : layers) {
            if (l.agents().size() != n || !List.copyOf(l.agents()).equals(List.copyOf(c.agents()))
                    || !c.containerName().equals(l.containerName())) {
                return false;
            }
        }
        return true;
    }

    @Test
    void twentyAgentsFormOnePlatformTalkByNameAndSurviveTheContainersCrash() throws Exception {
        String name = "sock" + ProcessHandle.current().pid();
        try (Platform p = Platform.builder().name(name).ports(PortRange.of(7301, 7400))
                .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(PlatformKey.random())
                        .identities(IdentityStore.ephemeral()).build()).build()) {
            List<AID> aids = new ArrayList<>();
            List<Echo> agents = new ArrayList<>();
            for (int i = 0; i < 20; i++) {
                Echo e = new Echo();
                agents.add(e);
                aids.add(p.startAgent("e" + i, e));
            }
            when(p, aids, l -> agreed(l, 20)).get(30, TimeUnit.SECONDS);

            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(AID.local("e19", name));
            m.setContent("hi");
            agents.get(0).send(m);
            assertEquals("echo:hi", agents.get(0).informed.get(30, TimeUnit.SECONDS).getContent());

            CompletableFuture<String> containerName = new CompletableFuture<>();
            p.runtime().execute(() -> containerName.complete(Platform.containerLayer(p.runtime(), aids.get(5)).containerName()));
            String old = containerName.get(10, TimeUnit.SECONDS);
            AID victim = aids.stream().filter(a -> a.name().equals(old)).findFirst().orElseThrow();
            int vi = aids.indexOf(victim);
            p.runtime().execute(() -> p.runtime().crashAgent(victim));
            aids.remove(vi);
            agents.remove(vi);
            when(p, aids, l -> agreed(l, 19) && !l.get(0).containerName().equals(old)).get(30, TimeUnit.SECONDS);

            Echo from = agents.get(agents.size() - 1);
            AclMessage again = new AclMessage(Performative.REQUEST);
            again.addReceiver(AID.local(agents.get(1).getLocalName(), name));
            again.setContent("after");
            from.send(again);
            AclMessage reply = from.informed.get(30, TimeUnit.SECONDS);
            assertEquals("echo:after", reply.getContent());
            assertNotEquals(old, reply.getSender().name());
        }
    }
}
