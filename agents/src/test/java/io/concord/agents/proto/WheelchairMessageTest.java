package io.concord.agents.proto;

import io.concord.agents.proto.WheelchairMessage.*;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.content.AbsAggregate;
import io.concord.core.content.AbsCompound;
import io.concord.core.content.AbsObject;
import io.concord.core.content.AbsPrimitive;
import io.concord.core.content.AgentAction;
import io.concord.core.content.ContentManager;
import io.concord.core.content.Ontology;
import io.concord.core.content.Schema;
import io.concord.core.content.SlCodec;
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

/** The wheelchair's ontology and its one codec: every record's FIPA-SL text, both ways, and what a bad text is told. */
class WheelchairMessageTest {

    /** A record, the performative it goes under, and its text on the wire (docs/wheelchair-protocol.md's examples). */
    private record Case(WheelchairMessage message, Performative performative, String text) {
    }

    private static final List<Case> CASES = List.of(
            new Case(new TransportCall("T1", 3, 9, 3, 60), CFP, "((transport-call :from 3 :priority 3.0 :task T1 :to 9 :unload 60.0))"),
            new Case(new TransportRequest(3, 9, 1.5, 30), REQUEST, "((transport-request :from 3 :priority 1.5 :to 9 :unload 30.0))"),
            new Case(new TransportRequest(3, 9, 1.5, 30), AGREE, "((transport-request :from 3 :priority 1.5 :to 9 :unload 30.0))"),
            new Case(new Proposal("T2", 273.47, 134.86, 60, List.of(new Proposal.Pending("T1", 177.4), new Proposal.Pending("T3", 139.5))), PROPOSE, "((proposal :cost 273.47 :path 134.86 :pending (sequence (pending :seconds 177.4 :task T1) (pending :seconds 139.5 :task T3)) :task T2 :unload 60.0))"),
            new Case(new Proposal("T1", 12.5, 8, 0, List.of()), PROPOSE, "((proposal :cost 12.5 :path 8.0 :task T1 :unload 0.0))"),
            new Case(new Refused("T1", null, "chair1 has its e-stop pressed", true), REFUSE, "((refused :reason \"chair1 has its e-stop pressed\" :task T1 :unavailable true))"),
            new Case(new Refused("T1/pickup", null, "unknown node 99", false), REFUSE, "((refused :reason \"unknown node 99\" :task T1/pickup :unavailable false))"),
            new Case(new Refused(null, "WB", "offline", false), REFUSE, "((refused :door WB :reason offline :unavailable false))"),
            new Case(Refused.because("chair1 is offline"), REFUSE, "((refused :reason \"chair1 is offline\" :unavailable false))"),
            new Case(new Award("T1"), ACCEPT_PROPOSAL, "((award :task T1))"),
            new Case(new Rejection("T1"), REJECT_PROPOSAL, "((rejection :task T1))"),
            new Case(new Withdrawal("T4"), CANCEL, "((withdrawal :task T4))"),
            new Case(new CancelRequest("T4", "the patient went home"), REQUEST, "((cancel-request :reason \"the patient went home\" :task T4))"),
            new Case(new CancelRequest("T4", null), AGREE, "((cancel-request :task T4))"),
            new Case(new Done("T1", 9, null, null), INFORM, "((transport-done :node 9 :task T1))"),
            new Case(new Done("T1", null, "chair1", ""), INFORM, "((transport-done :chair chair1 :reason \"\" :task T1))"),
            new Case(new Failed("T1", null, "chair1 has been offline for 30.0 s"), FAILURE, "((transport-failed :reason \"chair1 has been offline for 30.0 s\" :task T1))"),
            new Case(new Failed("T2", "null", "no chair proposed"), FAILURE, "((transport-failed :chair null :reason \"no chair proposed\" :task T2))"),
            new Case(new Paused("T1", "chair1", "the e-stop is pressed", false), INFORM, "((paused :agent-resumes false :chair chair1 :reason \"the e-stop is pressed\" :task T1))"),
            new Case(new Resumed("T1", "chair1", "decided by nurse Ada", true), INFORM, "((resumed :agent-resumes true :chair chair1 :reason \"decided by nurse Ada\" :task T1))"),
            new Case(new Progress("T1", "chair1", "to-pickup", 22, null), INFORM, "((progress :chair chair1 :node 22 :phase to-pickup :task T1))"),
            new Case(new Progress("T1", "chair1", "to-dropoff", 7, "its route (held by chair2)"), INFORM, "((progress :chair chair1 :node 7 :phase to-dropoff :task T1 :waits \"its route (held by chair2)\"))"),
            new Case(new ResumeRequest("nurse Ada"), REQUEST, "((resume-request :by \"nurse Ada\"))"),
            new Case(new ResumeRequest(null), REQUEST, "((resume-request))"),
            new Case(new Resuming("chair1"), INFORM, "((resuming :chair chair1))"),
            new Case(new PlanRequest("T1/pickup", 19, 3, null), REQUEST, "((plan-request :from 19 :task T1/pickup :to 3))"),
            new Case(new PlanRequest("make-way", 26, 25, null, List.of(26, 10, 25)), REQUEST, "((plan-request :from 26 :task make-way :to 25 :via (sequence 26 10 25)))"),
            new Case(new PlanRequest("T1/pickup", 19, 3, "control-chair1@hospital"), REQUEST, "((plan-request :chair control-chair1@hospital :from 19 :task T1/pickup :to 3))"),
            new Case(new PlanAgreed("T1/pickup"), AGREE, "((plan-agreed :task T1/pickup))"),
            new Case(new Plan("T1/pickup", List.of(19, 22, 7, 6, 5, 4, 2, 3), List.of("WA", "A2"), 23.4), INFORM_REF, "((plan :doors (sequence WA A2) :length 23.4 :nodes (sequence 19 22 7 6 5 4 2 3) :task T1/pickup))"),
            new Case(new Plan("T1/dropoff", List.of(3, 9), List.of(), 4.25), INFORM_REF, "((plan :length 4.25 :nodes (sequence 3 9) :task T1/dropoff))"),
            new Case(new NoRoute("T1/dropoff", "no route from 3 to 9 avoiding doors [WB]"), FAILURE, "((no-route :reason \"no route from 3 to 9 avoiding doors [WB]\" :task T1/dropoff))"),
            new Case(new NoRoute(null, "the planner did not answer within 10 s"), FAILURE, "((no-route :reason \"the planner did not answer within 10 s\"))"),
            new Case(new Blocked(7, 8), INFORM, "((blocked :from 7 :to 8))"),
            new Case(new StateQuery(), SUBSCRIBE, "((state-query))"),
            new Case(new StateQuery(), REQUEST, "((state-query))"),
            new Case(new DoorState("WA", "closed", 0, 20, 10.8), AGREE, "((door-state :door WA :open 0.0 :state closed :x 20.0 :y 10.8))"),
            new Case(new DoorState("WA", "opening", 0.25, 20, 10.8), INFORM, "((door-state :door WA :open 0.25 :state opening :x 20.0 :y 10.8))"),
            new Case(new PassRequest("control-chair1@hospital", "T1/pickup"), REQUEST, "((pass-request :chair control-chair1@hospital :task T1/pickup))"),
            new Case(new PassConfirmed("WA", "control-chair1@hospital"), CONFIRM, "((pass-confirmed :chair control-chair1@hospital :door WA))"),
            new Case(new OpenRequest("chair1"), REQUEST, "((open-request :body chair1))"),
            new Case(new OpenQueued("WA", 2), AGREE, "((open-queued :door WA :queue 2))"),
            new Case(new DoorOpen("WA"), INFORM, "((door-open :door WA))"),
            new Case(new Failure("WA", null, "offline"), FAILURE, "((failure :door WA :reason offline))"),
            new Case(new Failure(null, 22, "chair2 is silent and stands on the route"), FAILURE, "((failure :node 22 :reason \"chair2 is silent and stands on the route\"))"),
            new Case(new Failure(null, null, "make-way"), FAILURE, "((failure :reason make-way))"),
            new Case(new Passed("chair1"), INFORM, "((passed :body chair1))"),
            new Case(new Here("chair1", null), INFORM, "((here :body chair1))"),
            new Case(new Here(null, List.of(7, 8)), INFORM, "((here :at (sequence 7 8)))"),
            new Case(new Here(null, null), INFORM, "((here))"),
            new Case(new Reserve(List.of(7), List.of(7, 8, 10, 26), false), REQUEST, "((reserve :aside false :at (sequence 7) :path (sequence 7 8 10 26)))"),
            new Case(new Reserve(List.of(26), List.of(26, 10, 25), true), REQUEST, "((reserve :aside true :at (sequence 26) :path (sequence 26 10 25)))"),
            new Case(new Granted(List.of(7, 8, 10, 26)), INFORM, "((granted :path (sequence 7 8 10 26)))"),
            new Case(new Granted(List.of(7, 8, 10, 26), 8), INFORM, "((granted :path (sequence 7 8 10 26) :upto 8))"),
            new Case(new Clear(26), INFORM, "((clear :upto 26))"),
            new Case(new ReserveWaits(List.of("control-chair2")), AGREE, "((reserve-waits :held-by (sequence control-chair2)))"),
            new Case(new WaitEstimate(List.of(7, 8, 10), null), QUERY_REF, "((wait-estimate :path (sequence 7 8 10)))"),
            new Case(new WaitEstimate(List.of(7, 8, 10), 12.5), INFORM_REF, "((wait-estimate :path (sequence 7 8 10) :seconds 12.5))"),
            new Case(new Release(7), INFORM, "((release :node 7))"),
            new Case(new Idle(List.of(26)), INFORM, "((idle :at (sequence 26)))"),
            new Case(new MakeWay(26, 25, List.of(10, 25)), INFORM, "((make-way :from 26 :path (sequence 10 25) :to 25))"),
            new Case(new Stalled("control-chair2@hospital", 120, "its turn at node 8 (ahead: [control-chair1])"), INFORM,
                    "((stalled :chair control-chair2@hospital :seconds 120 :waits \"its turn at node 8 (ahead: [control-chair1])\"))"));

    @Test
    void everyRecordIsWrittenAsTheProtocolSaysAndReadBackEqual() {
        for (Case c : CASES) {
            assertEquals(c.text(), c.message().encode(), c.message().toString());
            assertEquals(c.message(), WheelchairMessage.decode(c.text(), c.performative()), c.text());
            assertTrue(c.text().startsWith("((" + c.message().verb() + " ") || c.text().equals("((" + c.message().verb() + "))"), c.text());
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

    /** The ontology: one schema a record (and the proposal's pending items), each named as its record says, checked as it is read. */
    @Test
    void theOntologyHasASchemaForEveryRecordWithItsSlotsAndFacets() {
        Ontology o = Codec.ONTOLOGY;
        assertEquals(Services.ONTOLOGY, o.name());
        for (Class<?> kind : WheelchairMessage.class.getPermittedSubclasses()) {
            Schema s = o.schema(Codec.verb(kind));
            assertEquals(kind, s.javaClass(), kind.getSimpleName());
            assertEquals(kind.getRecordComponents().length, s.slots().size(), kind.getSimpleName());
            assertEquals(AgentAction.class.isAssignableFrom(kind) ? Schema.Kind.AGENT_ACTION : Schema.Kind.CONCEPT, s.kind(), kind.getSimpleName());
        }
        assertEquals(WheelchairMessage.class.getPermittedSubclasses().length + 1, o.schemas().size(), "and the pending item");
        Schema call = o.schema("transport-call");
        assertTrue(call.slot("task").mandatory());
        assertTrue(call.slot("from").mandatory(), "a whole number is mandatory");
        Schema done = o.schema("transport-done");
        assertFalse(done.slot("chair").mandatory());
        assertEquals("sequence", o.schema("plan").slot("nodes").aggregate());
        assertEquals(Integer.class, o.schema("plan").slot("nodes").type());
    }

    /** What the key=value text could not carry: a ';', a '=', a line break, quotes, a backslash, no value at all. */
    @Test
    void anyTextTravelsUnchangedWhereTheOldTextTurnedSemicolonsIntoCommas() {
        for (String reason : List.of("held: e-stop; it waits for an operator's resume", "a=b", "two\nlines", "say \"stop\"", "C:\\ward", "", "(x)",
                "19", "?x", ":task T2")) {
            Paused p = new Paused("T1", "chair1", reason, false);
            assertEquals(p, WheelchairMessage.decode(p.encode(), INFORM), p.encode());
        }
        assertEquals("((paused :agent-resumes false :chair chair1 :reason \"held: e-stop; it waits\" :task T1))",
                new Paused("T1", "chair1", "held: e-stop; it waits", false).encode());
    }

    /** A third party that knows FIPA-SL and nothing of these records reads the same content as abstract objects. */
    @Test
    void theWireIsPlainFipaSlThatAnySlReaderReads() throws Exception {
        List<AbsObject> read = new SlCodec().read(new Proposal("T2", 273.47, 134.86, 60, List.of(new Proposal.Pending("T1", 177.4))).encode());
        AbsCompound proposal = (AbsCompound) read.get(0);
        assertEquals("proposal", proposal.name());
        assertEquals(new AbsPrimitive(273.47), proposal.get("cost"));
        AbsCompound pending = (AbsCompound) ((AbsAggregate) proposal.get("pending")).elements().get(0);
        assertEquals(new AbsPrimitive("T1"), pending.get("task"));
    }

    @Test
    void aTextThatDoesNotReadIsUnreadableAndSaysWhatToWrite() {
        assertEquals("empty content", assertThrows(Unreadable.class, () -> WheelchairMessage.decode("", INFORM)).getMessage());
        assertEquals("empty content", assertThrows(Unreadable.class, () -> WheelchairMessage.decode(null, REQUEST)).getMessage());
        assertEquals("content is not FIPA-SL (expected '(' at position 0); the wheelchair's contents are one element, such as "
                        + "((transport-request :from 3 :to 9)): docs/wheelchair-protocol.md",
                assertThrows(Unreadable.class, () -> WheelchairMessage.decode("transport; from=3; to=9", REQUEST)).getMessage(),
                "the old key=value text");
        assertTrue(assertThrows(Unreadable.class, () -> WheelchairMessage.decode("((a)) ((b))", INFORM)).getMessage()
                .contains("text after the content expression at position 6"));
        assertEquals("content must be one element, such as ((transport-request :from 3 :to 9)); got 2 element(s)",
                assertThrows(Unreadable.class, () -> WheelchairMessage.decode("((here) (here))", INFORM)).getMessage());
        assertEquals("content must be one element, such as ((transport-request :from 3 :to 9)); got 1 element(s)",
                assertThrows(Unreadable.class, () -> WheelchairMessage.decode("(\"here\")", INFORM)).getMessage());
    }

    @Test
    void aWordUnknownUnderItsPerformativeIsNamed() {
        UnknownWord e = assertThrows(UnknownWord.class, () -> WheelchairMessage.decode("((granted :path (sequence 1 2)))", REQUEST));
        assertEquals("no word 'granted' under REQUEST", e.getMessage());
        assertEquals("granted", e.verb());
        assertEquals("no word 'door-open' under CONFIRM",
                assertThrows(UnknownWord.class, () -> WheelchairMessage.decode("((door-open :door WA))", CONFIRM)).getMessage());
        assertEquals("no word 'refused' under FAILURE",
                assertThrows(UnknownWord.class, () -> WheelchairMessage.decode("((refused :reason x :unavailable false))", FAILURE)).getMessage());
        assertEquals("no word 'teleport' under REQUEST",
                assertThrows(UnknownWord.class, () -> WheelchairMessage.decode("((teleport :to 9))", REQUEST)).getMessage());
    }

    @Test
    void aSlotMissingOfTheWrongTypeOrRefusedIsNamed() {
        assertBad("missing mandatory slot :from of transport-call", "((transport-call :task T1 :to 9 :priority 1.0 :unload 2.0))", CFP);
        assertBad("missing mandatory slot :task of transport-call", "((transport-call :from 3 :to 9 :priority 1.0 :unload 2.0))", CFP);
        assertBad("slot :from of transport-call: expected integer, got string",
                "((transport-call :task t1 :from three :to 9 :priority 1.0 :unload 2.0))", CFP);
        assertBad("slot :unload of transport-request: expected float, got string", "((transport-request :from 3 :to 9 :unload long))", REQUEST);
        assertBad("slot :from of transport-request: expected integer, got float", "((transport-request :from 3.5 :to 9))", REQUEST);
        assertBad("unknown slot :colour of transport-request", "((transport-request :from 3 :to 9 :colour red))", REQUEST);
        assertBad("missing mandatory slot :reason of refused", "((refused :task T1 :unavailable false))", REFUSE);
        assertBad("slot :path of reserve: expected integer, got string", "((reserve :aside false :at (sequence 7) :path (sequence 7 x)))", REQUEST);
        assertBad("slot :nodes of plan: expected integer, got float", "((plan :task T :nodes (sequence 1 2.5) :length 3.0))", INFORM_REF);
        assertBad("slot :node of failure: expected integer, got string", "((failure :node two :reason x))", FAILURE);
        assertBad("slot :agent-resumes of paused: expected boolean, got string",
                "((paused :agent-resumes nobody :chair chair1 :reason r :task T1))", INFORM);
        assertBad("missing mandatory slot :task of pending",
                "((proposal :cost 1.0 :path 1.0 :pending (sequence (pending :seconds 1.0)) :task T2 :unload 1.0))", PROPOSE);
        assertBad("missing mandatory slot :task of plan-request", "((plan-request :from 19 :to 3))", REQUEST);
        assertBad("granted refused its slots: upto: node 5 is not on the path [1, 2]", "((granted :path (sequence 1 2) :upto 5))", INFORM);
        assertBad("slot :reason of refused: no schema in ontology concord-wheelchair for symbol x", "((refused :reason (x) :unavailable false))", REFUSE);
    }

    private static void assertBad(String what, String text, Performative p) {
        assertEquals(what, assertThrows(BadField.class, () -> WheelchairMessage.decode(text, p)).getMessage(), text);
    }

    @Test
    void absentOptionalFieldsAreNullOrTheirDefaults() {
        assertEquals(new TransportRequest(3, 9, 0, 60), WheelchairMessage.decode("((transport-request :from 3 :to 9))", REQUEST));
        assertEquals(new PassRequest(null, null), WheelchairMessage.decode("((pass-request))", REQUEST));
        assertEquals(new Here(null, List.of()), WheelchairMessage.decode("((here :at (sequence)))", INFORM), "at said, but empty");
        assertNull(((Here) WheelchairMessage.decode("((here))", INFORM)).at(), "at not said");
        assertEquals(List.of(), ((Plan) WheelchairMessage.decode("((plan :length 1.0 :nodes (sequence 1) :task T))", INFORM_REF)).doors());
        assertEquals(new TransportCall("T1", 3, 9, 1, 2), WheelchairMessage.decode("((transport-call :task T1 :from 3 :to 9 :priority 1 :unload 2))", CFP),
                "a whole number where a number is wanted");
    }

    @Test
    void aReplyOfAKnownKindIsDecodedAsThatKindOrNotAtAll() {
        AclMessage plan = new AclMessage(INFORM_REF).setContent("((plan :length 3.0 :nodes (sequence 1 2) :task T))");
        assertEquals(List.of(1, 2), WheelchairMessage.decode(plan, Plan.class).nodes());
        AclMessage none = new AclMessage(FAILURE).setContent("((no-route :reason \"no node 99\"))");
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
        WheelchairMessage.dispatch(new AclMessage(INFORM).setContent("((release :node 7))"), h, sent::add);
        WheelchairMessage.dispatch(new AclMessage(INFORM).setContent(new MakeWay(1, 2, List.of(2)).encode()), h, sent::add);
        WheelchairMessage.dispatch(new AclMessage(REQUEST).setContent("((teleport :to 9))"), h, sent::add);
        assertEquals(List.of("released 7", "make-way", "teleport"), unknown);
        assertTrue(sent.isEmpty());
    }

    @Test
    void aRequestThatDoesNotDecodeIsAnsweredAsTheProtocolSays() {
        List<AclMessage> sent = new ArrayList<>();
        Handler ignore = new Handler() { };
        WheelchairMessage.dispatch(request("reserve at 7"), ignore, sent::add);
        assertEquals(NOT_UNDERSTOOD, sent.get(0).getPerformative());
        assertTrue(sent.get(0).getContent().startsWith("content is not FIPA-SL (expected '(' at position 0)"), sent.get(0).getContent());

        WheelchairMessage.dispatch(request("((plan-request :task T1 :from 19 :to x))"), ignore, sent::add);
        assertEquals(REFUSE, sent.get(1).getPerformative());
        assertEquals("((refused :reason \"slot :to of plan-request: expected integer, got string\" :unavailable false))", sent.get(1).getContent());
        assertEquals(Refused.because("slot :to of plan-request: expected integer, got string"), WheelchairMessage.decode(sent.get(1)));

        WheelchairMessage.dispatch(new AclMessage(INFORM).setContent("release node 7"), ignore, sent::add);
        WheelchairMessage.dispatch(new AclMessage(INFORM).setContent("((release :node seven))"), ignore, sent::add);
        assertEquals(2, sent.size(), "an INFORM is not answered");
    }

    /** A REQUEST an agent does not take is answered, never left in its mailbox: what it takes, or what is wrong. */
    @Test
    void aRequestAnAgentDoesNotTakeIsAnsweredWithWhatItTakes() {
        List<AclMessage> sent = new ArrayList<>();
        String takes = "the Medical agent takes transport-request";
        WheelchairMessage.notTaken(request("((teleport :to 9))"), takes, sent::add);
        WheelchairMessage.notTaken(request("((plan-request :from 1 :task T :to 2))"), takes, sent::add);
        WheelchairMessage.notTaken(request("transport; from=3; to=9"), takes, sent::add);
        WheelchairMessage.notTaken(request("((plan-request :from x :task T :to 2))"), takes, sent::add);
        assertEquals(List.of(NOT_UNDERSTOOD, NOT_UNDERSTOOD, NOT_UNDERSTOOD, REFUSE), sent.stream().map(AclMessage::getPerformative).toList());
        assertEquals("unknown request 'teleport'; the Medical agent takes transport-request (docs/wheelchair-protocol.md)", sent.get(0).getContent());
        assertEquals("unknown request 'plan-request'; the Medical agent takes transport-request (docs/wheelchair-protocol.md)",
                sent.get(1).getContent(), "another agent's request");
        assertTrue(sent.get(2).getContent().startsWith("content is not FIPA-SL"), sent.get(2).getContent());
        assertEquals("slot :from of plan-request: expected integer, got string", WheelchairMessage.reasonOf(sent.get(3)));
    }

    @Test
    void aTransportRequestOutOfRangeIsRefusedWithTheRange() {
        assertBad("transport-request refused its slots: priority is 0 to 3 (the dissertation's TP: 0, 1.5 or 3), got 7.0",
                "((transport-request :from 3 :to 9 :priority 7.0))", REQUEST);
        assertBad("transport-request refused its slots: unload is 0 to 3600 s, got -1.0", "((transport-request :from 3 :to 9 :unload -1.0))", REQUEST);
    }

    /** A program of one's own reads the contents with core's content manager and the records' ontology. */
    @Test
    void aContentManagerReadsThemAsAbstractContentAndTheOntologyMakesTheRecords() throws Exception {
        ContentManager cm = new ContentManager().register(new SlCodec()).register(WheelchairMessage.ontology());
        AclMessage m = new AclMessage(INFORM).setLanguage(Services.LANGUAGE).setOntology(Services.ONTOLOGY)
                .setContent(new Progress("T1", "chair1", "loading", 3, null).encode());
        assertEquals(new Progress("T1", "chair1", "loading", 3, null), WheelchairMessage.ontology().fromAbs(cm.extractAbs(m).get(0)));
    }

    private static AclMessage request(String content) {
        return new AclMessage(REQUEST).setSender(AID.local("asker", "test")).setContent(content);
    }

    @Test
    void aTemplateMatchesItsElementUnderItsPerformativesWhetherOrNotTheRestDecodes() {
        var makeWay = WheelchairMessage.matching(MakeWay.class);
        assertTrue(makeWay.match(new AclMessage(INFORM).setContent("((make-way :from 1 :path (sequence 2) :to 2))")));
        assertTrue(makeWay.match(new AclMessage(INFORM).setContent("((make-way :from x")));
        assertFalse(makeWay.match(new AclMessage(REQUEST).setContent("((make-way :from 1 :path (sequence 2) :to 2))")));
        assertFalse(makeWay.match(new AclMessage(INFORM).setContent("((granted :path (sequence 1)))")));
        assertFalse(makeWay.match(new AclMessage(INFORM).setContent("((make-way-now))")), "another element that starts alike");
        assertFalse(makeWay.match(new AclMessage(INFORM)));
        var state = WheelchairMessage.matching(StateQuery.class);
        assertTrue(state.match(new AclMessage(SUBSCRIBE).setContent("((state-query))")));
        assertTrue(state.match(new AclMessage(REQUEST).setContent("((state-query))")));
        assertFalse(state.match(new AclMessage(INFORM).setContent("((state-query))")));
        assertInstanceOf(DoorState.class, WheelchairMessage.decode("((door-state :door A :state open :open 1 :x 0 :y 0))", INFORM));
    }

    /** The patient is on board from the moment the chair is at the pick-up; a phase not in the protocol is refused. */
    @Test
    void aProgressReportSaysWhetherThePatientIsOnBoard() {
        assertFalse(new Progress("T1", "chair1", "to-pickup", 22, null).patientOnBoard());
        for (String phase : List.of("loading", "to-dropoff", "unloading")) {
            assertTrue(new Progress("T1", "chair1", phase, 3, null).patientOnBoard(), phase);
        }
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> WheelchairMessage.decode("((progress :task T1 :chair chair1 :phase flying :node 3))", INFORM));
        assertTrue(e.getMessage().contains("phase"), e.getMessage());
    }
}
