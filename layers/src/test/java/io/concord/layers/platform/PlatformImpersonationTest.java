package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.testkit.FaultPlan;
import io.concord.layers.Profile;
import io.concord.layers.frame.Frames;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A member of the platform (it holds the platform key) tries to speak for others: the
 * container layer takes a platform message only in its sender's own name, and in a frame for
 * any agent (sealed with the platform key alone) only discovery. Security issue, hole 3.
 */
class PlatformImpersonationTest {

    private static PlatformWorld converged() {
        PlatformWorld w = new PlatformWorld(8, FaultPlan.NONE, Profile.CLASS_7);
        for (String n : List.of("a", "b", "c", "m")) {
            w.start(n);
        }
        assertTrue(w.sim.runUntil(w::converged, 10_000), w.describe());
        return w;
    }

    private static AclMessage platformMessage(String content, AID sender) {
        AclMessage m = new AclMessage(Performative.INFORM);
        m.setOntology("concord-platform");
        m.setProtocol("concord-maintenance");
        m.setSender(sender);
        m.setContent(content);
        return m;
    }

    @Test
    void aMemberCannotSayTheContainerLeft() {
        try (PlatformWorld w = converged()) {
            String container = w.containers().get(0);
            String rogue = w.live.keySet().stream().filter(n -> !n.equals(container)).findFirst().orElseThrow();
            Agent r = w.rt.agent(w.live.get(rogue));
            for (String n : w.live.keySet()) {
                if (!n.equals(rogue)) {
                    AclMessage m = platformMessage("leave", w.live.get(container));
                    m.addReceiver(w.live.get(n));
                    r.send(m);
                }
            }
            w.sim.runFor(2_000);
            assertEquals(List.of(container), w.containers(), "nobody took the container for gone: " + w.describe());
            assertTrue(w.converged(), w.describe());
            // The identification layer refuses a message whose sender is not the frame's source; the
            // container layer checks it again for platform messages (masquerade).
            assertTrue(w.rt.drops().getOrDefault("identification", 0L) + w.rt.drops().getOrDefault("masquerade", 0L) >= 3,
                    w.rt.drops().toString());
        }
    }

    @Test
    void onlyDiscoveryComesInAFrameForAnyAgent() {
        try (PlatformWorld w = converged()) {
            String container = w.containers().get(0);
            String rogue = w.live.keySet().stream().filter(n -> !n.equals(container)).findFirst().orElseThrow();
            Agent r = w.rt.agent(w.live.get(rogue));
            // In its own name, but sealed with the platform key only, to whoever holds the container's port.
            AID any = new AID(Frames.ANY_LOCAL_NAME + "@sim", w.live.get(container).addresses().get(0));
            AclMessage m = platformMessage("leave", w.live.get(rogue));
            m.addReceiver(any);
            r.send(m);
            w.sim.runFor(50);
            assertTrue(w.layer(container).agents().stream().anyMatch(e -> e.name().equals(rogue + "@sim")),
                    "the container did not take a leave from a frame anyone with the key could have written: " + w.describe());
            assertTrue(w.rt.drops().getOrDefault("unauthenticated", 0L) >= 1, w.rt.drops().toString());
            w.sim.runFor(2_000);
            assertTrue(w.converged(), w.describe());
        }
    }
}
