package io.concord.sim.board;

import io.concord.agents.chair.ChairSupervisor;
import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.proto.Services;
import io.concord.agents.proto.WheelchairMessage;
import io.concord.agents.proto.WheelchairMessage.ResumeRequest;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.layers.Platform;
import io.concord.layers.authority.OperatorKey;
import io.concord.layers.defence.Defence;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import static io.concord.sim.board.ChairSafetyTest.moved;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The attack, end to end: the chair on the emulated board (a real pty) is held for an
 * operator after an e-stop pressed and released mid-transport; an agent that merely joined the
 * platform with its key ({@code mallory}, in another runtime, over real UDP) asks it to resume.
 * Only an operator's signed order resumes it; without the {@link Defence#AUTHORITY} defence,
 * mallory's request does.
 */
class ResumeAuthorityTest {

    /** A member of the platform that sends what the test gives it and keeps the answers. */
    static final class Member extends Agent {
        final BlockingQueue<AclMessage> answers = new LinkedBlockingQueue<>();

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour() {
                @Override
                public void action() {
                    AclMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                    } else {
                        answers.add(m);
                    }
                }
            });
        }

        /** The observation service's REQUEST kill, as the console sends it. */
        AclMessage kill(String who) throws InterruptedException {
            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(new AID(who));
            m.setOntology("concord-observe");
            m.setContent("kill");
            m.setConversationId("kill-" + who);
            return exchange(m);
        }

        private AclMessage exchange(AclMessage m) throws InterruptedException {
            runtime().execute(() -> send(m));
            AclMessage a = answers.poll(20, TimeUnit.SECONDS);
            assertNotNull(a, "answered");
            return a;
        }

        AclMessage ask(ResumeRequest r) throws InterruptedException {
            AclMessage m = new AclMessage(Performative.REQUEST);
            m.addReceiver(new AID("control-chair1@hospital"));
            m.setOntology(Services.ONTOLOGY);
            m.setLanguage(Services.LANGUAGE);
            m.setContent(r.encode());
            CompletableFuture<Void> sent = new CompletableFuture<>();
            runtime().execute(() -> {
                send(m);
                sent.complete(null);
            });
            AclMessage a = answers.poll(20, TimeUnit.SECONDS);
            assertNotNull(a, "the control agent answered");
            return a;
        }
    }

    /** The ward's chair held for an operator, and mallory joined from another runtime. */
    private static double heldAfterAnEstop(ChairSafetyTest.Ward w) throws Exception {
        w.transportUnderWay();
        w.board.command("estop on");
        w.awaitSaid("control-chair1: pauses T1: the e-stop was pressed", 10_000);
        double stopped = moved(w.afterHostFrames(10));
        w.board.command("estop off");
        w.afterHostFrames(10);
        assertEquals(ChairSupervisor.State.HELD, w.call(w.supervisor::state));
        return stopped;
    }

    private static Member join(Platform p) throws Exception {
        Member m = new Member();
        p.startAgent("mallory", m);
        // Listed by the ward's container: a message from an agent not in the lists is dropped (membership).
        long end = System.nanoTime() + 20_000_000_000L;
        while (System.nanoTime() < end && !listed(p)) {
            Thread.sleep(20);
        }
        assertTrue(listed(p), "mallory joined the platform");
        return m;
    }

    private static boolean listed(Platform p) throws Exception {
        CompletableFuture<Boolean> f = new CompletableFuture<>();
        p.runtime().execute(() -> f.complete(Platform.containerLayer(p.runtime(), new AID("mallory@hospital")) != null
                && Platform.containerLayer(p.runtime(), new AID("mallory@hospital")).agents().stream()
                .anyMatch(e -> e.name().equals("control-chair1@hospital"))));
        return f.get(10, TimeUnit.SECONDS);
    }

    @Test
    void aKeyHoldersResumeOverUdpIsRefusedAndAnOperatorsSignedOneResumes(@TempDir Path dir) throws Exception {
        try (ChairSafetyTest.Ward w = new ChairSafetyTest.Ward(dir, ChairSafetyTest.ALL, MedicalAgent.Settings.standard());
             Platform other = Platform.builder().name("hospital").build()) {
            double stopped = heldAfterAnEstop(w);
            Member mallory = join(other);

            AclMessage a = mallory.ask(new ResumeRequest("mallory"));
            assertEquals(Performative.REFUSE, a.getPerformative(), a.getContent());
            assertTrue(WheelchairMessage.reasonOf(a).contains("only an operator may resume chair1"), a.getContent());
            w.awaitSaid("refuses the resume of chair1 asked by mallory@hospital", 10_000);
            Map<String, String> s = w.afterHostFrames(20);
            assertEquals("0,0", s.get("motors"), "still held: " + s);
            assertTrue(moved(s) - stopped < 0.05, "the chair stands: " + s);
            assertEquals(1L, w.call(() -> w.control.resumeRefusals()).get("unsigned"));

            OperatorKey nurse = w.hospital.operatorKey();
            String order = nurse.sign("resume", "chair1", System.currentTimeMillis()).encode();
            a = mallory.ask(new ResumeRequest("nurse at the desk", order));
            assertEquals(Performative.INFORM, a.getPerformative(), "an operator's order carried by a member: " + a.getContent());
            w.board.awaitStatus(st -> moved(st) > stopped + 0.2, 30_000, "the chair to drive on after the operator's resume");
            w.awaitSaid("resumes T1 (decided by an operator at the console (nurse at the desk) via mallory)", 10_000);

            // Nor does a member kill the agent that drives the chair (the observation service's kill).
            a = mallory.kill("control-chair1@hospital");
            assertEquals(Performative.REFUSE, a.getPerformative(), a.getContent());
            assertTrue(a.getContent().contains("is not killed by a message"), a.getContent());
            assertTrue(w.call(() -> w.rt.agents().contains(new AID("control-chair1@hospital"))), "the control agent runs");
        }
    }

    @Test
    void withoutTheAuthorityDefenceAKeyHoldersResumeDrivesTheChairOff(@TempDir Path dir) throws Exception {
        try (ChairSafetyTest.Ward w = new ChairSafetyTest.Ward(dir, ChairSafetyTest.ALL, MedicalAgent.Settings.standard());
             Platform other = Platform.builder().name("hospital").build()) {
            w.call(() -> w.control.withoutDefences(Defence.AUTHORITY));
            double stopped = heldAfterAnEstop(w);
            Member mallory = join(other);
            AclMessage a = mallory.ask(new ResumeRequest("mallory"));
            assertEquals(Performative.INFORM, a.getPerformative(), a.getContent());
            w.board.awaitStatus(st -> moved(st) > stopped + 0.2, 30_000, "the hazard: the chair drives off on mallory's word");
            a = mallory.kill("control-chair1@hospital");
            assertEquals(Performative.AGREE, a.getPerformative(), "the hazard: a member kills the agent that drives the chair: " + a);
        }
    }
}
