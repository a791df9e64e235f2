package io.concord.jadecompat.internal;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import jade.core.AID;
import jade.lang.acl.ACLMessage;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** JADE's message and AID to Concord's and back. */
public final class Convert {
    private Convert() {
    }

    /** A Concord AID for a JADE one (name, addresses, resolvers, slots). */
    public static io.concord.core.acl.AID toConcord(AID a) {
        List<String> addresses = List.of(a.getAddressesArray());
        List<io.concord.core.acl.AID> resolvers = new ArrayList<>();
        for (AID r : a.getResolversArray()) {
            resolvers.add(toConcord(r));
        }
        Map<String, String> slots = new java.util.LinkedHashMap<>();
        for (String k : a.getAllUserDefinedSlot().stringPropertyNames()) {
            if (AclMessage.isParameterName(k)) {
                slots.put(k, a.getAllUserDefinedSlot().getProperty(k));
            }
        }
        return new io.concord.core.acl.AID(Names.encodeFull(a.getName()), addresses, resolvers, slots);
    }

    /**
     * A JADE AID for a Concord one. Concord's own transport addresses ({@code udp://},
     * {@code tcp://}) are routing hints inside the platform, which JADE code never sees: they are
     * left out, as a JADE platform without an MTP shows none.
     */
    public static AID toJade(io.concord.core.acl.AID a) {
        AID r = new AID(Names.decode(a.name()), AID.ISGUID);
        for (String addr : a.addresses()) {
            if (!addr.startsWith("udp://") && !addr.startsWith("tcp://")) {
                r.addAddresses(addr);
            }
        }
        for (io.concord.core.acl.AID res : a.resolvers()) {
            r.addResolvers(toJade(res));
        }
        for (Map.Entry<String, String> e : a.userDefined().entrySet()) {
            r.addUserDefinedSlot(e.getKey(), e.getValue());
        }
        return r;
    }

    /** JADE's int performative as Concord's; {@code null} for an unknown one. */
    public static Performative performative(int p) {
        String name = ACLMessage.getPerformative(p);
        return "UNKNOWN".equals(name) ? null : Performative.fromWireName(name);
    }

    /** Concord's performative as JADE's int. */
    public static int performative(Performative p) {
        return ACLMessage.getInteger(p.wireName());
    }

    /** A Concord message with the fields of a JADE one. */
    public static AclMessage toConcord(ACLMessage m) {
        Performative p = performative(m.getPerformative());
        if (p == null) {
            throw new IllegalArgumentException("performative " + m.getPerformative() + " is not one of FIPA's 22");
        }
        AclMessage c = new AclMessage(p);
        if (m.getSender() != null) {
            c.setSender(toConcord(m.getSender()));
        }
        for (jade.util.leap.Iterator it = m.getAllReceiver(); it.hasNext(); ) {
            c.addReceiver(toConcord((AID) it.next()));
        }
        for (jade.util.leap.Iterator it = m.getAllReplyTo(); it.hasNext(); ) {
            c.addReplyTo(toConcord((AID) it.next()));
        }
        if (m.hasByteSequenceContent()) {
            c.setByteSequenceContent(m.getByteSequenceContent());
        } else if (m.getContent() != null) {
            c.setContent(m.getContent());
        }
        c.setLanguage(m.getLanguage());
        c.setEncoding(m.getEncoding());
        c.setOntology(m.getOntology());
        c.setProtocol(m.getProtocol());
        c.setConversationId(m.getConversationId());
        c.setReplyWith(m.getReplyWith());
        c.setInReplyTo(m.getInReplyTo());
        if (m.getReplyByDate() != null) {
            c.setReplyByEpochMs(m.getReplyByDate().getTime());
        }
        for (String k : m.getAllUserDefinedParameters().stringPropertyNames()) {
            String v = m.getAllUserDefinedParameters().getProperty(k);
            if (AclMessage.isParameterName(k)) {
                c.addUserDefinedParameter(k, v);
            }
        }
        return c;
    }

    /** A JADE message with the fields of a Concord one. */
    public static ACLMessage toJade(AclMessage c) {
        ACLMessage m = new ACLMessage(performative(c.getPerformative()));
        if (c.getSender() != null) {
            m.setSender(toJade(c.getSender()));
        }
        for (io.concord.core.acl.AID r : c.getReceivers()) {
            m.addReceiver(toJade(r));
        }
        for (io.concord.core.acl.AID r : c.getReplyTo()) {
            m.addReplyTo(toJade(r));
        }
        if (c.hasByteSequenceContent()) {
            m.setByteSequenceContent(c.getByteSequenceContent());
        } else {
            m.setContent(c.getContent());
        }
        m.setLanguage(c.getLanguage());
        m.setEncoding(c.getEncoding());
        m.setOntology(c.getOntology());
        m.setProtocol(c.getProtocol());
        m.setConversationId(c.getConversationId());
        m.setReplyWith(c.getReplyWith());
        m.setInReplyTo(c.getInReplyTo());
        if (c.hasReplyBy()) {
            m.setReplyByDate(new java.util.Date(c.getReplyByEpochMs()));
        }
        for (Map.Entry<String, String> e : c.getUserDefinedParameters().entrySet()) {
            m.addUserDefinedParameter(e.getKey(), e.getValue());
        }
        return m;
    }
}
