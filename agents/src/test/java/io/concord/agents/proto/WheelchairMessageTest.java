package io.concord.agents.proto;

import io.concord.agents.proto.WheelchairMessage.*;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import org.junit.jupiter.api.Test;

import java.lang.reflect.Proxy;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import static io.concord.core.acl.Performative.*;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The one codec of the wheelchair's messages: every record's text, both ways, and what a bad text is told. */
class WheelchairMessageTest {

    /** A record, the performative it goes under, and its text on the wire (docs/wheelchair-protocol.md's examples). */
    private record Case(WheelchairMessage message, Performative performative, String text) {
    }

    private static final List<Case> CASES = List.of(
            new Case(new TransportCall("T1", 3, 9, 3, 60), CFP, "transport; task=T1; from=3; to=9; priority=3.00; unload=60.00"),
            new Case(new TransportRequest(3, 9, 1.5, 30), REQUEST, "transport; from=3; to=9; priority=1.50; unload=30.00"),
            new Case(new TransportRequest(3, 9, 1.5, 30), AGREE, "transport; from=3; to=9; priority=1.50; unload=30.00"),
            new Case(new Proposal("T2", 273.47, 134.86, 60, List.of(new Proposal.Pending("T1", 177.4), new Proposal.Pending("T3", 139.5))),
                    PROPOSE, "proposal; task=T2; cost=273.47; path=134.86; unload=60.00; pending=T1:177.4,T3:139.5"),
            new Case(new Proposal("T1", 12.5, 8, 0, List.of()), PROPOSE, "proposal; task=T1; cost=12.50; path=8.00; unload=0.00"),
            new Case(new Refused("T1", null, "chair1 has its e-stop pressed", true), REFUSE,
                    "refuse; task=T1; reason=chair1 has its e-stop pressed; unavailable=true"),
            new Case(new Refused("T1/pickup", null, "unknown node 99", false), REFUSE, "refuse; task=T1/pickup; reason=unknown node 99"),
            new Case(new Refused(null, "WB", "offline", false), REFUSE, "refuse; door=WB; reason=offline"),
            new Case(Refused.because("chair1 is offline"), REFUSE, "refuse; reason=chair1 is offline"),
            new Case(new Award("T1"), ACCEPT_PROPOSAL, "transport; task=T1"),
            new Case(new Rejection("T1"), REJECT_PROPOSAL, "transport; task=T1"),
            new Case(new Withdrawal("T4"), CANCEL, "transport; task=T4"),
            new Case(new Done("T1", 9, null, null), INFORM, "done; task=T1; node=9"),
            new Case(new Done("T1", null, "chair1", ""), INFORM, "done; task=T1; chair=chair1; reason="),
            new Case(new Failed("T1", null, "chair1 has been offline for 30.0 s"), FAILURE,
                    "failed; task=T1; reason=chair1 has been offline for 30.0 s"),
            new Case(new Failed("T2", "null", "no chair proposed"), FAILURE, "failed; task=T2; chair=null; reason=no chair proposed"),
            new Case(new Paused("T1", "chair1", "the e-stop is pressed", false), INFORM,
                    "paused; task=T1; chair=chair1; reason=the e-stop is pressed; resume=operator"),
            new Case(new Resumed("T1", "chair1", "decided by nurse Ada", true), INFORM,
                    "resumed; task=T1; chair=chair1; reason=decided by nurse Ada; resume=agent"),
            new Case(new Progress("T1", "chair1", "to-pickup", 22, null), INFORM, "progress; task=T1; chair=chair1; phase=to-pickup; node=22"),
            new Case(new Progress("T1", "chair1", "to-dropoff", 7, "its route (held by chair2)"), INFORM,
                    "progress; task=T1; chair=chair1; phase=to-dropoff; node=7; waits=its route (held by chair2)"),
            new Case(new ResumeRequest("nurse Ada"), REQUEST, "resume; by=nurse Ada"),
            new Case(new ResumeRequest(null), REQUEST, "resume"),
            new Case(new Resuming("chair1"), INFORM, "resuming; chair=chair1"),
            new Case(new PlanRequest("T1/pickup", 19, 3, null), REQUEST, "plan; task=T1/pickup; from=19; to=3"),
            new Case(new PlanRequest("make-way", 26, 25, null, List.of(26, 10, 25)), REQUEST, "plan; task=make-way; from=26; to=25; via=26,10,25"),
            new Case(new PlanRequest("T1/pickup", 19, 3, "control-chair1@hospital"), REQUEST,
                    "plan; task=T1/pickup; from=19; to=3; chair=control-chair1@hospital"),
            new Case(new PlanAgreed("T1/pickup"), AGREE, "plan; task=T1/pickup"),
            new Case(new Plan("T1/pickup", List.of(19, 22, 7, 6, 5, 4, 2, 3), List.of("WA", "A2"), 23.4), INFORM_REF,
                    "plan; task=T1/pickup; nodes=19,22,7,6,5,4,2,3; doors=WA,A2; length=23.40"),
            new Case(new Plan("T1/dropoff", List.of(3, 9), List.of(), 4.25), INFORM_REF, "plan; task=T1/dropoff; nodes=3,9; doors=; length=4.25"),
            new Case(new NoRoute("T1/dropoff", "no route from 3 to 9 avoiding doors [WB]"), FAILURE,
                    "no-route; task=T1/dropoff; reason=no route from 3 to 9 avoiding doors [WB]"),
            new Case(new NoRoute(null, "the planner did not answer within 10 s"), FAILURE,
                    "no-route; reason=the planner did not answer within 10 s"),
            new Case(new Blocked(7, 8), INFORM, "blocked; from=7; to=8"),
            new Case(new StateQuery(), SUBSCRIBE, "state"),
            new Case(new StateQuery(), REQUEST, "state"),
            new Case(new DoorState("WA", "closed", 0, 20, 10.8), AGREE, "state; door=WA; state=closed; open=0.00; x=20.00; y=10.80"),
            new Case(new DoorState("WA", "opening", 0.25, 20, 10.8), INFORM, "state; door=WA; state=opening; open=0.25; x=20.00; y=10.80"),
            new Case(new PassRequest("control-chair1@hospital", "T1/pickup"), REQUEST, "pass; chair=control-chair1@hospital; task=T1/pickup"),
            new Case(new PassConfirmed("WA", "control-chair1@hospital"), CONFIRM, "pass; door=WA; chair=control-chair1@hospital"),
            new Case(new OpenRequest("chair1"), REQUEST, "open; body=chair1"),
            new Case(new OpenQueued("WA", 2), AGREE, "open; door=WA; queue=2"),
            new Case(new DoorOpen("WA"), INFORM, "open; door=WA"),
            new Case(new Failure("WA", null, "offline"), FAILURE, "failure; door=WA; reason=offline"),
            new Case(new Failure(null, 22, "chair2 is silent and stands on the route"), FAILURE,
                    "failure; node=22; reason=chair2 is silent and stands on the route"),
            new Case(new Failure(null, null, "make-way"), FAILURE, "failure; reason=make-way"),
            new Case(new Passed("chair1"), INFORM, "passed; body=chair1"),
            new Case(new Here("chair1", null), INFORM, "here; body=chair1"),
            new Case(new Here(null, List.of(7, 8)), INFORM, "here; at=7,8"),
            new Case(new Here(null, null), INFORM, "here"),
            new Case(new Reserve(List.of(7), List.of(7, 8, 10, 26), false), REQUEST, "reserve; at=7; path=7,8,10,26"),
            new Case(new Reserve(List.of(26), List.of(26, 10, 25), true), REQUEST, "reserve; at=26; path=26,10,25; aside=true"),
            new Case(new Granted(List.of(7, 8, 10, 26)), INFORM, "granted; path=7,8,10,26"),
            new Case(new Granted(List.of(7, 8, 10, 26), 8), INFORM, "granted; path=7,8,10,26; upto=8"),
            new Case(new Clear(26), INFORM, "clear; upto=26"),
            new Case(new ReserveWaits(List.of("control-chair2")), AGREE, "reserve; held-by=control-chair2"),
            new Case(new Release(7), INFORM, "release; node=7"),
            new Case(new Idle(List.of(26)), INFORM, "idle; at=26"),
            new Case(new MakeWay(26, 25, List.of(10, 25)), INFORM, "make-way; from=26; to=25; path=10,25"));

    @Test
    void everyRecordIsWrittenAsTheProtocolSaysAndReadBackEqual() {
        for (Case c : CASES) {
            assertEquals(c.text(), c.message().encode(), c.message().toString());
            assertEquals(c.message(), WheelchairMessage.decode(c.text(), c.performative()), c.text());
            assertEquals(c.text().split(";")[0], c.message().verb(), c.text());
        }
    }

    @Test
    void everyRecordAndEveryPerformativeItGoesUnderHasACase() {
        Set<String> covered = new HashSet<>();
        for (Case c : CASES) {
            covered.add(c.message().getClass().getSimpleName() + " " + c.performative());
        }
        Set<String> all = new HashSet<>();
        for (Class<?> kind : WheelchairMessage.class.getPermittedSubclasses()) {
            for (Performative p : Codec.under(kind)) {
                all.add(kind.getSimpleName() + " " + p);
            }
        }
        assertEquals(Codec.kinds(), new HashSet<>(Arrays.asList(WheelchairMessage.class.getPermittedSubclasses())),
                "every record is in the codec's table");
        assertEquals(all, covered);
    }

    @Test
    void numbersAreWrittenAsTheAgentsAlwaysWroteThemAndValuesHoldNoSemicolon() {
        assertEquals("proposal; task=T1; cost=0.67; path=1234.57; unload=60.00; pending=T2:0.3",
                new Proposal("T1", 2.0 / 3, 1234.567, 60, List.of(new Proposal.Pending("T2", 1.0 / 3))).encode());
        assertEquals("paused; task=T1; chair=chair1; reason=held: e-stop, it waits for an operator's resume; resume=operator",
                new Paused("T1", "chair1", "held: e-stop; it waits for an operator's resume", false).encode());
        assertEquals("failed; task=T1; reason=two lines", new Failed("T1", null, "two\nlines").encode());
    }

    @Test
    void aTextThatDoesNotReadIsUnreadable() {
        assertEquals("empty content", assertThrows(Unreadable.class, () -> WheelchairMessage.decode("", INFORM)).getMessage());
        assertEquals("empty content", assertThrows(Unreadable.class, () -> WheelchairMessage.decode(null, REQUEST)).getMessage());
        assertEquals("field 'nonsense' is not key=value",
                assertThrows(Unreadable.class, () -> WheelchairMessage.decode("transport; nonsense", REQUEST)).getMessage());
        assertEquals("content must start with a verb, got 'traffic knows all'",
                assertThrows(Unreadable.class, () -> WheelchairMessage.decode("traffic knows all", INFORM)).getMessage());
    }

    @Test
    void aWordUnknownUnderItsPerformativeIsNamed() {
        UnknownWord e = assertThrows(UnknownWord.class, () -> WheelchairMessage.decode("granted; path=1,2", REQUEST));
        assertEquals("no word 'granted' under REQUEST", e.getMessage());
        assertEquals("granted", e.verb());
        assertEquals("no word 'open' under CONFIRM",
                assertThrows(UnknownWord.class, () -> WheelchairMessage.decode("open; door=WA", CONFIRM)).getMessage());
        assertEquals("no word 'refuse' under FAILURE",
                assertThrows(UnknownWord.class, () -> WheelchairMessage.decode("refuse; reason=x", FAILURE)).getMessage());
    }

    @Test
    void aFieldMissingOrNotANumberIsNamed() {
        assertBad("'transport' needs a field 'from'", "transport; task=T1; to=9", CFP);
        assertBad("'transport' needs a field 'task'", "transport; from=3; to=9", CFP);
        assertBad("field 'from' must be a whole number, got 'three'", "transport; task=t1; from=three; to=9", CFP);
        assertBad("field 'unload' must be a number, got 'long'", "transport; from=3; to=9; unload=long", REQUEST);
        assertBad("field 'cost' must be a number, got 'much'", "proposal; task=T1; cost=much; path=1; unload=2", PROPOSE);
        assertBad("'refuse' needs a field 'reason'", "refuse; task=T1", REFUSE);
        assertBad("path: 'x' is not a node id", "reserve; at=7; path=7,x", REQUEST);
        assertBad("nodes: '2.5' is not a node id", "plan; task=T; nodes=1,2.5; doors=; length=3", INFORM_REF);
        assertBad("field 'node' must be a whole number, got 'two'", "failure; node=two; reason=x", FAILURE);
        assertBad("field 'resume' must be agent or operator, got 'nobody'",
                "paused; task=T1; chair=chair1; reason=r; resume=nobody", INFORM);
        assertBad("pending: 'T1' is not task:seconds", "proposal; task=T2; cost=1; path=1; unload=1; pending=T1", PROPOSE);
        assertBad("'plan' needs a field 'task'", "plan; from=19; to=3", REQUEST);
        // The planner has always checked from and to before the task.
        assertBad("field 'from' must be a whole number, got 'x'", "plan; from=x; to=3", REQUEST);
    }

    private static void assertBad(String what, String text, Performative p) {
        assertEquals(what, assertThrows(BadField.class, () -> WheelchairMessage.decode(text, p)).getMessage(), text);
    }

    @Test
    void absentOptionalFieldsAreNullOrTheirDefaults() {
        assertEquals(new TransportCall("T1", 3, 9, 0, 0), WheelchairMessage.decode("transport; task=T1; from=3; to=9", CFP));
        assertEquals(new TransportRequest(3, 9, 0, 60), WheelchairMessage.decode("transport; from=3; to=9", REQUEST));
        assertEquals(new PassRequest(null, null), WheelchairMessage.decode("pass", REQUEST));
        assertEquals(new Here(null, List.of()), WheelchairMessage.decode("here; at=", INFORM), "at said, but empty");
        assertFalse(((Reserve) WheelchairMessage.decode("reserve; at=1; path=1,2; aside=yes", REQUEST)).aside());
    }

    @Test
    void aReplyOfAKnownKindIsDecodedAsThatKindOrNotAtAll() {
        AclMessage plan = new AclMessage(INFORM_REF).setContent("plan; task=T; nodes=1,2; doors=; length=3.00");
        assertEquals(List.of(1, 2), WheelchairMessage.decode(plan, Plan.class).nodes());
        AclMessage none = new AclMessage(FAILURE).setContent("no-route; reason=no node 99");
        assertEquals("expected Plan, got 'no-route' under FAILURE",
                assertThrows(IllegalArgumentException.class, () -> WheelchairMessage.decode(none, Plan.class)).getMessage());
        assertEquals("no node 99", WheelchairMessage.reasonOf(none));
        assertNull(WheelchairMessage.reasonOf(plan));
        assertNull(WheelchairMessage.reasonOf(new AclMessage(NOT_UNDERSTOOD).setContent("a planner knows 'plan'")));
    }

    @Test
    void eachRecordGoesToItsOwnHandlerMethod() {
        for (Case c : CASES) {
            List<String> called = new ArrayList<>();
            Handler h = (Handler) Proxy.newProxyInstance(getClass().getClassLoader(), new Class<?>[] {Handler.class},
                    (proxy, method, args) -> {
                        called.add(method.getName());
                        return null;
                    });
            c.message().to(h, new AclMessage(c.performative()));
            assertEquals(List.of("on" + c.message().getClass().getSimpleName()), called);
        }
    }

    @Test
    void aHandlerGetsTheWordsItDoesNotTakeAsUnknown() {
        List<String> unknown = new ArrayList<>();
        Handler h = new Handler() {
            @Override
            public void unknown(String verb, AclMessage m) {
                unknown.add(verb);
            }

            @Override
            public void onRelease(Release r, AclMessage m) {
                unknown.add("released " + r.node());
            }
        };
        List<AclMessage> sent = new ArrayList<>();
        WheelchairMessage.dispatch(new AclMessage(INFORM).setContent("release; node=7"), h, sent::add);
        WheelchairMessage.dispatch(new AclMessage(INFORM).setContent("make-way; from=1; to=2; path=2"), h, sent::add);
        WheelchairMessage.dispatch(new AclMessage(REQUEST).setContent("teleport; to=9"), h, sent::add);
        assertEquals(List.of("released 7", "make-way", "teleport"), unknown);
        assertTrue(sent.isEmpty());
    }

    @Test
    void aRequestThatDoesNotDecodeIsAnsweredAsTheProtocolSays() {
        List<AclMessage> sent = new ArrayList<>();
        Handler ignore = new Handler() { };
        WheelchairMessage.dispatch(request("reserve at 7"), ignore, sent::add);
        assertEquals(NOT_UNDERSTOOD, sent.get(0).getPerformative());
        assertEquals("content must start with a verb, got 'reserve at 7'", sent.get(0).getContent());

        WheelchairMessage.dispatch(request("plan; task=T1; from=19; to=x"), ignore, sent::add);
        assertEquals(REFUSE, sent.get(1).getPerformative());
        assertEquals("refuse; reason=field 'to' must be a whole number, got 'x'", sent.get(1).getContent());

        WheelchairMessage.dispatch(new AclMessage(INFORM).setContent("release node 7"), ignore, sent::add);
        WheelchairMessage.dispatch(new AclMessage(INFORM).setContent("release; node=seven"), ignore, sent::add);
        assertEquals(2, sent.size(), "an INFORM is not answered");
    }

    private static AclMessage request(String content) {
        return new AclMessage(REQUEST).setSender(AID.local("asker", "test")).setContent(content);
    }

    @Test
    void aTemplateMatchesItsWordUnderItsPerformativesWhetherOrNotTheRestDecodes() {
        var makeWay = WheelchairMessage.matching(MakeWay.class);
        assertTrue(makeWay.match(new AclMessage(INFORM).setContent("make-way; from=1; to=2; path=2")));
        assertTrue(makeWay.match(new AclMessage(INFORM).setContent("make-way; from=x")));
        assertFalse(makeWay.match(new AclMessage(REQUEST).setContent("make-way; from=1; to=2; path=2")));
        assertFalse(makeWay.match(new AclMessage(INFORM).setContent("granted; path=1")));
        assertFalse(makeWay.match(new AclMessage(INFORM)));
        var state = WheelchairMessage.matching(StateQuery.class);
        assertTrue(state.match(new AclMessage(SUBSCRIBE).setContent("state")));
        assertTrue(state.match(new AclMessage(REQUEST).setContent("state")));
        assertFalse(state.match(new AclMessage(INFORM).setContent("state")));
        assertInstanceOf(DoorState.class, WheelchairMessage.decode("state; door=A; state=open; open=1; x=0; y=0", INFORM));
    }

    /** The patient is on board from the moment the chair is at the pick-up; a phase not in the protocol is refused. */
    @Test
    void aProgressReportSaysWhetherThePatientIsOnBoard() {
        assertFalse(new Progress("T1", "chair1", "to-pickup", 22, null).patientOnBoard());
        for (String phase : List.of("loading", "to-dropoff", "unloading")) {
            assertTrue(new Progress("T1", "chair1", phase, 3, null).patientOnBoard(), phase);
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> WheelchairMessage.decode("progress; task=T1; chair=chair1; phase=flying; node=3", INFORM));
        assertTrue(e.getMessage().contains("phase"), e.getMessage());
    }
}
