package io.concord.layers.platform;

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
        List<ContainerLayer> containers = layers.stream().filter(l -> l.role() == ContainerLayer.Role.CONTAINER).toList();
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
     * Idle, the container sends its members in this runtime an alive only every
     * {@link ContainerRole#LOCAL_ALIVE_EVERY} periods, then rarer (see ContainerRulesTest), and with
     * the default timeouts nobody is taken for dead meanwhile: the platform stays one, in its first
     * term, over three such alives.
     */
    @Test
    void anIdlePlatformOfOneRuntimeStaysOneBetweenItsRareAlives() throws Exception {
        java.util.concurrent.BlockingQueue<String> events = new java.util.concurrent.LinkedBlockingQueue<>();
        io.concord.core.agent.AgentRuntime rt = io.concord.core.agent.AgentRuntime.builder().platformName("coli" + ProcessHandle.current().pid())
                .tracer((now, node, event, detail) -> {
                    if (event.startsWith("platform-") || event.equals("send") && detail.toLowerCase(java.util.Locale.ROOT).startsWith("inform ")) {
                        events.add(node + " " + event + " " + detail);
                    }
                }).build().start();
        try (Platform p = Platform.builder().name("coli" + ProcessHandle.current().pid()).runtime(rt).ports(PortRange.of(7561, 7570))
                .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(PlatformKey.random())
                        .identities(IdentityStore.ephemeral()).build()).build()) {
            List<AID> aids = start(p, 4);
            when(p, aids, l -> agreed(l, 4)).get(WAIT_S, TimeUnit.SECONDS);
            String container = containerOf(p, aids.get(0));
            String member = aids.stream().map(AID::name).filter(n -> !n.equals(container)).findFirst().orElseThrow();
            events.clear();
            int alives = 0;
            String changed = null;
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (alives < 3 && changed == null && System.nanoTime() < deadline) {
                String e = events.poll(1, TimeUnit.SECONDS);
                if (e == null) {
                    continue;
                }
                if (e.toLowerCase(java.util.Locale.ROOT).startsWith(container.toLowerCase(java.util.Locale.ROOT) + " send inform from ") && e.endsWith(" to " + member)) {
                    alives++;
                } else if (java.util.regex.Pattern.compile(" platform-(container|member|failover|removed|rejoin|registered|yield|join-failed|distribute) ")
                        .matcher(e).find()) {
                    changed = e;
                }
            }
            assertEquals(null, changed, "the platform changed while idle");
            assertEquals(3, alives);
            assertEquals(container, containerOf(p, aids.get(1)));
        } finally {
            rt.close();
        }
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
