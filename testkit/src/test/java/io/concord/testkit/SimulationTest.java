package io.concord.testkit;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.LambdaAgent;
import io.concord.core.agent.OneShotBehaviour;
import io.concord.core.proto.AchieveREResponder;
import io.concord.core.proto.Conversations;
import io.concord.core.proto.FipaProtocols;
import io.concord.core.proto.ProtocolException;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Two virtual hosts: partitions, healing and crashes, seen through a request with a deadline. */
class SimulationTest {
    private final Simulation sim = new Simulation(11, FaultPlan.NONE);
    private final AgentRuntime h1 = sim.newRuntime("h1");
    private final AgentRuntime h2 = sim.newRuntime("h2");
    private final AID echo = h2.startAgent("echo", new LambdaAgent(a -> Conversations.serve(a,
            AchieveREResponder.createMessageTemplate(FipaProtocols.REQUEST),
            r -> r.createReply().setPerformative(Performative.INFORM).setContent("pong"))));
    private int asks;

    @AfterEach
    void close() {
        sim.close();
    }

    private CompletableFuture<AclMessage> ask() {
        CompletableFuture<AclMessage> f = new CompletableFuture<>();
        h1.startAgent("asker" + asks++, new LambdaAgent(a -> a.addBehaviour(new OneShotBehaviour() {
            @Override
            public void action() {
                AclMessage req = new AclMessage(Performative.REQUEST).addReceiver(echo).setContent("ping");
                req.setReplyByEpochMs(myAgent.currentTimeMillis() + 500);
                Conversations.request(myAgent, req).whenComplete((m, e) -> {
                    if (e != null) {
                        f.completeExceptionally(e);
                    } else {
                        f.complete(m);
                    }
                });
            }
        })));
        sim.runUntil(f::isDone, 10_000);
        return f;
    }

    private ProtocolException.Reason failureOf(CompletableFuture<AclMessage> f) {
        ExecutionException e = assertThrows(ExecutionException.class, f::get);
        return assertInstanceOf(ProtocolException.class, e.getCause()).reason();
    }

    @Test
    void hostsTalkAcrossTheVirtualNetwork() throws Exception {
        assertEquals("pong", ask().get().getContent());
    }

    @Test
    void aPartitionTimesTheRequestOutAndHealingRestoresIt() throws Exception {
        sim.network().partition("h1", "h2");
        assertEquals(ProtocolException.Reason.TIMEOUT, failureOf(ask()));
        sim.network().heal("h1", "h2");
        assertEquals("pong", ask().get().getContent());
    }

    @Test
    void aCrashedHostStopsAnswering() {
        sim.crash(h2);
        assertFalse(sim.network().isBound("h2", echo.addresses().isEmpty() ? 0
                : io.concord.core.net.Address.parse(echo.addresses().get(0)).port()));
        assertEquals(ProtocolException.Reason.TIMEOUT, failureOf(ask()));
        assertTrue(sim.trace().lastLines().stream().anyMatch(l -> l.contains("echo@sim crash")), "the crash is traced");
    }

    @Test
    void aHostWhoseLinkIsDownIsUnreachableUntilItComesBack() throws Exception {
        sim.network().setHostDown("h2", true);
        assertEquals(ProtocolException.Reason.TIMEOUT, failureOf(ask()));
        sim.network().setHostDown("h2", false);
        assertEquals("pong", ask().get().getContent());
    }
}
