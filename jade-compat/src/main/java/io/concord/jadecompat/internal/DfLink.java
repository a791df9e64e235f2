package io.concord.jadecompat.internal;

import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.platform.ServiceDescription;
import jade.core.AID;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.lang.acl.ACLMessage;
import jade.util.leap.Iterator;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * One JADE agent's DF subscriptions, translated at its edge: a SUBSCRIBE to the DF in JADE's SL
 * form goes to Concord's DF as a subscription for the template's first service, and each of the
 * DF's notifications in that conversation comes back as JADE's DF writes it (an INFORM from the
 * DF in {@code fipa-sl}, {@code ((= (iota ...) (sequence dfd...)))}). A CANCEL ends it.
 */
public final class DfLink {
    private static final String ONTOLOGY = "FIPA-Agent-Management";

    /** The SL content of each open subscription, by conversation id. */
    private final Map<String, String> open = new ConcurrentHashMap<>();
    private long counter;

    /** The message to send in place of {@code m} (itself unless it subscribes to or cancels at the DF). */
    public ACLMessage outgoing(ACLMessage m, AID df) {
        int p = m.getPerformative();
        if ((p != ACLMessage.SUBSCRIBE && p != ACLMessage.CANCEL) || !addressedTo(m, df)) {
            return m;
        }
        if (p == ACLMessage.CANCEL) {
            if (m.getConversationId() != null) {
                open.remove(m.getConversationId());
            }
            return m;
        }
        String content = m.getContent();
        DFAgentDescription template;
        try {
            template = content == null ? null : DfSl.templateOf(content);
        } catch (IllegalArgumentException e) {
            return m; // not a DF subscription in SL: the DF answers NOT_UNDERSTOOD
        }
        if (template == null) {
            return m;
        }
        ACLMessage c = (ACLMessage) m.clone();
        if (c.getConversationId() == null) {
            c.setConversationId("df-subscription-" + m.getSender().getLocalName() + "-" + (++counter));
        }
        List<ServiceDescription> services = DfSl.toConcord(template);
        ServiceDescription first = services.isEmpty()
                ? new ServiceDescription(null, null, Map.of(), List.of(), List.of(), List.of()) : services.get(0);
        c.setContent(ContainerLayer.subscriptionContent(first));
        open.put(c.getConversationId(), content);
        return c;
    }

    /** The message to deliver in place of {@code j} (itself unless it is the DF's notification of an open subscription). */
    public ACLMessage incoming(ACLMessage j, AID df) {
        String conversation = j.getConversationId();
        String subscription = conversation == null ? null : open.get(conversation);
        if (subscription == null || j.getPerformative() != ACLMessage.INFORM
                || !ContainerLayer.contentLanguage().equals(j.getLanguage())) {
            return j;
        }
        List<DFAgentDescription> found = new ArrayList<>();
        try {
            for (AgentEntry e : ContainerLayer.resultEntries(j.getContent())) {
                found.add(DfSl.toJade(e));
            }
        } catch (IllegalArgumentException e) {
            return j;
        }
        j.setContent(DfSl.notification(subscription, found));
        j.setLanguage("fipa-sl");
        j.setOntology(ONTOLOGY);
        // Concord's DF answers from the agent that is container now; JADE's from the DF.
        j.setSender(df);
        return j;
    }

    private static boolean addressedTo(ACLMessage m, AID df) {
        for (Iterator it = m.getAllReceiver(); it.hasNext(); ) {
            if (df.equals(it.next())) {
                return true;
            }
        }
        return false;
    }
}
