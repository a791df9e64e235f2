package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
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
import java.util.function.Predicate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * Agents of one runtime on real sockets, class 7, with silence taken for death only after 400
 * maintenance periods (16 s and more): far longer than these tests wait for anything. What they see
 * happen comes from the runtime telling the platform that an agent of it left, not from a timeout.
 * Each also shows that an idle platform of one JVM needs no alive messages to stay one.
 */
class CoLocatedTest {
    private static final PlatformConfig PATIENT = new PlatformConfig(25, 3, 60, 40, 500, 400, 60, 4, 5, 3_000);
    private static final long WAIT_S = 10;

    private static Platform platform(String name, int first) {
        return Platform.builder().name(name + ProcessHandle.current().pid()).ports(PortRange.of(first, first + 9)).config(PATIENT)
                .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(PlatformKey.random())
                        .identities(IdentityStore.ephemeral()).build()).build();
    }

    private static CompletableFuture<Void> when(Platform p, List<AID> agents, Predicate<List<ContainerLayer>> cond) {
        return PlatformSocketsTest.when(p, agents, cond);
    }

    /** One container, followed by all, listing exactly {@code n} agents in every copy. */
    private static boolean agreed(List<ContainerLayer> layers, int n) {
        List<ContainerLayer> containers = layers.stream().filter(l -> l.role() == Role.CONTAINER).toList();
        if (containers.size() != 1) {
            return false;
        }
        ContainerLayer c = containers.get(0);
        for (ContainerLayer l : layers) {
            if (l.agents().size() != n || !c.containerName().equals(l.containerName())) {
                return false;
            }
        }
        return true;
    }

    private static String containerOf(Platform p, AID a) throws Exception {
        CompletableFuture<String> f = new CompletableFuture<>();
        p.runtime().execute(() -> f.complete(Platform.containerLayer(p.runtime(), a).containerName()));
        return f.get(WAIT_S, TimeUnit.SECONDS);
    }

    private static List<AID> start(Platform p, int n) {
        List<AID> aids = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            aids.add(p.startAgent("a" + i, new Agent() { }));
        }
        return aids;
    }

    /**
     * Idle, a platform of one runtime exchanges no message at all: the container sends its members
     * no alive (each reads it in memory at the end of its watch), its cycle comes rarer and rarer,
     * and nobody is taken for dead: the platform stays one, in its first term, over ten minutes of
     * the loop's clock (a manual clock, moved by the test, on real sockets).
     */
    @Test
    void anIdlePlatformOfOneRuntimeStaysOneWithoutAWord() throws Exception {
        java.util.concurrent.BlockingQueue<String> events = new java.util.concurrent.LinkedBlockingQueue<>();
        io.concord.core.time.ManualClock clock = new io.concord.core.time.ManualClock();
        io.concord.core.agent.AgentRuntime rt = io.concord.core.agent.AgentRuntime.builder().platformName("coli" + ProcessHandle.current().pid())
                .clock(clock).tracer((now, node, event, detail) -> {
                    if (event.startsWith("platform-") || event.equals("send")) {
                        events.add(node + " " + event + " " + detail);
                    }
                }).build().start();
        try (Platform p = Platform.builder().name("coli" + ProcessHandle.current().pid()).runtime(rt).ports(PortRange.of(7561, 7570))
                .network(null).safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(PlatformKey.random())
                        .identities(IdentityStore.ephemeral()).build()).build()) {
            List<AID> aids = start(p, 4);
            CompletableFuture<Void> agreed = when(p, aids, l -> agreed(l, 4));
            for (int i = 0; i < 100_000 && !agreed.isDone(); i++) {
                advance(rt, clock, 1);
            }
            agreed.get(WAIT_S, TimeUnit.SECONDS);
            String container = containerOf(p, aids.get(0));
            for (int i = 0; i < 2_000; i++) {
                advance(rt, clock, 10); // 20 s: the cycles after the start, and the lists' last confirmations
            }
            events.clear();
            for (int i = 0; i < 6_000; i++) {
                advance(rt, clock, 100);
            }
            List<String> seen = new ArrayList<>(events);
            assertEquals(List.of(), seen, "ten idle minutes");
            for (AID a : aids) {
                assertEquals(container, containerOf(p, a));
            }
            CompletableFuture<Long> term = new CompletableFuture<>();
            rt.execute(() -> term.complete(Platform.containerLayer(rt, aids.get(0)).term()));
            assertEquals(1L, term.get(WAIT_S, TimeUnit.SECONDS));
        } finally {
            rt.close();
        }
    }

    /** Moves the loop's clock on, on the loop, and waits until the loop has run once more. */
    private static void advance(io.concord.core.agent.AgentRuntime rt, io.concord.core.time.ManualClock clock, long ms) throws Exception {
        rt.execute(() -> clock.advanceMs(ms));
        CompletableFuture<Void> f = new CompletableFuture<>();
        rt.execute(() -> rt.execute(() -> f.complete(null)));
        f.get(WAIT_S, TimeUnit.SECONDS);
    }

    @Test
    void theContainersCrashIsSeenAtOnceByTheMembersOfItsRuntime() throws Exception {
        try (Platform p = platform("colo", 7521)) {
            Crash c = crashOneOfFour(p, true);
            assertFalse(containerOf(p, c.left().get(0)).equals(c.container()));
        }
    }

    @Test
    void aMembersCrashIsSeenAtOnceByTheContainerOfItsRuntime() throws Exception {
        try (Platform p = platform("colm", 7541)) {
            Crash c = crashOneOfFour(p, false);
            assertEquals(c.container(), containerOf(p, c.left().get(0)));
        }
    }

    /** The container before the crash, and the agents left. */
    private record Crash(String container, List<AID> left) {
    }

    /**
     * Four agents agree; the container (or a member) crashes; the three left agree again, within
     * the test's wait, far below the timeout.
     */
    private static Crash crashOneOfFour(Platform p, boolean theContainer) throws Exception {
        List<AID> aids = start(p, 4);
        when(p, aids, l -> agreed(l, 4)).get(WAIT_S, TimeUnit.SECONDS);
        String container = containerOf(p, aids.get(0));
        AID victim = aids.stream().filter(a -> a.name().equals(container) == theContainer).findFirst().orElseThrow();
        p.runtime().execute(() -> p.runtime().crashAgent(victim));
        aids.remove(victim);
        when(p, aids, l -> agreed(l, 3)).get(WAIT_S, TimeUnit.SECONDS);
        return new Crash(container, aids);
    }
}
