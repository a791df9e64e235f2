package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.testkit.EchoAgent;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
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
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Twenty agents in one JVM on real UDP sockets, class 7: one platform, messaging by name, failover. */
class PlatformSocketsTest {

    /** Answers every REQUEST; completes a future on the first INFORM it gets. */
    static final class Echo extends EchoAgent {
        final CompletableFuture<AclMessage> informed;

        Echo() {
            this(new CompletableFuture<>());
        }

        private Echo(CompletableFuture<AclMessage> informed) {
            super("echo:", m -> {
                if (m.getPerformative() == Performative.INFORM) {
                    informed.complete(m);
                }
            });
            this.informed = informed;
        }
    }

    /** Completes when the condition holds over the agents' layers, checked on the loop at every change. */
    static CompletableFuture<Void> when(Platform p, List<AID> agents, java.util.function.Predicate<List<ContainerLayer>> cond) {
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
        long containers = layers.stream().filter(l -> l.role() == Role.CONTAINER).count();
        if (containers != 1) {
            return false;
        }
        ContainerLayer c = layers.stream().filter(l -> l.role() == Role.CONTAINER).findFirst().orElseThrow();
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

    @Test
    void twoPlatformsWithTheirOwnKeysShareAPortRangeAndStayApart() throws Exception {
        long pid = ProcessHandle.current().pid();
        PortRange range = PortRange.of(7461, 7480);
        try (Platform a = Platform.builder().name("one" + pid).ports(range)
                .safetyStack(SafetyStack.builder().profile(Profile.CLASS_3).platformKey(PlatformKey.random()).build()).build();
             Platform b = Platform.builder().name("two" + pid).ports(range)
                     .safetyStack(SafetyStack.builder().profile(Profile.CLASS_3).platformKey(PlatformKey.random()).build()).build()) {
            List<AID> inA = new ArrayList<>();
            List<AID> inB = new ArrayList<>();
            for (int i = 0; i < 3; i++) {
                // Interleaved: each platform's agents hold ports between the other's.
                inA.add(a.startAgent("x" + i, new Echo()));
                inB.add(b.startAgent("y" + i, new Echo()));
            }
            when(a, inA, l -> agreed(l, 3)).get(30, TimeUnit.SECONDS);
            when(b, inB, l -> agreed(l, 3)).get(30, TimeUnit.SECONDS);
            CompletableFuture<List<String>> namesInA = new CompletableFuture<>();
            a.runtime().execute(() -> namesInA.complete(Platform.containerLayer(a.runtime(), inA.get(0)).agents().stream()
                    .map(AgentEntry::name).toList()));
            assertEquals(List.of("x0@one" + pid, "x1@one" + pid, "x2@one" + pid), namesInA.get(10, TimeUnit.SECONDS));
            // The other platform's frames were skipped as another key's (or, when the two random keys
            // share an id, 1 in 32, failed authentication), counted, never accepted.
            CompletableFuture<Long> refused = new CompletableFuture<>();
            a.runtime().execute(() -> refused.complete(a.runtime().drops().getOrDefault("foreign-key", 0L)
                    + a.runtime().drops().getOrDefault("bad-tag", 0L)));
            assertTrue(refused.get(10, TimeUnit.SECONDS) > 0);
        }
    }
}
