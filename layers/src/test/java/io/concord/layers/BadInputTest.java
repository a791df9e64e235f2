package io.concord.layers;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.net.Address;
import io.concord.core.net.Endpoint;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.layers.security.PlatformKey;
import org.junit.jupiter.api.Test;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Random datagrams, truncated frames, bit flips, oversized frames, valid frames under a wrong key,
 * replays of captured frames: no exception escapes, nothing reaches the agent, the next good
 * message is served, and every drop is counted by reason.
 */
class BadInputTest {

    /** Everything an attacker on the path can make of frames it captured from A to B. */
    private static List<byte[]> attacks(List<byte[]> captured, List<byte[]> wrongKeyFrames, SplittableRandom r) {
        List<byte[]> out = new ArrayList<>();
        for (int i = 0; i < 300; i++) {
            byte[] junk = new byte[r.nextInt(900)];
            r.nextBytes(junk);
            out.add(junk);
        }
        for (byte[] f : captured) {
            for (int len = 0; len < f.length; len += 7) {
                out.add(java.util.Arrays.copyOf(f, len));
            }
            for (int k = 0; k < 20; k++) {
                byte[] flipped = f.clone();
                int bit = r.nextInt(f.length * 8);
                flipped[bit / 8] ^= (byte) (1 << (bit % 8));
                out.add(flipped);
            }
            out.add(f.clone()); // a replay
        }
        out.add(new byte[20_000]); // oversized
        out.addAll(wrongKeyFrames);
        return out;
    }

    @Test
    void onTheVirtualNetworkNothingBadReachesTheAgentAndTheNextGoodMessageDoes() {
        try (Simulation sim = new Simulation(31, FaultPlan.NONE).platformName("plat")) {
            AgentRuntime a = sim.newRuntime("host-a", Stacks.of(Profile.CLASS_7));
            AgentRuntime b = sim.newRuntime("host-b", Stacks.of(Profile.CLASS_7));
            AgentRuntime wrong = sim.newRuntime("host-w", Stacks.builder(Profile.CLASS_7)
                    .platformKey(PlatformKey.ofHex("ab".repeat(32))).build());
            ThreatWorld.Receiver receiver = new ThreatWorld.Receiver();
            AID bAid = b.startAgent("b", receiver);
            ThreatWorld.Puppet sender = new ThreatWorld.Puppet();
            a.startAgent("a", sender);
            ThreatWorld.Puppet stranger = new ThreatWorld.Puppet();
            wrong.startAgent("a", stranger);

            List<byte[]> captured = new ArrayList<>();
            List<byte[]> wrongKey = new ArrayList<>();
            sim.network().setMedium("host-a", (from, to, d, out) -> {
                captured.add(d.clone());
                out.deliver(0, d);
            });
            sender.send(new AclMessage(Performative.INFORM).addReceiver(bAid).setContent("first"));
            sim.runUntil(() -> receiver.got.size() == 1, 10_000);
            sim.network().setMedium("host-w", (from, to, d, out) -> {
                wrongKey.add(d.clone());
                out.deliver(0, d);
            });
            stranger.send(new AclMessage(Performative.INFORM).addReceiver(bAid).setContent("under a wrong key"));
            sim.runFor(5_000);

            Endpoint attacker = sim.network().tryBind("host-a", 9999, (f, d, o, l, now) -> { });
            Address bAddress = Address.parse(bAid.addresses().get(0));
            for (byte[] bad : attacks(captured, wrongKey, new SplittableRandom(1))) {
                attacker.send(bAddress, bad, 0, bad.length);
            }
            sim.runFor(5_000);
            assertEquals(1, receiver.got.size(), "nothing bad reached B");

            sender.send(new AclMessage(Performative.INFORM).addReceiver(bAid).setContent("next good one"));
            sim.runUntil(() -> receiver.got.size() == 2, 10_000);
            assertEquals(List.of("a:first", "a:next good one"), received(receiver));
            assertCountedByReason(b.drops());
        }
    }

    @Test
    void overRealUdpNothingBadReachesTheAgentAndTheNextGoodMessageDoes() throws Exception {
        try (AgentRuntime a = AgentRuntime.builder().platformName("plat").stack(Stacks.of(Profile.CLASS_7)).build().start();
             AgentRuntime b = AgentRuntime.builder().platformName("plat").stack(Stacks.of(Profile.CLASS_7)).build().start();
             AgentRuntime wrong = AgentRuntime.builder().platformName("plat").stack(Stacks.builder(Profile.CLASS_7)
                     .platformKey(PlatformKey.ofHex("ab".repeat(32))).build()).build().start();
             DatagramSocket tap = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            ThreatWorld.Receiver receiver = new ThreatWorld.Receiver();
            AID bAid = b.startAgent("b", receiver);
            InetSocketAddress bSocket = new InetSocketAddress("127.0.0.1", Address.parse(bAid.addresses().get(0)).port());
            // A's frames to B pass a relay that keeps a copy of each; the tap socket replays the attacks.
            ThreatWorld.Puppet sender = new ThreatWorld.Puppet();
            a.startAgent("a", sender);
            List<byte[]> captured = java.util.Collections.synchronizedList(new ArrayList<>());
            try (io.concord.testkit.UdpRelay relay = new io.concord.testkit.UdpRelay(
                    Address.parse(bAid.addresses().get(0)), (from, to, d, out) -> {
                        captured.add(d.clone());
                        out.deliver(0, d);
                    })) {
                AID bViaRelay = new AID(bAid.name(), relay.portFacingA().toUri());
                a.execute(() -> sender.send(new AclMessage(Performative.INFORM).addReceiver(bViaRelay).setContent("first")));
                assertTrue(receiver.awaitCount(1, 30_000));

                List<byte[]> wrongKey = java.util.Collections.synchronizedList(new ArrayList<>());
                java.util.concurrent.CountDownLatch firstWrong = new java.util.concurrent.CountDownLatch(1);
                try (io.concord.testkit.UdpRelay wrongRelay = new io.concord.testkit.UdpRelay(
                        Address.parse(bAid.addresses().get(0)), (from, to, d, out) -> {
                            wrongKey.add(d.clone());
                            firstWrong.countDown();
                        })) {
                    ThreatWorld.Puppet stranger = new ThreatWorld.Puppet();
                    wrong.startAgent("a", stranger);
                    AID bViaWrong = new AID(bAid.name(), wrongRelay.portFacingA().toUri());
                    wrong.execute(() -> stranger.send(new AclMessage(Performative.INFORM).addReceiver(bViaWrong).setContent("x")));
                    assertTrue(firstWrong.await(30, java.util.concurrent.TimeUnit.SECONDS), "the stranger sent a frame");
                }
                for (byte[] bad : attacks(new ArrayList<>(captured), new ArrayList<>(wrongKey), new SplittableRandom(2))) {
                    tap.send(new DatagramPacket(bad, bad.length, bSocket));
                }
                a.execute(() -> sender.send(new AclMessage(Performative.INFORM).addReceiver(bViaRelay).setContent("next good one")));
                assertTrue(receiver.awaitCount(2, 30_000));
            }
            assertEquals(List.of("a:first", "a:next good one"), received(receiver));
            assertCountedByReason(b.drops());
        }
    }

    private static List<String> received(ThreatWorld.Receiver r) {
        List<String> out = new ArrayList<>();
        r.got.forEach(m -> out.add(m.getSender().localName() + ":" + m.getContent()));
        return out;
    }

    private static void assertCountedByReason(Map<String, Long> drops) {
        for (String reason : List.of("malformed-frame", "too-large", "bad-tag", "copy")) {
            assertTrue(drops.getOrDefault(reason, 0L) > 0, reason + " was counted: " + drops);
        }
        assertTrue(drops.getOrDefault("layer-error", 0L) == 0, "no layer threw: " + drops);
    }
}
