package io.concord.sim.scenario;

import io.concord.agents.proto.Asks;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.*;
import io.concord.agents.proto.Services;
import io.concord.agents.traffic.TrafficAgent;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.testkit.FaultPlan;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;
import java.util.concurrent.CompletableFuture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The traffic agent's rules one by one, with probes in place of the chairs' control agents, on
 * the virtual clock, under its default rules (in order). A traffic agent built without rules
 * ({@link io.concord.agents.traffic.TrafficRules#NONE}) grants every route at once.
 */
class TrafficTest {

    /** A chair's control agent as far as the traffic agent can tell: asks, tells, and keeps its orders. */
    static final class Chair extends Agent {
        Asks asks;
        final List<AclMessage> agrees = new ArrayList<>();
        final List<WheelchairMessage> orders = new ArrayList<>();
        /** FAILUREs that come after the answer (in a granted reservation's conversation). */
        final List<AclMessage> failures = new ArrayList<>();

        @Override
        protected void setup() {
            asks = new Asks(this);
            addBehaviour(asks);
            io.concord.core.agent.Inbox.each(this, MessageTemplate.matchPerformative(Performative.INFORM)
                    .and(WheelchairMessage.matching(MakeWay.class).or(WheelchairMessage.matching(Clear.class))),
                    m -> orders.add(WheelchairMessage.decode(m)));
            io.concord.core.agent.Inbox.each(this, MessageTemplate.matchPerformative(Performative.FAILURE), failures::add);
        }

        CompletableFuture<AclMessage> reserve(String at, String path, boolean aside) {
            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(AID.local("traffic", "hospital"));
            m.setOntology(Services.ONTOLOGY);
            m.setLanguage(Services.LANGUAGE);
            m.setContent(new Reserve(nodes(at), nodes(path), aside).encode());
            return asks.ask(m, 600_000, agrees::add);
        }

        void tell(WheelchairMessage c) {
            AclMessage m = new AclMessage(Performative.INFORM);
            m.addReceiver(AID.local("traffic", "hospital"));
            m.setOntology(Services.ONTOLOGY);
            m.setLanguage(Services.LANGUAGE);
            m.setContent(c.encode());
            send(m);
        }

        void release(int... nodes) {
            for (int n : nodes) {
                tell(new Release(n));
            }
        }
    }

    private static List<Integer> nodes(String commaSeparated) {
        return Arrays.stream(commaSeparated.split(",")).map(Integer::valueOf).toList();
    }

    private static Chair chair(ScenarioTest.Run r, String name) {
        Chair c = new Chair();
        r.platform.startAgent(name, c);
        r.sim.runFor(200);
        return c;
    }

    private static AclMessage answer(ScenarioTest.Run r, CompletableFuture<AclMessage> f) {
        assertTrue(r.sim.runUntil(f::isDone, 30_000), "an answer");
        return f.join();
    }

    private static String reason(AclMessage m) {
        return WheelchairMessage.reasonOf(m);
    }

    /**
     * a drives 19, 22, 7, 8; b's route crosses it the other way (7, then 22): b is granted at once,
     * but only up to node 6, where it stands, and told to go on once a has left 7 (and 22 before it).
     */
    @Test
    void aCrossingRouteIsGrantedBehindAndClearedOnlyOnceTheChairAheadHasLeftItsNodes() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(1, FaultPlan.NONE, 0)) {
            Chair a = chair(r, "a");
            Chair b = chair(r, "b");
            AclMessage ga = answer(r, a.reserve("19", "19,22,7,8", false));
            assertEquals(Performative.INFORM, ga.getPerformative());
            assertEquals(new Granted(List.of(19, 22, 7, 8), 8), WheelchairMessage.decode(ga), "a may drive all of it");
            AclMessage gb = answer(r, b.reserve("6", "6,7,22,23", false));
            assertEquals(Performative.INFORM, gb.getPerformative());
            assertEquals(6, WheelchairMessage.decode(gb, Granted.class).upto(), "b waits where it stands: 7 is a's turn");
            assertEquals(List.of("a@hospital", "b@hospital"), r.hospital.traffic().holders().get(7), "7's queue");
            a.release(19, 22);
            r.sim.runFor(5_000);
            assertTrue(b.orders.isEmpty(), "7 is still a's: " + b.orders);
            a.release(7);
            assertTrue(r.sim.runUntil(() -> !b.orders.isEmpty(), 5_000), "b is told to go on");
            assertEquals(new Clear(23), b.orders.get(0));
            assertEquals(List.of("b@hospital"), r.hospital.traffic().holders().get(22));
        }
    }

    @Test
    void anIdleChairInTheWayMakesWayToANodeNobodyNeeds() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(1, FaultPlan.NONE, 0)) {
            Chair a = chair(r, "a");
            Chair b = chair(r, "b");
            a.tell(new Idle(List.of(7)));
            r.sim.runFor(500);
            CompletableFuture<AclMessage> gb = b.reserve("19", "19,22,7,6,5,21", false);
            assertTrue(r.sim.runUntil(() -> !a.orders.isEmpty(), 10_000), "a is told to make way");
            MakeWay order = (MakeWay) a.orders.get(0);
            assertEquals(7, order.from());
            int to = order.to();
            assertFalse(List.of(19, 22, 7, 6, 5, 21).contains(to), "not onto b's route: " + to);
            assertFalse(gb.isDone(), "b waits while a stands on 7");
            // a asks for the way there (stepping aside goes first), drives it, and leaves 7 and every
            // node before the one it was sent to.
            String path = "7," + order.path().stream().map(String::valueOf).collect(Collectors.joining(","));
            assertEquals(Performative.INFORM, answer(r, a.reserve("7", path, true)).getPerformative());
            List<Integer> passed = order.path().stream().filter(n -> n != to).toList();
            a.release(7);
            passed.forEach(a::release);
            assertEquals(Performative.INFORM, answer(r, gb).getPerformative());
            assertEquals(1, r.hospital.traffic().moves());
        }
    }

    @Test
    void twoChairsEachWantingTheOthersRoomIsADeadlockBrokenByOneMakingWay() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(1, FaultPlan.NONE, 0)) {
            Chair a = chair(r, "a");
            Chair b = chair(r, "b");
            // Each stands in its room (a route of one node), busy (not idle), then asks for the other's.
            assertEquals(Performative.INFORM, answer(r, a.reserve("3", "3", false)).getPerformative());
            assertEquals(Performative.INFORM, answer(r, b.reserve("16", "16", false)).getPerformative());
            CompletableFuture<AclMessage> ga = a.reserve("3", "3,2,16", false);
            r.sim.runFor(3_000);
            assertFalse(ga.isDone(), "a waits for b, who is busy: no deadlock yet");
            assertEquals(0, r.hospital.traffic().deadlocks());
            CompletableFuture<AclMessage> gb = b.reserve("16", "16,2,3", false);
            assertTrue(r.sim.runUntil(() -> !a.orders.isEmpty() || !b.orders.isEmpty(), 10_000), "one of them is told to make way");
            assertEquals(1, r.hospital.traffic().deadlocks());
            // The first by name goes: its wait is answered FAILURE make-way.
            assertEquals(1, a.orders.size());
            assertTrue(b.orders.isEmpty());
            assertEquals(Performative.FAILURE, answer(r, ga).getPerformative());
            assertEquals("make-way", reason(ga.join()));
            MakeWay order = (MakeWay) a.orders.get(0);
            assertEquals(3, order.from());
            String path = "3," + order.path().stream().map(String::valueOf).collect(Collectors.joining(","));
            assertEquals(Performative.INFORM, answer(r, a.reserve("3", path, true)).getPerformative());
            assertFalse(gb.isDone(), "b waits until a has left its room and the corridor");
            a.release(3, 2);
            assertEquals(Performative.INFORM, answer(r, gb).getPerformative());
        }
    }

    @Test
    void aSilentChairKeepsOnlyWhereItStandsAndWhoWaitsForThatIsToldWhy() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(1, FaultPlan.NONE, 0)) {
            Chair a = chair(r, "a");
            Chair b = chair(r, "b");
            assertEquals(Performative.INFORM, answer(r, a.reserve("19", "19,22,7,6", false)).getPerformative());
            // a sets off along 19-22 and says so; then nothing more is heard of it.
            a.tell(new Here(null, List.of(19, 22)));
            AclMessage gb = answer(r, b.reserve("23", "23,22,7,8", false));
            assertEquals("((granted :path (sequence 23 22 7 8) :upto 23))", gb.getContent(), "granted behind a, which holds 22");
            for (int i = 0; i < 4; i++) {
                r.sim.runFor(TrafficAgent.SILENT_MS / 4);
                b.tell(new Here(null, null));
            }
            assertTrue(r.sim.runUntil(() -> !b.failures.isEmpty(), 5_000), "b is told, in its reservation's conversation");
            AclMessage m = b.failures.get(0);
            assertEquals(gb.getConversationId(), m.getConversationId());
            assertEquals("a is silent and stands on the route", reason(m));
            assertEquals(22, WheelchairMessage.decode(m, Failure.class).node());
            var held = r.hospital.traffic().holders();
            assertTrue(held.get(19).contains("a@hospital") && held.get(22).contains("a@hospital"), "its body: " + held);
            assertFalse(held.get(7).contains("a@hospital"), "the rest of its route is given back: " + held);
            assertTrue(r.log.contains("traffic: a is silent; it keeps [19, 22] where it stands"), String.join("\n", r.log));
        }
    }

    @Test
    void aChairSilentBeforeItSetOffKeepsOnlyTheNodeItStandsOn() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(1, FaultPlan.NONE, 0)) {
            Chair a = chair(r, "a");
            Chair b = chair(r, "b");
            assertEquals(Performative.INFORM, answer(r, a.reserve("19", "19,22,7,6", false)).getPerformative());
            CompletableFuture<AclMessage> gb = b.reserve("23", "23,22,7,8", false);
            for (int i = 0; i < 4; i++) {
                r.sim.runFor(TrafficAgent.SILENT_MS / 4);
                b.tell(new Here(null, null));
            }
            assertEquals(Performative.INFORM, answer(r, gb).getPerformative(), "22 is free: a never left 19");
            assertEquals(List.of("a@hospital"), r.hospital.traffic().holders().get(19));
        }
    }

    @Test
    void aRouteOffTheMapIsRefusedWithTheReason() {
        try (ScenarioTest.Run r = new ScenarioTest.Run(1, FaultPlan.NONE, 0)) {
            Chair a = chair(r, "a");
            AclMessage m = answer(r, a.reserve("19", "19,99", false));
            assertEquals(Performative.REFUSE, m.getPerformative());
            assertEquals("path: there is no node 99 on " + ScenarioTest.MAP.name(), reason(m));
            m = answer(r, a.reserve("1", "1,3", false));
            assertEquals(Performative.REFUSE, m.getPerformative());
            assertEquals("the route has no edge 1-3", reason(m));
            assertTrue(r.hospital.traffic().holders().isEmpty(), "nothing held for a refused route");
        }
    }
}
