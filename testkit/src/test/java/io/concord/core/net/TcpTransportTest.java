package io.concord.core.net;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.AgentOptions;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.LambdaAgent;
import io.concord.core.agent.OneShotBehaviour;
import io.concord.core.proto.AchieveREResponder;
import io.concord.core.proto.Conversations;
import io.concord.core.proto.FipaProtocols;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import org.junit.jupiter.api.Test;

import java.io.OutputStream;
import java.net.Socket;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Agents that chose TCP: real streams on loopback, and the virtual network's TCP. */
class TcpTransportTest {

    /** Receives everything and counts down. */
    private static LambdaAgent collector(List<String> got, CountDownLatch done) {
        return new LambdaAgent(a -> a.addBehaviour(new CyclicBehaviour() {
            @Override
            public void action() {
                AclMessage m;
                while ((m = myAgent.receive()) != null) {
                    got.add(m.getContent());
                    done.countDown();
                }
                block();
            }
        }));
    }

    @Test
    void agentsOnTcpExchangeManyMessagesInOrderAndLargeOnes() throws Exception {
        try (AgentRuntime a = AgentRuntime.builder().transport(Transport.TCP).build().start();
             AgentRuntime b = AgentRuntime.builder().transport(Transport.TCP).build().start()) {
            List<String> got = Collections.synchronizedList(new ArrayList<>());
            CountDownLatch done = new CountDownLatch(2_001);
            AID receiver = b.startAgent("receiver", collector(got, done));
            assertTrue(receiver.addresses().get(0).startsWith("tcp://"), receiver.toString());
            a.startAgent("sender", new LambdaAgent(ag -> ag.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    for (int i = 0; i < 2_000; i++) {
                        myAgent.send(new AclMessage(Performative.INFORM).addReceiver(receiver).setContent("m" + i));
                    }
                    myAgent.send(new AclMessage(Performative.INFORM).addReceiver(receiver).setContent("x".repeat(200_000)));
                }
            })));
            assertTrue(done.await(30, TimeUnit.SECONDS), "received " + got.size());
            for (int i = 0; i < 2_000; i++) {
                assertEquals("m" + i, got.get(i));
            }
            assertEquals(200_000, got.get(2_000).length(), "a frame far larger than a datagram");
        }
    }

    @Test
    void aRequestOverTcpBothWays() throws Exception {
        try (AgentRuntime rt = AgentRuntime.builder().transport(Transport.TCP).build().start()) {
            AID echo = rt.startAgent("echo", new LambdaAgent(ag -> Conversations.serve(ag,
                    AchieveREResponder.createMessageTemplate(FipaProtocols.REQUEST),
                    r -> r.createReply().setPerformative(Performative.INFORM).setContent("echo " + r.getContent()))));
            CompletableFuture<String> reply = new CompletableFuture<>();
            rt.startAgent("client", new LambdaAgent(ag -> ag.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    Conversations.request(myAgent, new AclMessage(Performative.REQUEST).addReceiver(echo).setContent("hi"))
                            .thenAccept(m -> reply.complete(m.getContent()));
                }
            })));
            assertEquals("echo hi", reply.get(20, TimeUnit.SECONDS));
        }
    }

    @Test
    void aStreamThatIsNotConcordsIsClosedAndTheAgentGoesOn() throws Exception {
        try (AgentRuntime rt = AgentRuntime.builder().transport(Transport.TCP).build().start()) {
            List<String> got = Collections.synchronizedList(new ArrayList<>());
            CountDownLatch one = new CountDownLatch(1);
            AID receiver = rt.startAgent("receiver", collector(got, one));
            Address at = Address.parse(receiver.addresses().get(0));
            try (Socket s = new Socket(at.host(), at.port())) {
                OutputStream out = s.getOutputStream();
                out.write("GET / HTTP/1.1\r\n\r\n".getBytes());
                out.write(new byte[]{'C', 'T', 'C', 'P', 0, 3, 'x', 'y', 'z', 0x7f, 0, 0, 0});
                out.flush();
                assertEquals(-1, s.getInputStream().read(), "the endpoint closed the stream");
            }
            rt.startAgent("sender", new LambdaAgent(ag -> ag.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    myAgent.send(new AclMessage(Performative.INFORM).addReceiver(receiver).setContent("still here"));
                }
            })));
            assertTrue(one.await(20, TimeUnit.SECONDS));
            assertEquals(List.of("still here"), got);
        }
    }

    @Test
    void aUdpAgentCannotAddressATcpOneAndIsToldSo() {
        try (Simulation sim = new Simulation(3, FaultPlan.NONE)) {
            AgentRuntime rt = sim.newRuntime("h");
            AID tcp = rt.startAgentWith("tcp", new LambdaAgent(a -> { }), AgentOptions.defaults().withTransport(Transport.TCP));
            rt.startAgent("udp", new LambdaAgent(a -> a.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    myAgent.send(new AclMessage(Performative.INFORM).addReceiver(tcp));
                }
            })));
            sim.runUntilQuiet(1_000);
            assertEquals(1L, rt.drops().get("unknown-receiver"));
        }
    }

    @Test
    void virtualTcpIsReliableAndInOrderWhateverTheFaultPlan() {
        try (Simulation sim = new Simulation(8, FaultPlan.lossy(0.3, 0.2, 0.3, 0.05))) {
            AgentRuntime a = sim.newRuntime("ha");
            AgentRuntime b = sim.newRuntime("hb");
            List<String> got = new ArrayList<>();
            AID receiver = b.startAgentWith("r", collector(got, new CountDownLatch(0)),
                    AgentOptions.defaults().withTransport(Transport.TCP));
            a.startAgentWith("s", new LambdaAgent(ag -> ag.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    for (int i = 0; i < 500; i++) {
                        myAgent.send(new AclMessage(Performative.INFORM).addReceiver(receiver).setContent("m" + i));
                    }
                }
            })), AgentOptions.defaults().withTransport(Transport.TCP));
            sim.runUntilQuiet(10_000);
            assertEquals(500, got.size());
            for (int i = 0; i < 500; i++) {
                assertEquals("m" + i, got.get(i));
            }
            assertNull(sim.network().tryBind(Transport.TCP, "hb", Address.parse(receiver.addresses().get(0)).port(),
                    (f, d, o, l, n) -> { }), "the TCP port is taken");
        }
    }
}
