package io.concord.layers.platform;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

class LinesTest {

    @Test
    void entriesWithAwkwardCharactersRoundTrip() {
        ServiceDescription s = new ServiceDescription("book selling", "Dune, vol. 1; 2=3 %", Map.of("price €", "42 ,;=%\n"),
                List.of("o 1"), List.of("fipa-sl"), List.of("fipa-contract-net"));
        AgentEntry e = new AgentEntry("söller 1@plat", "udp://127.0.0.1:7001", 1_767_225_600_123L, List.of(s, ServiceDescription.ofType("x")));
        String text = Lines.content("lal", Lines.params("term", 3, "seq", 7), List.of(e, e.withServices(List.of())));
        Lines.Content c = Lines.parse(text);
        assertEquals("lal", c.command());
        assertEquals(7, c.longParam("seq"));
        assertEquals(List.of(e, e.withServices(List.of())), c.entries());
    }

    @Test
    void malformedContentsSayWhatIsWrong() {
        assertThrows(IllegalArgumentException.class, () -> Lines.parse(""));
        assertThrows(IllegalArgumentException.class, () -> Lines.parse("lal term"));
        assertThrows(IllegalArgumentException.class, () -> Lines.parse("lal\na@p udp://x:1 notanumber -"));
        assertThrows(IllegalArgumentException.class, () -> Lines.parse("lal\nnoplatform udp://x:1 1 -"));
        assertThrows(IllegalArgumentException.class, () -> Lines.parse("lal\na@p udp://x:1 1 q=1"));
        assertThrows(IllegalArgumentException.class, () -> Lines.parse("lal\na@p udp://x:1 1 t=%4"));
        assertThrows(IllegalArgumentException.class, () -> Lines.parse("lal\na@p udp://x:1 1 - extra"));
        assertThrows(IllegalArgumentException.class, () -> Lines.parse("join").longParam("term"));
    }

    /**
     * A service's properties go out in their keys' order in every JVM: an immutable copy made with
     * {@code Map.copyOf} iterates in an order salted per JVM run, so the same registration went on
     * the wire differently from run to run, and a seed's trace did not replay in another JVM. (With
     * that copy, five keys come out sorted in one run of 120.)
     */
    @Test
    void aServicesPropertiesKeepTheirKeysOrderInEveryRun() {
        ServiceDescription s = ServiceDescription.of("door", "D1").withProperty("y", "1").withProperty("x", "2")
                .withProperty("kind", "hinged").withProperty("b", "3").withProperty("a", "4");
        assertEquals(List.of("a", "b", "kind", "x", "y"), List.copyOf(s.properties().keySet()));
        assertEquals(s.properties(), Map.of("a", "4", "b", "3", "kind", "hinged", "x", "2", "y", "1"));
    }
}
