package io.concord.core.acl;

import org.junit.jupiter.api.Test;

import static io.concord.core.acl.MessageTemplate.*;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class MessageTemplateTest {
    private final AID alice = new AID("alice@p");
    private final AID bob = new AID("bob@p");

    private AclMessage sample() {
        AclMessage m = new AclMessage(Performative.PROPOSE);
        m.setSender(alice);
        m.addReceiver(bob);
        m.setConversationId("c1");
        m.setInReplyTo("r0");
        m.setReplyWith("r1");
        m.setProtocol("fipa-contract-net");
        m.setOntology("books");
        m.setLanguage("fipa-sl");
        m.setEncoding("utf8");
        m.setContent("42");
        return m;
    }

    @Test
    void eachMatcherMatchesItsSlotAndNothingElse() {
        AclMessage m = sample();
        MessageTemplate[][] pairs = {
                {matchPerformative(Performative.PROPOSE), matchPerformative(Performative.INFORM)},
                {matchSender(new AID("ALICE@p")), matchSender(bob)},
                {matchReceiver(bob), matchReceiver(alice)},
                {matchConversationId("c1"), matchConversationId("c2")},
                {matchInReplyTo("r0"), matchInReplyTo("r1")},
                {matchReplyWith("r1"), matchReplyWith("r0")},
                {matchProtocol("fipa-contract-net"), matchProtocol("fipa-request")},
                {matchOntology("books"), matchOntology("cars")},
                {matchLanguage("fipa-sl"), matchLanguage("fipa-sl0")},
                {matchEncoding("utf8"), matchEncoding("latin1")},
                {matchContent("42"), matchContent("43")},
                {matchCustom(x -> x.getContent().length() == 2), matchCustom(x -> x.getContent().isEmpty())},
        };
        for (MessageTemplate[] p : pairs) {
            assertTrue(p[0].match(m));
            assertFalse(p[1].match(m));
        }
        assertTrue(matchAll().match(m));
    }

    @Test
    void combinesWithAndOrNot() {
        AclMessage m = sample();
        MessageTemplate yes = matchConversationId("c1");
        MessageTemplate no = matchConversationId("zz");
        assertTrue(and(yes, yes).match(m));
        assertFalse(and(yes, no).match(m));
        assertTrue(or(no, yes).match(m));
        assertFalse(or(no, no).match(m));
        assertTrue(not(no).match(m));
        assertFalse(not(yes).match(m));
        assertTrue(yes.and(not(no)).or(no).match(m));
    }

    @Test
    void absentSlotsDoNotMatchAValue() {
        AclMessage empty = new AclMessage(Performative.INFORM);
        assertFalse(matchConversationId("c1").match(empty));
        assertTrue(matchConversationId(null).match(empty));
        assertFalse(matchSender(alice).match(empty));
    }
}
