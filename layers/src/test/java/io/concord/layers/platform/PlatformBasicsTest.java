package io.concord.layers.platform;

import io.concord.core.testkit.FaultPlan;
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
}
