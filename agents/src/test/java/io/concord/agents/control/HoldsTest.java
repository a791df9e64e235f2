package io.concord.agents.control;

import io.concord.agents.chair.ChairEvent;
import io.concord.agents.chair.ChairListener;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.ChairSupervisor;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.*;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.layers.authority.OperatorKey;
import io.concord.layers.authority.Operators;
import io.concord.layers.authority.Policy;
import io.concord.layers.authority.SignedOrder;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static io.concord.agents.control.Fakes.estop;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The holds alone, on a real {@link ChairSupervisor} around a fake chair: what a hold does to the
 * task under way, and who may resume. Timers are the test's: it runs them when it says time has
 * passed.
 */
class HoldsTest {
    static final AID MEDICAL = new AID("medical@test");

    final Fakes.Chair chair = new Fakes.Chair();
    final ChairSupervisor supervisor = new ChairSupervisor(chair);
    final List<AclMessage> sent = new ArrayList<>();
    final List<String> said = new ArrayList<>();
    final List<Long> timerMs = new ArrayList<>();
    final List<Runnable> timers = new ArrayList<>();
    final List<String> failed = new ArrayList<>();
    Task active;
    boolean work;
    long ms;

    static final OperatorKey ADA = OperatorKey.generate("nurse Ada");
    long nowMs = 1_700_000_000_000L;
    final ResumeAuthority authority = new ResumeAuthority(() -> nowMs);

    final Holds holds = new Holds(supervisor, () -> "control-chair1", () -> "test", new Holds.Agent() {
        @Override
        public Task active() {
            return active;
        }

        @Override
        public boolean hasWork() {
            return work;
        }

        @Override
        public void failAll(String why) {
            failed.add(why);
        }

        @Override
        public void send(AclMessage m) {
            sent.add(m);
        }

        @Override
        public void after(long delayMs, Runnable r) {
            timerMs.add(delayMs);
            timers.add(r);
        }

        @Override
        public void say(String s) {
            said.add(s);
        }
    }, authority);

    HoldsTest() {
        authority.operators(Operators.of(ADA.operator()));
        supervisor.setObserver(holds);
        supervisor.setListener(new ChairListener() {
            @Override
            public void onReadings(ChairReadings r) {
                holds.reading(r);
            }

            @Override
            public void onOnline(boolean up) {
                holds.online(up);
            }

            @Override
            public void onEvent(ChairEvent event) {
            }
        });
    }

    /** A task under way, accepted from the Medical agent. */
    private void taskUnderWay() {
        AclMessage cfp = new AclMessage(Performative.CFP);
        cfp.setConversationId("cfp-t1");
        active = new Task("t1", 3, 9, 0, 0, cfp);
        active.accept = new AclMessage(Performative.ACCEPT_PROPOSAL).setSender(MEDICAL);
        active.state = TaskView.State.TO_PICKUP;
        work = true;
    }

    private void readings(int n, boolean estopPressed) {
        for (int i = 0; i < n; i++) {
            ms += 50;
            chair.report(estop(ms, estopPressed));
        }
    }

    private WheelchairMessage sent(int i) {
        return WheelchairMessage.decode(sent.get(i));
    }

    @Test
    void withNoTaskTheAgentArmsTheChairItself() {
        readings(3, false);
        assertTrue(supervisor.armed(), supervisor.state().toString());
        assertTrue(sent.isEmpty());
    }

    @Test
    void anEStopPausesTheTaskAndAfterItsReleaseOnlyAnOperatorResumesIt() {
        readings(3, false);
        taskUnderWay();
        readings(1, true);
        assertEquals("paused", sent(0).verb());
        assertFalse(((Paused) sent(0)).agentResumes(), "an operator resumes");
        assertEquals("cfp-t1/status", sent.get(0).getConversationId());
        assertEquals(MEDICAL, sent.get(0).getReceivers().get(0));
        assertNotNull(active.paused);

        readings(5, false);
        assertEquals(ChairSupervisor.State.HELD, supervisor.state(), "released: still held, no resume by the agent");
        assertTrue(said.contains("the e-stop of chair1 is released: the chair stays held until an operator resumes it"), said.toString());
        holds.keepAlive();
        assertEquals("paused", sent(1).verb(), "told again while paused");

        assertNull(holds.resumeOrdered(ADA.sign("resume", "chair1", nowMs).encode()));
        readings(3, false);
        assertTrue(supervisor.armed());
        assertNull(active.paused);
        assertEquals("resumed", sent(2).verb());
        assertEquals("decided by nurse Ada", ((Resumed) sent(2)).reason());
    }

    @Test
    void anEStopWithNoTaskAcceptedIsResumedByTheAgentOnceReleased() {
        readings(3, false);
        readings(2, true);
        assertEquals(ChairSupervisor.State.HELD, supervisor.state());
        readings(1, false);
        readings(2, false);
        assertTrue(supervisor.armed(), "no task: no motion follows until one is accepted");
    }

    @Test
    void anOperatorsResumeWhileTheEStopIsStillPressedIsRefusedWithWhy() {
        readings(3, false);
        taskUnderWay();
        readings(1, true);
        AclMessage ask = new AclMessage(Performative.REQUEST).setSender(new AID("console@test"));
        ask.setContent(new ResumeRequest("nurse Ada", ADA.sign("resume", "chair1", nowMs).encode()).encode());
        holds.resumeAsked(ask);
        AclMessage answer = sent.get(sent.size() - 1);
        assertEquals(Performative.REFUSE, answer.getPerformative());
        assertTrue(WheelchairMessage.decode(answer, Refused.class).reason().contains("e-stop"), answer.getContent());
        assertEquals(ChairSupervisor.State.HELD, supervisor.state());
    }

    /** As the console's form: an armed chair has nothing to resume; a request that does not read resumes nothing. */
    @Test
    void aResumeOfAnArmedChairOrOneThatDoesNotReadIsRefused() {
        readings(3, false);
        assertTrue(supervisor.armed());
        AclMessage ask = new AclMessage(Performative.REQUEST).setSender(new AID("console@test"));
        ask.setContent(new ResumeRequest("nurse Ada").encode());
        holds.resumeAsked(ask);
        assertTrue(WheelchairMessage.reasonOf(sent.get(sent.size() - 1)).contains("only an operator may resume"),
                "who asks comes first: a key holder learns nothing of the chair's state: " + sent.get(sent.size() - 1).getContent());
        ask.setContent(new ResumeRequest("nurse Ada", ADA.sign("resume", "chair1", nowMs).encode()).encode());
        holds.resumeAsked(ask);
        assertEquals(Performative.REFUSE, sent.get(sent.size() - 1).getPerformative());
        assertTrue(WheelchairMessage.reasonOf(sent.get(sent.size() - 1)).contains("is not held"), sent.get(sent.size() - 1).getContent());

        taskUnderWay();
        readings(1, true);
        readings(3, false);
        assertEquals(ChairSupervisor.State.HELD, supervisor.state(), "released, held for an operator");
        ask.setContent("((resume-request :by \"nurse Ada\" :colour red))");
        holds.resumeAsked(ask);
        AclMessage answer = sent.get(sent.size() - 1);
        assertEquals(Performative.REFUSE, answer.getPerformative());
        assertEquals("unknown slot :colour of resume-request", WheelchairMessage.reasonOf(answer));
        readings(3, false);
        assertEquals(ChairSupervisor.State.HELD, supervisor.state(), "still held");
    }

    @Test
    void aLinkDownLongerThanTheGraceFailsTheTasksAndOneThatCameBackDoesNot() {
        readings(3, false);
        taskUnderWay();
        chair.link(false);
        assertEquals(List.of(ControlAgent.LINK_GRACE_MS), timerMs);
        timers.get(0).run();
        assertEquals(List.of("chair1 has been offline for 30.0 s"), failed);

        chair.link(true);
        chair.link(false);
        chair.link(true);
        timers.get(1).run();
        assertEquals(1, failed.size(), "the link came back within the grace");
        readings(3, false);
        assertTrue(supervisor.armed(), "a lost link that came back: the agent resumes");
    }

    // ---- who may resume: only an operator's signed order (docs/security.md, "Who may do what") ----

    /** The chair held for an operator after an e-stop pressed and released under a task. */
    private void heldForAnOperator() {
        readings(3, false);
        taskUnderWay();
        readings(1, true);
        readings(3, false);
        assertEquals(ChairSupervisor.State.HELD, supervisor.state());
    }

    private AclMessage ask(String sender, String order) {
        AclMessage ask = new AclMessage(Performative.REQUEST).setSender(new AID(sender));
        ask.setContent(new ResumeRequest("mallory", order).encode());
        holds.resumeAsked(ask);
        return sent.get(sent.size() - 1);
    }

    @Test
    void aKeyHoldersResumeWithoutAnOperatorsOrderIsRefusedLoggedAndCounted() {
        heldForAnOperator();
        AclMessage answer = ask("mallory@test", null);
        assertEquals(Performative.REFUSE, answer.getPerformative());
        assertTrue(WheelchairMessage.reasonOf(answer).contains("only an operator may resume chair1"), answer.getContent());
        assertTrue(said.stream().anyMatch(l -> l.startsWith("refuses the resume of chair1 asked by mallory@test")), said.toString());
        assertEquals(1L, authority.refusals().get("unsigned"));
        readings(3, false);
        assertEquals(ChairSupervisor.State.HELD, supervisor.state(), "still held");
    }

    @Test
    void withoutTheAuthorityDefenceAKeyHoldersResumeResumesTheChair() {
        authority.policy(Policy.allowingEverything());
        heldForAnOperator();
        assertEquals(Performative.INFORM, ask("mallory@test", null).getPerformative());
        readings(3, false);
        assertTrue(supervisor.armed(), "the hazard: a key holder resumed a chair held for an operator");
    }

    @Test
    void anAgentOfAnotherPlatformIsRefusedEvenWithAnOperatorsOrder() {
        heldForAnOperator();
        AclMessage answer = ask("killer@elsewhere", ADA.sign("resume", "chair1", nowMs).encode());
        assertEquals(Performative.REFUSE, answer.getPerformative());
        assertTrue(WheelchairMessage.reasonOf(answer).contains("an agent of another platform may not use the chair's resume"), answer.getContent());
        assertEquals(1L, authority.refusals().get("foreign"));
    }

    @Test
    void anOperatorsSignedOrderCarriedByAMemberResumesTheChairOnceOnly() {
        heldForAnOperator();
        String order = ADA.sign("resume", "chair1", nowMs).encode();
        assertEquals(Performative.INFORM, ask("console@test", order).getPerformative());
        assertTrue(said.contains("resume decided by nurse Ada (mallory) via console"), said.toString());
        readings(3, false);
        assertTrue(supervisor.armed());

        readings(1, true);
        readings(3, false);
        assertEquals(ChairSupervisor.State.HELD, supervisor.state());
        AclMessage again = ask("console@test", order);
        assertEquals(Performative.REFUSE, again.getPerformative(), "the same order a second time");
        assertTrue(WheelchairMessage.reasonOf(again).contains("a replay"), again.getContent());
    }

    @Test
    void aTamperedStaleForeignKeyedOrAnotherChairsOrderIsRefused() {
        heldForAnOperator();
        SignedOrder good = ADA.sign("resume", "chair1", nowMs);
        SignedOrder tampered = new SignedOrder(good.action(), "chair1", good.operator(), good.atMs() + 1, good.nonce(), good.signature());
        assertTrue(WheelchairMessage.reasonOf(ask("console@test", tampered.encode())).contains("forged, or changed"));
        SignedOrder otherChair = ADA.sign("resume", "chair2", nowMs);
        assertTrue(WheelchairMessage.reasonOf(ask("console@test", otherChair.encode())).contains("not to resume chair1"));
        SignedOrder stale = ADA.sign("resume", "chair1", nowMs - Operators.MAX_AGE_MS - 1);
        assertTrue(WheelchairMessage.reasonOf(ask("console@test", stale.encode())).contains("s old"));
        SignedOrder stranger = OperatorKey.generate("nurse Ada").sign("resume", "chair1", nowMs);
        assertTrue(WheelchairMessage.reasonOf(ask("console@test", stranger.encode())).contains("forged, or changed"),
                "a key of the same name that the ward does not know");
        assertTrue(WheelchairMessage.reasonOf(ask("console@test", "resume chair1 please")).contains("an order is written"));
        assertEquals(5L, authority.refusals().get("bad-order"));
        readings(3, false);
        assertEquals(ChairSupervisor.State.HELD, supervisor.state());
    }

    /** The control agent resumes after a lost link twice; the third loss within 10 minutes waits for an operator, task or not. */
    @Test
    void aLinkLostAThirdTimeWithinTheWindowIsLeftToAnOperatorEvenWithNoTask() {
        readings(3, false);
        taskUnderWay();
        for (int i = 1; i <= 2; i++) {
            chair.link(false);
            chair.link(true);
            readings(2, false);
            assertTrue(supervisor.armed(), "loss " + i + ": the agent resumed");
        }
        chair.link(false);
        chair.link(true);
        readings(5, false);
        assertEquals(ChairSupervisor.State.HELD, supervisor.state());
        Paused p = (Paused) WheelchairMessage.decode(sent.get(sent.size() - 1));
        assertFalse(p.agentResumes(), "the Medical agent is told an operator resumes: " + p);
        assertTrue(said.stream().anyMatch(l -> l.contains("the 3rd link loss within 10 minutes: an operator must resume it")), said.toString());
        work = false;
        active = null;
        readings(5, false);
        assertEquals(ChairSupervisor.State.HELD, supervisor.state(), "no task either: the next task would meet the same fault");
        assertNull(holds.resumeOrdered(ADA.sign("resume", "chair1", nowMs).encode()));
        readings(2, false);
        assertTrue(supervisor.armed());
    }
}
