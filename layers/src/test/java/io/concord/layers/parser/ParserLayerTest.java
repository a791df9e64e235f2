package io.concord.layers.parser;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;
import io.concord.testkit.LayerHarness;
import io.concord.core.time.ManualClock;
import io.concord.layers.frame.Frames;
import io.concord.layers.sequence.SequenceLayer;
import io.concord.layers.temporal.PlatformClock;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

class ParserLayerTest {
    private static final AID ALICE = new AID("alice@p");
    private static final AID BOB = new AID("bob@p");
    private static final Address ALICE_AT = new Address("h", 1);
    private final ManualClock clock = new ManualClock();

    private LayerHarness parser(Membership m) {
        return new LayerHarness("bob@p", clock, new ParserLayer(m, new PlatformClock(), true));
    }

    /** Encodes a message as alice's parser would, and lets it arrive as authenticated from {@code frameFrom}. */
    private Envelope arriving(AclMessage m, String frameFrom, Address from) {
        LayerHarness alice = new LayerHarness("alice@p", clock, new ParserLayer(Membership.open(), null, true));
        alice.sendDown(Envelope.outgoing(m, BOB, new Address("h", 2)));
        byte[] wire = alice.pollDown().dataCopy();
        Envelope e = Envelope.incoming(from, wire, 0, wire.length, 0);
        e.setPeerId(Frames.id(frameFrom));
        e.putHeader(SequenceLayer.ENVELOPE_HEADER, new long[]{Frames.id(frameFrom), 1, 1});
        return e;
    }

    private static AclMessage from(AID sender) {
        return new AclMessage(Performative.INFORM).setSender(sender).addReceiver(BOB).setContent("hi");
    }

    @Test
    void aMessageFromAMemberAtItsAddressPasses() {
        LayerHarness h = parser(new Membership.Static().add(ALICE, ALICE_AT));
        h.receiveUp(arriving(from(ALICE), "alice@p", ALICE_AT));
        assertEquals("hi", h.pollUp().message().getContent());
    }

    @Test
    void aSenderThatIsNotTheAuthenticatedSourceFailsIdentification() {
        LayerHarness h = parser(Membership.open());
        h.receiveUp(arriving(from(ALICE), "mallory@p", ALICE_AT));
        assertNull(h.pollUp());
        assertEquals(1, h.drops().get("identification"));
    }

    @Test
    void aMemberSpeakingFromAnotherAddressFailsIdentification() {
        LayerHarness h = parser(new Membership.Static().add(ALICE, ALICE_AT));
        h.receiveUp(arriving(from(ALICE), "alice@p", new Address("h", 99)));
        assertEquals(1, h.drops().get("identification"));
    }

    @Test
    void aNonMemberIsRefusedAndAJoiningOneIsAskedToSendAgain() {
        LayerHarness h = parser(new Membership.Static().joining(ALICE));
        h.receiveUp(arriving(from(ALICE), "alice@p", ALICE_AT));
        assertEquals(1, h.drops().get("not-member"));
        assertEquals(SequenceLayer.RESEND_REQUEST, h.events().get(0).type());
        LayerHarness strict = parser(new Membership.Static());
        strict.receiveUp(arriving(from(ALICE), "alice@p", ALICE_AT));
        assertEquals(1, strict.drops().get("not-member"));
        assertEquals(0, strict.events().size(), "a stranger is not asked again");
    }

    @Test
    void platformMessagesAreExemptFromMembership() {
        LayerHarness h = parser(new Membership.Static());
        AclMessage join = from(ALICE).setOntology(Membership.PLATFORM_ONTOLOGY);
        h.receiveUp(arriving(join, "alice@p", ALICE_AT));
        assertNotNull(h.pollUp());
    }

    @Test
    void aMessageWhoseReplyByHasPassedHasExpired() {
        LayerHarness h = parser(Membership.open());
        AclMessage late = from(ALICE).setReplyByEpochMs(clock.epochMillis() - 1);
        h.receiveUp(arriving(late, "alice@p", ALICE_AT));
        assertEquals(1, h.drops().get("expired"));
    }

    @Test
    void bytesThatAreNotAMessageAreMalformed() {
        LayerHarness h = parser(Membership.open());
        Envelope junk = Envelope.incoming(ALICE_AT, new byte[]{1, 2, 3}, 0, 3, 0);
        h.receiveUp(junk);
        assertEquals(1, h.drops().get("malformed"));
    }

    @Test
    void aMessageToSeveralReceiversIsEncodedOnceButAChangedOneAgain() throws Exception {
        LayerHarness alice = new LayerHarness("alice@p", clock, new ParserLayer(Membership.open(), null, true));
        AID carol = new AID("carol@p");
        AclMessage m = new AclMessage(Performative.INFORM).setSender(ALICE).addReceiver(BOB).addReceiver(carol).setContent("v1");
        for (AID r : m.getReceivers()) {
            alice.sendDown(Envelope.outgoing(m, r, new Address("h", 2)));
        }
        m.setContent("v2");
        for (AID r : m.getReceivers()) {
            alice.sendDown(Envelope.outgoing(m, r, new Address("h", 2)));
        }
        String[] contents = new String[4];
        for (int i = 0; i < 4; i++) {
            Envelope e = alice.pollDown();
            contents[i] = io.concord.core.codec.BinaryAclCodec.INSTANCE.decode(e.data(), e.offset(), e.length()).getContent();
            assertEquals(i % 2 == 0 ? Frames.id("bob@p") : Frames.id("carol@p"), e.peerId());
        }
        assertEquals(java.util.List.of("v1", "v1", "v2", "v2"), java.util.List.of(contents));
    }
}
