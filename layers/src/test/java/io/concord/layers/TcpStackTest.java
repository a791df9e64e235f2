package io.concord.layers;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.AgentOptions;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.LambdaAgent;
import io.concord.core.agent.OneShotBehaviour;
import io.concord.core.net.Transport;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import org.junit.jupiter.api.Test;

import java.util.concurrent.atomic.AtomicReference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The class-7 stack on agents that chose TCP. */
class TcpStackTest {

    @Test
    void classSevenOverRealTcpCarriesMessagesUpToSixteenKilobytes() throws Exception {
        var stack = Stacks.builder(Profile.CLASS_7).transport(Transport.TCP).build();
        try (AgentRuntime a = AgentRuntime.builder().transport(Transport.TCP).stack(stack).build().start();
             AgentRuntime b = AgentRuntime.builder().transport(Transport.TCP).stack(stack).build().start()) {
            ThreatWorld.Receiver receiver = new ThreatWorld.Receiver();
            AID to = b.startAgent("b", receiver);
            AtomicReference<RuntimeException> refused = new AtomicReference<>();
            a.startAgent("a", new LambdaAgent(ag -> ag.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    myAgent.send(new AclMessage(Performative.INFORM).addReceiver(to).setContent("small"));
                    myAgent.send(new AclMessage(Performative.INFORM).addReceiver(to).setContent("y".repeat(12_000)));
                    try {
                        myAgent.send(new AclMessage(Performative.INFORM).addReceiver(to).setContent("z".repeat(17_000)));
                    } catch (RuntimeException e) {
                        refused.set(e);
                    }
                }
            })));
            assertTrue(receiver.awaitCount(2, 30_000), "received " + receiver.got.size());
            assertEquals("small", receiver.got.poll().getContent());
            assertEquals(12_000, receiver.got.poll().getContent().length(), "over the UDP limit, under TCP's");
            assertNotNull(refused.get(), "17 000 bytes is over TCP's 16 KiB");
            assertTrue(refused.get().getMessage().contains("16384"), refused.get().getMessage());
        }
    }

    @Test
    void aFloodOfIdleTcpStreamsCannotKeepARealPeerOut() throws Exception {
        var stack = Stacks.builder(Profile.CLASS_7).transport(Transport.TCP).build();
        java.util.List<java.nio.channels.SocketChannel> flood = new java.util.ArrayList<>();
        // What a stream that breaks the format costs: one counted drop, no log line each.
        try (AgentRuntime a = AgentRuntime.builder().transport(Transport.TCP).stack(stack).build().start();
             AgentRuntime b = AgentRuntime.builder().transport(Transport.TCP).stack(stack).build().start()) {
            ThreatWorld.Receiver receiver = new ThreatWorld.Receiver();
            AID to = b.startAgent("b", receiver);
            io.concord.core.net.Address at = io.concord.core.net.Address.parse(to.addresses().get(0));
            for (int i = 0; i < 200; i++) {
                java.nio.channels.SocketChannel c = java.nio.channels.SocketChannel.open(
                        new java.net.InetSocketAddress(at.host(), at.port()));
                if (i % 2 == 0) {
                    // half announce a 1 MiB frame and never send it
                    byte[] who = "127.0.0.1:9".getBytes(java.nio.charset.StandardCharsets.UTF_8);
                    java.nio.ByteBuffer hello = java.nio.ByteBuffer.allocate(6 + who.length + 4);
                    hello.put(new byte[]{'C', 'T', 'C', 'P', 0, (byte) who.length}).put(who).putInt(1 << 20).flip();
                    c.write(hello);
                }
                c.configureBlocking(false);
                flood.add(c);
            }
            long deadline = System.nanoTime() + 30_000_000_000L;
            int closed = 0;
            while (System.nanoTime() < deadline) {
                closed = 0;
                for (java.nio.channels.SocketChannel c : flood) {
                    try {
                        if (c.read(java.nio.ByteBuffer.allocate(1)) < 0) {
                            closed++;
                        }
                    } catch (java.io.IOException reset) {
                        closed++;
                    }
                }
                if (closed >= 200 - 64) {
                    break;
                }
                Thread.onSpinWait();
            }
            assertTrue(closed >= 200 - 64, "at most 64 streams stay open into one agent; " + closed + " of 200 were closed");
            assertTrue(b.drops().getOrDefault("tcp-connections", 0L) >= 200 - 64, "each counted: " + b.drops());
            a.startAgent("a", new LambdaAgent(ag -> ag.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    myAgent.send(new AclMessage(Performative.INFORM).addReceiver(to).setContent("through"));
                }
            })));
            assertTrue(receiver.awaitCount(1, 30_000), "a real peer still gets through: " + b.drops());
            assertEquals("through", receiver.got.poll().getContent());
        } finally {
            for (java.nio.channels.SocketChannel c : flood) {
                c.close();
            }
        }
    }

    @Test
    void repetitionOnTcpIsRefusedAtBuildTime() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Stacks.builder(Profile.CLASS_7).transport(Transport.TCP).copies(2).build());
        assertTrue(e.getMessage().contains("TCP already retransmits"), e.getMessage());
    }

    @Test
    void aStackBuiltForTcpRefusesToStartOnAUdpAgent() {
        try (Simulation sim = new Simulation(4, FaultPlan.NONE)) {
            AgentRuntime rt = sim.newRuntime("h");
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> rt.startAgentWith("a",
                    new LambdaAgent(ag -> { }), AgentOptions.defaults()
                            .withStack(Stacks.builder(Profile.CLASS_7).transport(Transport.TCP).build())));
            assertTrue(e.getMessage().contains("built for TCP"), e.getMessage());
        }
    }
}
