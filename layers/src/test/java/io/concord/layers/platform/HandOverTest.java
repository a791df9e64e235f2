package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.LoopGroup;
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

    /**
     * Two loops of one platform in this JVM, as {@code Platform.Builder.loops(2)} makes them but with
     * a mailbox of {@code mailbox}: two runtimes of one {@link LoopGroup}, a platform on each.
     */
    private static Platform[] twoLoops(int first, int mailbox) {
        String name = "hx" + first + "x" + ProcessHandle.current().pid();
        LoopGroup group = new LoopGroup();
        java.util.function.Supplier<List<io.concord.core.layer.Layer>> stack = SafetyStack.builder().profile(Profile.CLASS_7)
                .platformKey(PlatformKey.random()).identities(IdentityStore.ephemeral()).build();
        Platform[] loops = new Platform[2];
        for (int i = 0; i < 2; i++) {
            AgentRuntime rt = AgentRuntime.builder().platformName(name).group(group).mailboxCapacity(mailbox).build().start();
            loops[i] = Platform.builder().name(name).runtime(rt).ports(PortRange.of(first, first + 9)).safetyStack(stack).build();
        }
        return loops;
    }

    private static void closeAll(Platform[] ps) {
        for (int i = ps.length - 1; i >= 0; i--) {
            ps[i].close();
        }
    }

    /** Takes at most {@code perAction} messages an action; completes when it has {@code expected}. */
    private static final class Receiver extends Agent {
        final List<String> got = new ArrayList<>();
        final CompletableFuture<List<String>> done = new CompletableFuture<>();
        final int expected;
        final int perAction;
        final java.util.Set<Thread> threads = java.util.concurrent.ConcurrentHashMap.newKeySet();
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
                    threads.add(Thread.currentThread());
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

    @Test
    void messagesToAnAgentOfAnotherLoopAreHandedOverOnceAndInOrder() throws Exception {
        Platform[] loops = twoLoops(7611, 100_000);
        try {
            Receiver r = new Receiver(5_000, Integer.MAX_VALUE);
            AID ra = loops[0].startAgent("receiver", r);
            loops[1].startAgent("sender", new FastSender(AID.local("receiver", ra.platform()), 5_000, 100));
            assertEquals(numbers(5_000), r.done.get(WAIT_S, TimeUnit.SECONDS));
            assertEquals(5_000, loops[1].runtime().handedOver(), "every one handed over across the loops, none through the stacks");
            CompletableFuture<Thread> senderLoop = new CompletableFuture<>();
            loops[1].runtime().execute(() -> senderLoop.complete(Thread.currentThread()));
            assertEquals(1, r.threads.size(), "the receiver ran on one thread: " + r.threads);
            assertTrue(!r.threads.contains(senderLoop.get(WAIT_S, TimeUnit.SECONDS)), "its own loop's, not the sender's");
        } finally {
            closeAll(loops);
        }
    }

    @Test
    void aReceiverOnAnotherLoopSlowerThanItsSenderPausesItAndLosesNothing() throws Exception {
        // A mailbox of 1,000; the sender puts 200 an action, the receiver on the other loop takes 1.
        Platform[] loops = twoLoops(7621, 1_000);
        try {
            Receiver r = new Receiver(20_000, 1);
            AID ra = loops[0].startAgent("receiver", r);
            AID sa = loops[1].startAgent("sender", new FastSender(AID.local("receiver", ra.platform()), 20_000, 200));
            assertEquals(numbers(20_000), r.done.get(WAIT_S * 3, TimeUnit.SECONDS), "all, once, in order");
            assertTrue(r.maxQueued <= 1_000, "the mailbox within its capacity: " + r.maxQueued);
            assertTrue(loops[1].runtime().pauses() > 0, "the sender was paused");
            assertEquals(20_000, loops[1].runtime().handedOver(), "all across in memory");
            // (The two platforms' own frames may count a "copy": a retransmission the busy receiver's loop acked late.)
            for (String reason : List.of("mailbox-full", "flow-control", "receiver-gone")) {
                assertEquals(null, loops[0].runtime().drops(ra).get(reason), reason + " at the receiver: " + loops[0].runtime().drops(ra));
                assertEquals(null, loops[1].runtime().drops(sa).get(reason), reason + " at the sender: " + loops[1].runtime().drops(sa));
            }
        } finally {
            closeAll(loops);
        }
    }

    @Test
    void aSenderPausedForAReceiverOfAnotherLoopGoesOnWhenThatReceiverDies() throws Exception {
        Platform[] loops = twoLoops(7631, 1_000);
        try {
            Receiver r = new Receiver(Integer.MAX_VALUE, 0); // takes nothing
            AID ra = loops[0].startAgent("receiver", r);
            CompletableFuture<Void> resumed = new CompletableFuture<>();
            loops[1].startAgent("sender", new Agent() {
                int actions;

                @Override
                protected void setup() {
                    addBehaviour(new CyclicBehaviour() {
                        @Override
                        public void action() {
                            if (actions++ == 0) {
                                for (int i = 0; i < 600; i++) { // over half the receiver's mailbox: paused after
                                    send(new AclMessage(Performative.INFORM).addReceiver(AID.local("receiver", ra.platform()))
                                            .setContent("m" + i));
                                }
                            } else {
                                resumed.complete(null);
                                myAgent.removeBehaviour(this);
                            }
                        }
                    });
                }
            });
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(WAIT_S);
            while (loops[1].runtime().pauses() == 0 && System.nanoTime() < end) {
                Thread.sleep(5); // a poll with a deadline
            }
            assertEquals(1, loops[1].runtime().pauses(), "the sender paused for the receiver of the other loop");
            assertTrue(!resumed.isDone(), "and waits while the receiver holds its messages");
            loops[0].runtime().execute(() -> loops[0].runtime().crashAgent(ra));
            resumed.get(WAIT_S, TimeUnit.SECONDS); // let go when it died
        } finally {
            closeAll(loops);
        }
    }
}
