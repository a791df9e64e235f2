package io.concord.sim;

import com.fasterxml.jackson.databind.JsonNode;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.agents.medical.TransportAudit;
import io.concord.agents.traffic.TrafficRules;
import io.concord.testkit.FaultPlan;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The audit trail of transports, as a ward's staff asks for it (rmf-web's users ask for exactly
 * this): a transport asked at the front desk, from a console's client, is done; the Medical agent's
 * trail says who asked, from where, when, which chair, when each phase began, how it ended; its
 * story tells the auction, every bid, the award, the phases and the result; and the front desk gets
 * both over the platform, as the console's hospital view shows them.
 */
class TransportAuditTest {

    @Test
    void theTrailTellsWhoAskedTheChairEachPhaseAndTheStory() {
        try (VirtualHospital h = new VirtualHospital(HospitalMap.defaultHospital(), 2010, FaultPlan.NONE, 2, TrafficRules.IN_ORDER,
                MedicalAgent.Settings.standard(), line -> { })) {
            assertTrue(h.ready());
            HospitalView.FrontDesk desk = new HospitalView.FrontDesk();
            h.platform.startAgent("desk", desk);
            h.sim.runFor(1_000);
            desk.ask(3, 9, 3, 30, "127.0.0.1:5555");
            assertTrue(h.sim.runUntil(() -> h.medical.audit().entry("T1") != null && !h.medical.audit().entry("T1").outcome().equals("open"),
                    1_800_000), "the transport ended");

            TransportAudit.Entry e = h.medical.audit().entry("T1");
            assertEquals("desk@hospital", e.askedBy());
            assertEquals("desk-1", e.conversation());
            assertEquals("done", e.outcome(), e.toString());
            assertTrue(e.chair().startsWith("control-chair"), e.chair());
            // Every phase reached, in order, and the end after the last.
            List<Long> times = new ArrayList<>(List.of(e.askedAtMs()));
            for (String phase : TransportAudit.PHASES) {
                assertTrue(e.phases().containsKey(phase), phase + " missing: " + e.phases());
                times.add(e.phases().get(phase));
            }
            times.add(e.endedAtMs());
            for (int i = 1; i < times.size(); i++) {
                assertTrue(times.get(i) >= times.get(i - 1), "phases out of order: " + e);
            }
            assertTrue(times.get(times.size() - 1) > times.get(0), "the transport took time: " + e);
            String story = String.join("\n", e.story().stream().map(TransportAudit.Line::text).toList());
            // Its way node by node, and what it waited for on it (a door on the way to room A2: A2).
            assertTrue(story.contains(": to-pickup at node 2") && story.contains(": to-dropoff at node 10"), "the route in the story:\n" + story);
            assertTrue(story.contains("waiting for door"), "the doors in the story:\n" + story);
            for (String said : List.of("transport T1 from node 3 to node 9", "CFP T1", "proposes cost", "ACCEPT " + e.chair() + " for T1",
                    "T1 on " + e.chair() + ": loading", "reports T1 done")) {
                assertTrue(story.contains(said), "the story lacks '" + said + "':\n" + story);
            }

            // Over the platform, as the console's hospital view gets it.
            desk.refreshAudit();
            h.sim.runFor(1_000);
            JsonNode t = desk.audit().get(0);
            assertEquals("T1", t.path("task").asText());
            assertEquals("127.0.0.1:5555", desk.origin(t.path("conversation").asText()), "from where: the console's client");
            assertEquals(e.phases().get("loading").longValue(), t.path("phases").path("loading").asLong());
            desk.askStory("T1");
            h.sim.runFor(1_000);
            assertEquals(e.story().size(), desk.story().path("story").size());
            // A transport the Medical agent never had: it says so, and the trail stays as it was.
            desk.askStory("T99");
            h.sim.runFor(1_000);
            desk.refreshAudit();
            h.sim.runFor(3_000);
            assertTrue(desk.story().path("unknown").asBoolean(), desk.story().toString());
            assertEquals("T1", desk.audit().get(0).path("task").asText(), "the trail is still there");
        }
    }
}
