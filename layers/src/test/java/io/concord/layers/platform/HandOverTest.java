package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.layers.FlowControlTest.FastSender;
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
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Messages between agents of one runtime are handed over in memory (class 7, real sockets): every
 * one arrives once and in order without a frame; a receiver slower than its sender pauses the
 * sender and loses nothing; a message a layer acts on (here, an observation query) and one in
 * another agent's name still take the stacks.
 */
class HandOverTest {
    private static final long WAIT_S = 20;

    private static Platform platform(int first, boolean handOver, int mailbox) {
        AgentRuntime rt = AgentRuntime.builder().platformName("ho" + first + "x" + ProcessHandle.current().pid())
                .handOver(handOver).mailboxCapacity(mailbox).build().start();
        return Platform.builder().name("ho" + first + "x" + ProcessHandle.current().pid()).runtime(rt)
                .ports(PortRange.of(first, first + 9))
                .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(PlatformKey.random())
                        .identities(IdentityStore.ephemeral()).build()).build();
    }

    /** Takes at most {@code perAction} messages an action; completes when it has {@code expected}. */
    private static final class Receiver extends Agent {
        final List<String> got = new ArrayList<>();
        final CompletableFuture<List<String>> done = new CompletableFuture<>();
        final int expected;
        final int perAction;
        int maxQueued;

        Receiver(int expected, int perAction) {
            this.expected = expected;
            this.perAction = perAction;
        }

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour() {
                @Override
                public void action() {
                    maxQueued = Math.max(maxQueued, getCurQueueSize());
                    for (int i = 0; i < perAction; i++) {
                        AclMessage m = receive();
                        if (m == null) {
                            block();
                            return;
                        }
                        got.add(m.getContent());
                        if (got.size() == expected) {
                            done.complete(List.copyOf(got));
                        }
                    }
                }
            });
        }
    }

    private static List<String> numbers(int n) {
        List<String> l = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            l.add("m" + i); // as FlowControlTest.FastSender numbers them
        }
        return l;
    }

    @Test
    void messagesBetweenAgentsOfOneRuntimeAreHandedOverOnceAndInOrder() throws Exception {
        try (Platform p = platform(7581, true, 100_000)) {
            Receiver r = new Receiver(5_000, Integer.MAX_VALUE);
            AID ra = p.startAgent("receiver", r);
            p.startAgent("sender", new FastSender(AID.local("receiver", ra.platform()), 5_000, 100));
            assertEquals(numbers(5_000), r.done.get(WAIT_S, TimeUnit.SECONDS));
            assertEquals(5_000, p.runtime().handedOver(), "every one handed over, none through the stacks");
        }
    }

    @Test
    void aReceiverSlowerThanItsSenderPausesItAndLosesNothing() throws Exception {
        // A mailbox of 1,000; the sender puts 200 an action, the receiver takes 1.
        try (Platform p = platform(7591, true, 1_000)) {
            Receiver r = new Receiver(20_000, 1);
            AID ra = p.startAgent("receiver", r);
            p.startAgent("sender", new FastSender(AID.local("receiver", ra.platform()), 20_000, 200));
            assertEquals(numbers(20_000), r.done.get(WAIT_S * 3, TimeUnit.SECONDS), "all, once, in order");
            assertTrue(r.maxQueued <= 1_000, "the mailbox within its capacity: " + r.maxQueued);
            assertTrue(p.runtime().pauses() > 0, "the sender was paused");
            assertEquals(0L, p.runtime().drops(ra).values().stream().mapToLong(Long::longValue).sum(), "nothing dropped");
        }
    }

    @Test
    void aMessageALayerActsOnOrInAnothersNameTakesTheStacks() throws Exception {
        try (Platform p = platform(7601, true, 100_000)) {
            Receiver r = new Receiver(1, Integer.MAX_VALUE);
            AID ra = p.startAgent("receiver", r);
            CompletableFuture<AclMessage> dfAnswer = new CompletableFuture<>();
            AID sa = p.startAgent("asker", new Agent() {
                @Override
                protected void setup() {
                    addBehaviour(new CyclicBehaviour() {
                        @Override
                        public void action() {
                            AclMessage m = receive();
                            if (m == null) {
                                block();
                            } else {
                                dfAnswer.complete(m);
                            }
                        }
                    });
                }
            });
            PlatformSocketsTest.when(p, List.of(ra, sa), l -> l.stream().allMatch(x -> x.agents().size() == 2))
                    .get(WAIT_S, TimeUnit.SECONDS);
            long before = p.runtime().handedOver();
            p.runtime().execute(() -> {
                Agent asker = p.runtime().agent(sa);
                AclMessage forged = new AclMessage(Performative.INFORM);
                forged.setSender(AID.local("somebody", ra.platform()));
                forged.addReceiver(AID.local("receiver", ra.platform()));
                forged.setContent("forged");
                asker.send(forged);
                AclMessage status = new AclMessage(Performative.QUERY_REF);
                status.addReceiver(AID.local("receiver", ra.platform()));
                status.setOntology(io.concord.layers.observe.ObserverLayer.ONTOLOGY);
                status.setContent("status");
                asker.send(status);
            });
            AclMessage answer = dfAnswer.get(WAIT_S, TimeUnit.SECONDS);
            assertEquals(Performative.INFORM, answer.getPerformative(), "the receiver's observation layer answered the "
                    + "status query (handed over, it would have reached the agent, which answers nothing): " + answer);
            assertEquals(io.concord.layers.observe.ObserverLayer.ONTOLOGY, answer.getOntology());
            assertEquals(before, p.runtime().handedOver(), "neither was handed over");
            assertTrue(r.got.isEmpty(), "the message in another's name did not reach the receiver");
        }
    }
}
