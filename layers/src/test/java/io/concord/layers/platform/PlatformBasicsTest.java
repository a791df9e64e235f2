package io.concord.layers.platform;

import io.concord.layers.Platform;
import io.concord.testkit.FaultPlan;
import io.concord.layers.Profile;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class PlatformBasicsTest {

    @Test
    void tenAgentsStartedAtOnceAgreeOnOneContainer() {
        try (PlatformWorld w = new PlatformWorld(1, FaultPlan.NONE, Profile.CLOSED)) {
            for (int i = 0; i < 10; i++) {
                w.start("a" + i);
            }
            assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
            assertEquals(1, w.containers().size());
            assertTrue(w.violations.isEmpty(), w.violations.toString());
        }
    }

    @Test
    void agentsOnTcpFormAPlatformToo() {
        try (io.concord.testkit.Simulation sim = new io.concord.testkit.Simulation(3, FaultPlan.NONE)) {
            var rt = sim.newRuntime("h1");
            Platform p = Platform.builder().runtime(rt).transport(io.concord.core.net.Transport.TCP)
                    .safetyStack(io.concord.layers.SafetyStack.builder().profile(Profile.CLOSED)
                            .transport(io.concord.core.net.Transport.TCP).build()).build();
            java.util.List<io.concord.core.acl.AID> aids = new java.util.ArrayList<>();
            for (int i = 0; i < 5; i++) {
                aids.add(p.startAgent("t" + i, new PlatformWorld.Idle()));
            }
            java.util.function.BooleanSupplier agreed = () -> {
                long containers = aids.stream().filter(a -> Platform.containerLayer(rt, a).role() == Role.CONTAINER).count();
                return containers == 1 && aids.stream().allMatch(a -> Platform.containerLayer(rt, a).agents().size() == 5);
            };
            assertTrue(sim.runUntil(agreed, 5_000));
            assertTrue(aids.get(0).addresses().get(0).startsWith("tcp://"), aids.get(0).toString());
        }
    }

    /** A platform named otherwise than the runtime it is given would name its agents after the runtime: refused, saying what to do. */
    @Test
    void aPlatformNamedOtherwiseThanItsRuntimeIsRefused() {
        try (io.concord.testkit.Simulation sim = new io.concord.testkit.Simulation(3, FaultPlan.NONE)) {
            var rt = sim.newRuntime("h1");
            IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                    () -> Platform.builder().name("shop").runtime(rt).build());
            assertTrue(e.getMessage().contains("'shop'") && e.getMessage().contains("'" + rt.platformName() + "'")
                    && e.getMessage().contains("Simulation.platformName"), e.getMessage());
            sim.platformName("shop");
            var shop = sim.newRuntime("h2");
            try (Platform p = Platform.builder().name("shop").runtime(shop).build()) {
                assertEquals("shop", shop.platformName());
            }
        }
    }
}
