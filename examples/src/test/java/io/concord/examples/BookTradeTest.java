package io.concord.examples;

import io.concord.core.acl.AID;
import io.concord.core.agent.AgentRuntime;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The annex agents as a program runs them (the benchmarks): on a bare runtime (no Platform, no
 * DF), on the test kit's virtual network and clock.
 */
class BookTradeTest {

    @Test
    void aProgramsBuyerOrdersFromTheCheapestAsOftenAsTheProgramSaysAndAgainWhenTold() {
        try (Simulation sim = new Simulation(1, FaultPlan.NONE)) {
            List<String> sent = new ArrayList<>();
            AgentRuntime rt = sim.newRuntime("10.0.0.1", null, b -> b.tracer((now, node, event, detail) -> {
                if (event.equals("send")) {
                    sent.add(node + " " + detail.substring(0, detail.indexOf(' ')) + detail.substring(detail.lastIndexOf(" to ")));
                }
            }));
            List<AID> sellers = List.of(rt.startAgent("s1", new BookSeller(42)), rt.startAgent("s2", new BookSeller(35)),
                    rt.startAgent("s3", new BookSeller(39)));
            int[] purchases = {0};
            BookBuyer buyer = new BookBuyer(sellers, () -> ++purchases[0] < 3);
            rt.startAgent("buyer", buyer);
            rt.execute(buyer::buy);
            assertTrue(sim.runUntil(() -> purchases[0] == 3, 10_000), "three purchases: " + sent);
            String p = "@" + rt.platformName();
            assertEquals(List.of("buyer" + p + " QUERY-REF to s1" + p, "buyer" + p + " QUERY-REF to s2" + p,
                    "buyer" + p + " QUERY-REF to s3" + p), sent.subList(0, 3), "every seller is asked");
            assertTrue(sent.contains("buyer" + p + " REQUEST to s2" + p), sent.toString());
            assertTrue(sent.stream().noneMatch(l -> l.contains("REQUEST to s1") || l.contains("REQUEST to s3")),
                    "orders go to the cheapest only: " + sent);
            assertEquals(3, sent.stream().filter(l -> l.startsWith("s2@") && l.contains("AGREE")).count(), sent.toString());
            sim.runFor(5_000);
            assertEquals(3, purchases[0], "it stops when the program says so");
            rt.execute(buyer::buy);
            assertTrue(sim.runUntil(() -> purchases[0] == 4, 10_000), "and buys again when told");
        }
    }

    @Test
    void aProgramsBuyerNeedsItsSellers() {
        assertThrows(IllegalArgumentException.class, () -> new BookBuyer(List.of(), () -> false));
    }
}
