package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.layers.PlatformServices;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The yellow pages survive a flap: two JVMs on one host, the container in the first; the network
 * between them goes silent long enough for the container to drop the second JVM's agents, then
 * comes back. An agent that registered through {@link PlatformServices} registers again on its own
 * and is found; one that registered by a bare ACL request to the DF (what every agent did before)
 * is lost for good. Registering and deregistering work from {@code setup()} and {@code takeDown()}.
 */
class RegistrationFlapTest {

    /** Registers a service in its setup, through the Java API; deregisters in its takeDown. */
    static final class ApiSeller extends Agent {
        final List<String> said = new ArrayList<>();

        @Override
        protected void setup() {
            Platform.of(this).register(ServiceDescription.of("book-selling", getLocalName()));
        }

        @Override
        protected void takeDown() {
            try {
                Platform.of(this).deregister();
                said.add("deregistered");
            } catch (RuntimeException e) {
                said.add("takeDown failed: " + e);
            }
        }
    }

    /** Registers by a bare ACL request to the DF, once: nothing of it is kept by the agent. */
    static final class AclSeller extends Agent {
        @Override
        protected void setup() {
            StringBuilder b = new StringBuilder();
            Lines.appendServices(b, List.of(ServiceDescription.of("book-selling", getLocalName())));
            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(AID.local("df", getAID().platform()));
            m.setContent(Lines.content("register", Map.of("services", b.toString()), List.of()));
            send(m);
        }
    }

    /**
     * Without the port check: on one host a container now keeps an agent whose process holds its
     * port however long the network is silent (SlowNotDeadTest), so the flap is made as it still
     * happens across hosts, or to a process hung past the bound.
     */
    private static Platform platform(AgentRuntime rt) {
        return Platform.builder().runtime(rt).ports(new PortRange(7001, 50, 10)).withoutDefences(io.concord.layers.defence.Defence.PORT_CHECK)
                .safetyStack(SafetyStack.builder().profile(Profile.CLOSED).build()).network(null).build();
    }

    private static boolean found(AgentRuntime rt, AID at, String name) {
        ContainerLayer l = Platform.containerLayer(rt, at);
        return l.search(ServiceDescription.ofType("book-selling")).stream().anyMatch(e -> e.name().startsWith(name + "@"));
    }

    private static boolean listed(AgentRuntime rt, AID at, String name) {
        return Platform.containerLayer(rt, at).agents().stream().anyMatch(e -> e.name().startsWith(name + "@"));
    }

    @Test
    void aServiceRegisteredThroughTheApiSurvivesItsAgentBeingDroppedAndAddedBack() {
        try (Simulation sim = new Simulation(36, FaultPlan.NONE)) {
            sim.platformName("flap");
            AgentRuntime rt1 = sim.newRuntime("h1");
            AgentRuntime rt2 = sim.newRuntime("h1");   // a second JVM on the same host
            Platform p1 = platform(rt1);
            Platform p2 = platform(rt2);
            AID boss = p1.startAgent("boss", new PlatformWorld.Idle());
            assertTrue(sim.runUntil(() -> Platform.containerLayer(rt1, boss).role() == Role.CONTAINER, 5_000));
            ApiSeller apiSeller = new ApiSeller();
            AID api = p2.startAgent("api-seller", apiSeller);
            p2.startAgent("acl-seller", new AclSeller());
            assertTrue(sim.runUntil(() -> found(rt1, boss, "api-seller") && found(rt1, boss, "acl-seller"), 10_000),
                    "both registered");

            // The flap: nothing passes between the JVMs until the container has dropped the second's agents.
            sim.network().setFaultPlan(FaultPlan.lossy(1.0, 0, 0, 0));
            assertTrue(sim.runUntil(() -> !listed(rt1, boss, "api-seller") && !listed(rt1, boss, "acl-seller"), 20_000),
                    "the container dropped them");
            sim.network().setFaultPlan(FaultPlan.NONE);
            assertTrue(sim.runUntil(() -> listed(rt1, boss, "api-seller") && listed(rt1, boss, "acl-seller"), 20_000),
                    "and added them back");

            assertTrue(sim.runUntil(() -> found(rt1, boss, "api-seller"), 5_000), "the agent registered again on its own");
            assertTrue(Platform.containerLayer(rt2, api).registrationsResent() >= 1);
            // The same 5 s for the other one: its registration was the container's alone, and is gone.
            assertFalse(found(rt1, boss, "acl-seller"), "a registration nobody keeps is lost in a flap");

            // takeDown deregisters through the API, as JADE code does there.
            rt2.agent(api).doDelete();
            assertTrue(sim.runUntil(() -> !found(rt1, boss, "api-seller"), 5_000));
            assertEquals(List.of("deregistered"), apiSeller.said);
        }
    }

    @Test
    void aRegistrationRefusedBecauseTheAgentIsNotListedYetIsSentAgainWhenItIs() {
        try (Simulation sim = new Simulation(37, FaultPlan.NONE)) {
            sim.platformName("refused");
            AgentRuntime rt1 = sim.newRuntime("h1");
            AgentRuntime rt2 = sim.newRuntime("h1");
            Platform p1 = platform(rt1);
            Platform p2 = platform(rt2);
            AID boss = p1.startAgent("boss", new PlatformWorld.Idle());
            assertTrue(sim.runUntil(() -> Platform.containerLayer(rt1, boss).role() == Role.CONTAINER, 5_000));
            AID api = p2.startAgent("api-seller", new PlatformWorld.Idle());
            assertTrue(sim.runUntil(() -> listed(rt1, boss, "api-seller"), 10_000));
            // The container forgets the agent (as in a flap), and the agent registers at that moment.
            CompletableFuture<Void> f = new CompletableFuture<>();
            rt1.execute(() -> {
                try {
                    java.lang.reflect.Field st = ContainerLayer.class.getDeclaredField("st");
                    st.setAccessible(true);
                    ((PlatformState) st.get(Platform.containerLayer(rt1, boss))).lists.lal.remove("api-seller@refused");
                } catch (ReflectiveOperationException e) {
                    throw new AssertionError(e);
                }
            });
            rt2.execute(() -> Platform.of(rt2.agent(api)).register(ServiceDescription.of("book-selling", "late"))
                    .whenComplete((v, e) -> {
                        if (e != null) {
                            f.completeExceptionally(e);
                        } else {
                            f.complete(null);
                        }
                    }));
            assertTrue(sim.runUntil(() -> found(rt1, boss, "api-seller"), 20_000), "registered once listed again");
            assertTrue(Platform.containerLayer(rt2, api).registrationsRefused() >= 1, "it was refused first (not-registered)");
            assertTrue(sim.runUntil(f::isDone, 5_000));
            assertNull(f.join(), "the caller's future completes when the DF took it");
        }
    }
}
