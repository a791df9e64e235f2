package io.concord.core.acl;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class AclMessageTest {
    @Test
    void hasAllTwentyTwoFipaPerformativesWithTheirWireNames() {
        assertEquals(22, Performative.values().length);
        assertEquals("QUERY-REF", Performative.QUERY_REF.wireName());
        assertEquals(Performative.REQUEST_WHENEVER, Performative.fromWireName("request-whenever"));
        assertNull(Performative.fromWireName("shout"));
    }

    @Test
    void createReplyFollowsJade() {
        AclMessage m = new AclMessage(Performative.QUERY_REF);
        m.setSender(new AID("alice@p"));
        m.addReceiver(new AID("bob@p"));
        m.setConversationId("c1");
        m.setProtocol("fipa-query");
        m.setLanguage("fipa-sl");
        m.setOntology("books");
        m.setReplyWith("q7");
        m.setContent("(price x)");
        m.setReceivedAtEpochMs(1234);
        AclMessage r = m.createReply();
        assertEquals(Performative.QUERY_REF, r.getPerformative(), "the performative is the caller's to set");
        assertEquals(List.of(new AID("alice@p")), r.getReceivers());
        assertEquals("c1", r.getConversationId());
        assertEquals("fipa-query", r.getProtocol());
        assertEquals("fipa-sl", r.getLanguage());
        assertEquals("books", r.getOntology());
        assertEquals("q7", r.getInReplyTo());
        assertEquals("alice@p1234", r.getReplyWith());
        assertNull(r.getContent());
    }

    @Test
    void createReplyGoesToReplyToWhenPresent() {
        AclMessage m = new AclMessage(Performative.REQUEST);
        m.setSender(new AID("alice@p"));
        m.addReplyTo(new AID("carol@p"));
        assertEquals(List.of(new AID("carol@p")), m.createReply().getReceivers());
    }

    @Test
    void aidsAreEqualByNameIgnoringCase() {
        assertEquals(new AID("Alice@P", "udp://h:1"), new AID("alice@p"));
        assertEquals("alice", new AID("alice@p").localName());
        assertEquals("p", new AID("alice@p").platform());
        assertThrows(IllegalArgumentException.class, () -> new AID(""));
    }

    @Test
    void userParametersDropTheirXPrefixAndRejectNamesThatCannotBeWritten() {
        AclMessage m = new AclMessage(Performative.INFORM);
        m.addUserDefinedParameter("X-foo", "1");
        assertEquals("1", m.getUserDefinedParameter("foo"));
        assertEquals("1", m.getUserDefinedParameter("X-foo"));
        assertTrue(m.getUserDefinedParameters().containsKey("foo"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> m.addUserDefinedParameter("two words", "v"));
        assertTrue(e.getMessage().contains("two words"));
    }

    @Test
    void contentConvertsBetweenTextAndBytes() {
        AclMessage m = new AclMessage(Performative.INFORM).setContent("héllo");
        assertEquals(6, m.getByteSequenceContent().length);
        m.setByteSequenceContent(new byte[]{104, 105});
        assertEquals("hi", m.getContent());
        assertTrue(m.hasByteSequenceContent());
    }

    @Test
    void aCopyIsDeep() {
        AclMessage m = new AclMessage(Performative.INFORM);
        m.addReceiver(new AID("a@p"));
        AclMessage c = m.copy();
        c.addReceiver(new AID("b@p"));
        assertEquals(1, m.getReceivers().size());
        assertTrue(m.sameAs(m.copy()));
    }
}
