package io.concord.console;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** Drop reasons by the threat their defence stands against; the copies sent on purpose apart from every threat. */
class ThreatsTest {
    @Test
    void copiesSentOnPurposeAreNoThreatAndRepeatsAre() {
        assertEquals(Threats.COPIES, Threats.of("copy"), "the second UDP copy of a frame, dropped by its tag");
        assertEquals(Threats.COPIES, Threats.ORDER.get(0), "shown first, apart");
        assertEquals("repetition", Threats.of("repeated"), "a frame the sequence window delivered already");
        assertEquals("repetition", Threats.of("replayed-handshake"));
        assertEquals(Threats.of("copy"), Threats.of("handshake-late"), "a second answer to a retried hello is expected, as a copy is");
        assertEquals("corruption", Threats.of("bad-tag"));
        assertEquals(Threats.OTHER_PLATFORMS, Threats.of("foreign-key"), "another platform's frame, skipped by its key's id");
        assertEquals(Threats.OTHER_PLATFORMS, Threats.of("foreign-platform"), "another platform of the same key, skipped by its name");
        assertEquals(List.of(Threats.COPIES, Threats.OTHER_PLATFORMS), Threats.EXPECTED, "no threat: grey, never the alarm");
        assertEquals("flooding", Threats.of("handshake-limit"));
        assertEquals("other", Threats.of("something-new"));
    }
}
