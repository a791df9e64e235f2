package io.concord.core.net;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.LambdaAgent;
import io.concord.core.agent.OneShotBehaviour;
import io.concord.core.agent.ThreadedBehaviourFactory;
import io.concord.core.codec.BinaryAclCodec;
import io.concord.core.proto.AchieveREResponder;
import io.concord.core.proto.Conversations;
import io.concord.core.proto.FipaProtocols;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** One runtime on its own loop thread, agents on real UDP sockets on loopback. */
class RealUdpRuntimeTest {
    private final AgentRuntime rt = AgentRuntime.builder().platformName("real").build().start();

    @AfterEach
    void close() {
        rt.close();
    }

    /** Receives INFORMs and completes the future with the first one's content. */
    private AID sink(String name, CompletableFuture<String> first) {
        return rt.startAgent(name, new LambdaAgent(a -> a.addBehaviour(new CyclicBehaviour() {
            @Override
            public void action() {
                AclMessage m = myAgent.receive(MessageTemplate.matchPerformative(Performative.INFORM));
                if (m == null) {
                    block();
                    return;
                }
                first.complete(m.getContent());
            }
        })));
    }

    private void sendFrom(String name, AID to, String content) {
        rt.startAgent(name, new LambdaAgent(a -> a.addBehaviour(new OneShotBehaviour() {
            @Override
            public void action() {
                myAgent.send(new AclMessage(Performative.INFORM).addReceiver(to).setContent(content));
            }
        })));
    }

    @Test
    void twentyAgentsPassAMessageRoundARingOverRealSockets() throws Exception {
        int n = 20;
        List<AID> ring = new ArrayList<>();
        CompletableFuture<String> back = new CompletableFuture<>();
        AID[] next = new AID[n];
        for (int i = 0; i < n; i++) {
            int me = i;
            ring.add(rt.startAgent("link" + i, new LambdaAgent(a -> a.addBehaviour(new CyclicBehaviour() {
                @Override
                public void action() {
                    AclMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    if (me == 0) {
                        back.complete(m.getContent());
                    } else {
                        myAgent.send(new AclMessage(Performative.INFORM).addReceiver(next[me]).setContent(m.getContent() + me));
                    }
                }
            }))));
        }
        for (int i = 0; i < n; i++) {
            next[i] = ring.get((i + 1) % n);
        }
        assertEquals(n, ring.stream().map(a -> a.addresses().get(0)).distinct().count(), "one port per agent");
        sendFrom("starter", ring.get(1), "s");
        StringBuilder expected = new StringBuilder("s");
        for (int i = 1; i < n; i++) {
            expected.append(i);
        }
        assertEquals(expected.toString(), back.get(10, TimeUnit.SECONDS));
    }

    @Test
    void aMalformedDatagramIsDroppedCountedAndTheAgentGoesOn() throws Exception {
        CompletableFuture<String> got = new CompletableFuture<>();
        AID target = sink("target", got);
        Address addr = Address.parse(target.addresses().get(0));
        try (DatagramSocket raw = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            InetSocketAddress to = new InetSocketAddress(addr.host(), addr.port());
            byte[] garbage = {(byte) 0xA1, 7, 0x01, (byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff, 0x07};
            raw.send(new DatagramPacket(garbage, garbage.length, to));
            AclMessage ok = new AclMessage(Performative.INFORM).addReceiver(target).setContent("after the garbage");
            byte[] good = BinaryAclCodec.INSTANCE.encode(ok);
            raw.send(new DatagramPacket(good, good.length, to));
        }
        assertEquals("after the garbage", got.get(10, TimeUnit.SECONDS));
        assertEquals(1L, rt.drops(target).get("malformed"));
    }

    @Test
    void aThreadedBehaviourMayUseBlockingReceive() throws Exception {
        CompletableFuture<String> got = new CompletableFuture<>();
        CompletableFuture<Boolean> offLoop = new CompletableFuture<>();
        AID waiter = rt.startAgent("waiter", new LambdaAgent(a -> a.addBehaviour(new ThreadedBehaviourFactory().wrap(
                new OneShotBehaviour() {
                    @Override
                    public void action() {
                        offLoop.complete(!myAgent.runtime().inLoop());
                        AclMessage m = myAgent.blockingReceive(MessageTemplate.matchContent("wake up"), 10_000);
                        got.complete(m == null ? "timed out" : m.getContent());
                    }
                }))));
        assertTrue(offLoop.get(10, TimeUnit.SECONDS), "runs on a thread of its own");
        sendFrom("waker", waiter, "wake up");
        assertEquals("wake up", got.get(10, TimeUnit.SECONDS));
    }

    @Test
    void aRequestOverRealSocketsCompletesItsFuture() throws Exception {
        AID echo = rt.startAgent("echo", new LambdaAgent(a -> Conversations.serve(a,
                AchieveREResponder.createMessageTemplate(FipaProtocols.REQUEST),
                req -> req.createReply().setPerformative(Performative.INFORM).setContent("echo " + req.getContent()))));
        CompletableFuture<AclMessage> reply = new CompletableFuture<>();
        rt.startAgent("client", new LambdaAgent(a -> a.addBehaviour(new OneShotBehaviour() {
            @Override
            public void action() {
                Conversations.request(myAgent, new AclMessage(Performative.REQUEST).addReceiver(echo).setContent("ping"))
                        .whenComplete((m, e) -> {
                            if (e != null) {
                                reply.completeExceptionally(e);
                            } else {
                                reply.complete(m);
                            }
                        });
            }
        })));
        assertEquals("echo ping", reply.get(10, TimeUnit.SECONDS).getContent());
    }

    @Test
    void startingAnAgentOnATakenPortSaysSo() {
        AID first = rt.startAgent("first", new LambdaAgent(a -> { }));
        int port = Address.parse(first.addresses().get(0)).port();
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> rt.startAgentOnPort("second", new LambdaAgent(a -> { }), port));
        assertTrue(e.getMessage().contains("already in use"), e.getMessage());
        IllegalArgumentException dup = assertThrows(IllegalArgumentException.class,
                () -> rt.startAgent("first", new LambdaAgent(a -> { })));
        assertTrue(dup.getMessage().contains("already runs here"));
    }

    @Test
    void sendingFromAnotherThreadIsHandedToTheLoop() throws Exception {
        CompletableFuture<String> got = new CompletableFuture<>();
        AID target = sink("target", got);
        Agent[] ref = new Agent[1];
        rt.startAgent("outsider", new LambdaAgent(a -> ref[0] = a));
        Thread t = new Thread(() -> ref[0].send(new AclMessage(Performative.INFORM).addReceiver(target).setContent("from afar")));
        t.start();
        t.join();
        assertEquals("from afar", got.get(10, TimeUnit.SECONDS));
    }
}
