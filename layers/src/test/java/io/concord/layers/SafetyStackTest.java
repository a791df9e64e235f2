package io.concord.layers;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.OneShotBehaviour;
import io.concord.core.layer.Layer;
import io.concord.core.layer.SendRejectedException;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class SafetyStackTest {
    @Test
    void buildsTheFiveLayersTopFirst() {
        List<Layer> layers = Stacks.of(Profile.CLASS_7).get();
        assertEquals(List.of("parser", "sequence", "temporal", "security", "communication"),
                layers.stream().map(Layer::name).toList());
        assertTrue(Stacks.of(Profile.CLASS_7).get().get(0) != layers.get(0), "a new stack for each agent");
    }

    @Test
    void failsFastOnCombinationsThatCannotWork() {
        IllegalArgumentException noSeq = assertThrows(IllegalArgumentException.class,
                () -> Stacks.builder(Profile.CLASS_7).without(SafetyStack.LayerKind.SEQUENCE).build());
        assertTrue(noSeq.getMessage().contains("CLASS_7"), noSeq.getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> Stacks.builder(Profile.CLASS_3).without(SafetyStack.LayerKind.TEMPORAL).build());
        IllegalArgumentException noParser = assertThrows(IllegalArgumentException.class,
                () -> Stacks.builder(Profile.CLOSED).without(SafetyStack.LayerKind.PARSER).build());
        assertTrue(noParser.getMessage().contains("PARSER"));
        assertThrows(IllegalArgumentException.class, () -> Stacks.builder(Profile.CLASS_7).copies(0).build());
        assertThrows(IllegalArgumentException.class, () -> Stacks.builder(Profile.CLASS_7).maxFrameBytes(100_000).build());
        assertThrows(IllegalArgumentException.class, () -> Stacks.builder(Profile.CLOSED)
                .without(SafetyStack.LayerKind.TEMPORAL)
                .timeSource("c@p", new io.concord.core.net.Address("h", 1), 1000).build());
    }

    @Test
    void aClosedNetworkMayLeaveSequenceAndTimeOut() {
        List<Layer> layers = Stacks.builder(Profile.CLOSED)
                .without(SafetyStack.LayerKind.SEQUENCE, SafetyStack.LayerKind.TEMPORAL).build().get();
        assertEquals(List.of("parser", "security", "communication"), layers.stream().map(Layer::name).toList());
    }

    @Test
    void aMessageTooLargeIsRefusedToTheCallerWithItsSize() {
        try (Simulation sim = new Simulation(5, FaultPlan.NONE)) {
            AgentRuntime rt = sim.newRuntime("h", Stacks.of(Profile.CLASS_7));
            AID b = rt.startAgent("b", new ThreatWorld.Receiver());
            AtomicReference<RuntimeException> thrown = new AtomicReference<>();
            rt.startAgent("a", new io.concord.core.agent.LambdaAgent(a -> a.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    try {
                        myAgent.send(new AclMessage(Performative.INFORM).addReceiver(b).setContent("x".repeat(9_000)));
                    } catch (RuntimeException e) {
                        thrown.set(e);
                    }
                }
            })));
            sim.runUntilQuiet(5_000);
            assertNotNull(thrown.get(), "send refused the message");
            SendRejectedException e = assertInstanceOf(SendRejectedException.class, thrown.get());
            assertTrue(e.getMessage().contains("8192"), e.getMessage());
            assertEquals(1L, rt.drops().get("too-large"));
        }
    }

    @Test
    void aRuntimeWithoutAChosenStackGivesItsAgentsTheClassSevenStack(@org.junit.jupiter.api.io.TempDir java.nio.file.Path home) {
        String old = System.getProperty(io.concord.layers.security.PlatformKey.HOME_PROPERTY);
        System.setProperty(io.concord.layers.security.PlatformKey.HOME_PROPERTY, home.toString());
        try (Simulation sim = new Simulation(6, FaultPlan.NONE)) {
            AgentRuntime rt = sim.newRuntime("h");
            AID a = rt.startAgent("a", new io.concord.core.agent.LambdaAgent(ag -> { }));
            assertEquals(List.of("parser", "sequence", "temporal", "security", "communication"),
                    rt.layers(a).stream().map(Layer::name).toList());
            assertTrue(java.nio.file.Files.exists(home.resolve("platform.key")), "a platform key was made for the user");
        } finally {
            if (old == null) {
                System.clearProperty(io.concord.layers.security.PlatformKey.HOME_PROPERTY);
            } else {
                System.setProperty(io.concord.layers.security.PlatformKey.HOME_PROPERTY, old);
            }
        }
    }
}
