package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.testkit.FaultPlan;
import io.concord.layers.Profile;
import io.concord.layers.observe.ObserverLayer;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The agents' observation service (what the console sniffs and asks), over the platform itself. */
class ObserverTest {

    private static PlatformWorld world() {
        return new PlatformWorld(11, FaultPlan.NONE, Profile.CLASS_7);
    }

    private static AclMessage ask(Performative p, String to, String content, String conversation) {
        AclMessage m = new AclMessage(p);
        m.addReceiver(AID.local(to, "sim"));
        m.setOntology(ObserverLayer.ONTOLOGY);
        m.setConversationId(conversation);
        m.setContent(content);
        return m;
    }

    /** Starts a keeping agent and waits until the lists hold it. */
    private static void join(PlatformWorld w, String name, PlatformServicesTest.Inbox agent) {
        w.everStarted.add(name + "@sim");
        w.live.put(name, w.platform.startAgent(name, agent));
        assertTrue(w.sim.runUntil(w::converged, 5_000), w.describe());
    }

    private static List<String> events(PlatformServicesTest.Inbox s) {
        return s.got.stream().filter(m -> m.getPerformative() == Performative.INFORM).map(AclMessage::getContent)
                .collect(Collectors.toList());
    }

    @Test
    void aSnifferSeesWhatTheAgentSendsAndReceivesUntilItCancels() {
        try (PlatformWorld w = world()) {
            PlatformServicesTest.Inbox b = new PlatformServicesTest.Inbox();
            PlatformServicesTest.Inbox s = new PlatformServicesTest.Inbox();
            w.start("a");
            join(w, "b", b);
            join(w, "sniffer", s);
            Agent a = w.rt.agent(w.live.get("a"));
            Agent sn = w.rt.agent(w.live.get("sniffer"));
            sn.send(ask(Performative.SUBSCRIBE, "a", "sniff", "s1"));
            assertTrue(w.sim.runUntil(() -> s.got.stream().anyMatch(m -> m.getPerformative() == Performative.AGREE), 2_000));
            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(AID.local("b", "sim"));
            m.setConversationId("c7");
            m.setContent("a \"quoted\" request");
            a.send(m);
            assertTrue(w.sim.runUntil(() -> !b.got.isEmpty(), 2_000));
            b.send(b.got.get(0).createReply().setPerformative(Performative.AGREE).setContent("yes"));
            assertTrue(w.sim.runUntil(() -> events(s).size() >= 2, 2_000), events(s).toString());
            List<String> ev = events(s);
            assertTrue(ev.get(0).startsWith("{\"dir\":\"sent\",\"by\":\"a@sim\""), ev.get(0));
            assertTrue(ev.get(0).contains("\"from\":\"a@sim\",\"to\":\"b@sim\",\"performative\":\"REQUEST\",\"conversation\":\"c7\""), ev.get(0));
            assertTrue(ev.get(0).contains("a \\\\\\\"quoted\\\\\\\" request"), "the message whole, escaped: " + ev.get(0));
            assertTrue(ev.get(1).contains("\"dir\":\"received\"") && ev.get(1).contains("\"performative\":\"AGREE\""), ev.get(1));
            // Cancelled: nothing more.
            sn.send(ask(Performative.CANCEL, "a", "sniff", "s1"));
            w.sim.runFor(500);
            a.send(m.copy());
            w.sim.runFor(1_000);
            assertEquals(2, events(s).size(), events(s).toString());
        }
    }

    @Test
    void aSubscriptionEndsWithItsLeaseUnlessRenewed() {
        try (PlatformWorld w = world()) {
            PlatformServicesTest.Inbox s = new PlatformServicesTest.Inbox();
            w.start("a");
            w.start("b");
            join(w, "sniffer", s);
            Agent a = w.rt.agent(w.live.get("a"));
            w.rt.agent(w.live.get("sniffer")).send(ask(Performative.SUBSCRIBE, "a", "sniff", "s1"));
            w.sim.runFor(ObserverLayer.LEASE_MS + 1_000);
            AclMessage m = new AclMessage(Performative.INFORM);
            m.addReceiver(AID.local("b", "sim"));
            m.setContent("after the lease");
            a.send(m);
            w.sim.runFor(1_000);
            assertEquals(List.of(), events(s));
        }
    }

    @Test
    void statusTellsTheRoleTheClockAndTheDropsByLayer() {
        try (PlatformWorld w = world()) {
            PlatformServicesTest.Inbox s = new PlatformServicesTest.Inbox();
            w.start("a");
            join(w, "sniffer", s);
            w.rt.agent(w.live.get("sniffer")).send(ask(Performative.QUERY_REF, "a", "status", "q1"));
            assertTrue(w.sim.runUntil(() -> !events(s).isEmpty(), 2_000));
            String st = events(s).get(0);
            assertTrue(st.startsWith("{\"agent\":\"a@sim\",") && st.contains(",\"role\":\""), st);
            assertTrue(st.contains("\"container\":\"") && st.contains("\"clockOffsetUs\":") && st.contains("\"drops\":{"), st);
            // Where it runs (the console groups by it) and how it is doing.
            assertTrue(st.contains("\"pid\":" + ProcessHandle.current().pid() + ",") && st.contains("\"host\":\""), st);
            assertTrue(st.matches(".*\"sent\":\\d+,\"received\":\\d+,\"mailbox\":0,\"lagMs\":\\d+,.*"), st);
            w.rt.agent(w.live.get("sniffer")).send(ask(Performative.QUERY_REF, "a", "what?", "q2"));
            assertTrue(w.sim.runUntil(() -> s.got.stream().anyMatch(m -> m.getPerformative() == Performative.NOT_UNDERSTOOD), 2_000));
        }
    }

    @Test
    void statusCountsTheApplicationsMessagesNotTheServicesOwn() {
        try (PlatformWorld w = world()) {
            PlatformServicesTest.Inbox s = new PlatformServicesTest.Inbox();
            PlatformServicesTest.Inbox b = new PlatformServicesTest.Inbox();
            w.start("a");
            join(w, "b", b);
            join(w, "sniffer", s);
            Agent a = w.rt.agent(w.live.get("a"));
            for (int i = 0; i < 3; i++) {
                AclMessage m = new AclMessage(Performative.INFORM);
                m.addReceiver(AID.local("b", "sim"));
                m.setContent("n" + i);
                a.send(m);
            }
            assertTrue(w.sim.runUntil(() -> b.got.size() == 3, 2_000));
            w.rt.agent(w.live.get("sniffer")).send(ask(Performative.QUERY_REF, "a", "status", "q1"));
            w.rt.agent(w.live.get("sniffer")).send(ask(Performative.QUERY_REF, "b", "status", "q2"));
            assertTrue(w.sim.runUntil(() -> events(s).size() == 2, 2_000));
            String ofA = events(s).stream().filter(e -> e.startsWith("{\"agent\":\"a@sim\"")).findFirst().orElseThrow();
            String ofB = events(s).stream().filter(e -> e.startsWith("{\"agent\":\"b@sim\"")).findFirst().orElseThrow();
            assertTrue(ofA.contains("\"sent\":3,\"received\":0,"), ofA);
            assertTrue(ofB.contains("\"sent\":0,\"received\":3,"), ofB);
        }
    }

    /** JADE's AMS kills any agent on request; here any member of the platform may ask an agent to leave. */
    @Test
    void anAgentAskedToLeaveAgreesAndLeavesTheLists() {
        try (PlatformWorld w = world()) {
            PlatformServicesTest.Inbox s = new PlatformServicesTest.Inbox();
            w.start("a");
            join(w, "sniffer", s);
            w.rt.agent(w.live.get("sniffer")).send(ask(Performative.REQUEST, "a", "kill", "k1"));
            assertTrue(w.sim.runUntil(() -> s.got.stream().anyMatch(m -> m.getPerformative() == Performative.AGREE), 2_000));
            assertTrue(w.sim.runUntil(() -> !w.rt.agents().contains(w.live.get("a")), 2_000), "a is deleted");
            ContainerLayer c = io.concord.layers.Platform.containerLayer(w.rt, w.live.get("sniffer"));
            assertTrue(w.sim.runUntil(() -> c.agents().stream().noneMatch(e -> e.name().equals("a@sim"))
                    && c.globalAgents().stream().noneMatch(e -> e.name().equals("a@sim")), 5_000), "a left the lists");
        }
    }

    @Test
    void atMostEightSniffersAndTheNinthIsRefusedAndCounted() {
        try (PlatformWorld w = world()) {
            PlatformServicesTest.Inbox s = new PlatformServicesTest.Inbox();
            w.start("a");
            join(w, "sniffer", s);
            for (int i = 0; i <= ObserverLayer.MAX_SNIFFERS; i++) {
                w.rt.agent(w.live.get("sniffer")).send(ask(Performative.SUBSCRIBE, "a", "sniff", "s" + i));
            }
            assertTrue(w.sim.runUntil(() -> s.got.size() > ObserverLayer.MAX_SNIFFERS, 2_000));
            assertEquals(ObserverLayer.MAX_SNIFFERS, s.got.stream().filter(m -> m.getPerformative() == Performative.AGREE).count());
            assertEquals(1, s.got.stream().filter(m -> m.getPerformative() == Performative.REFUSE).count());
            assertEquals(1L, w.rt.drops(w.live.get("a")).get("sniff-limit"));
        }
    }

    /**
     * A flood of subscriptions, 30,000 from one sender (each in a conversation of its own) and
     * 30,000 from 100 senders: the agent holds 8 sniffers, refuses and counts the rest, and what
     * it keeps stays 8 whatever comes. With the bound lifted (a test's setting), it keeps them all.
     */
    @Test
    void thirtyThousandSubscriptionsFromOneAndFromAHundredSendersHoldEightSniffers() {
        assertEquals(ObserverLayer.MAX_SNIFFERS, flood(true, 30_000));
        // Lifted, a tenth of the flood is enough to show it: every subscription is kept (and each new one costs more).
        assertEquals(6_000, flood(false, 3_000), "without the bound every subscription is kept: the flood would grow the agent without end");
    }

    /** Floods agent a with {@code each} SUBSCRIBE sniff from one sender and as many from 100; the sniffers it holds at the end. */
    private static int flood(boolean bounded, int each) {
        try (PlatformWorld w = world()) {
            w.start("a");
            if (!bounded) {
                w.rt.layer(w.live.get("a"), ObserverLayer.class).sniffLimit(Integer.MAX_VALUE);
            }
            List<PlatformServicesTest.Inbox> senders = new java.util.ArrayList<>();
            for (int i = 0; i <= 100; i++) {
                PlatformServicesTest.Inbox s = new PlatformServicesTest.Inbox();
                join(w, "s" + i, s);
                senders.add(s);
            }
            int sent = 0;
            for (int i = 0; i < each; i++) {
                w.rt.agent(w.live.get("s0")).send(ask(Performative.SUBSCRIBE, "a", "sniff", "one-" + i));
                w.rt.agent(w.live.get("s" + (1 + i % 100))).send(ask(Performative.SUBSCRIBE, "a", "sniff", "many-" + i));
                sent += 2;
                if (sent % 2_000 == 0) {
                    w.sim.runFor(50);   // the senders' loops and the agent's take what was sent
                }
            }
            long answers = 2L * each;
            assertTrue(w.sim.runUntil(() -> senders.stream().mapToLong(s -> s.got.size()).sum() >= answers, 60_000),
                    senders.stream().mapToLong(s -> s.got.size()).sum() + " answers");
            long agreed = senders.stream().flatMap(s -> s.got.stream()).filter(m -> m.getPerformative() == Performative.AGREE).count();
            long refused = senders.stream().flatMap(s -> s.got.stream()).filter(m -> m.getPerformative() == Performative.REFUSE).count();
            assertEquals(answers, agreed + refused);
            if (bounded) {
                assertEquals(ObserverLayer.MAX_SNIFFERS, agreed);
                assertEquals(answers - ObserverLayer.MAX_SNIFFERS, (long) w.rt.drops(w.live.get("a")).get("sniff-limit"),
                        "every refusal counted with its reason");
            }
            return w.rt.layer(w.live.get("a"), ObserverLayer.class).sniffers();
        }
    }
}
