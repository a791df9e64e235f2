package io.concord.jadecompat;

import io.concord.jadecompat.internal.DfSl;
import jade.core.AID;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.Property;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/** DF notifications in SL, as JADE 4.3's DF writes them and as concord-jade writes them, read by {@code decodeNotification}. */
class DfNotificationTest {
    /** Two notifications JADE 4.3.3's DF sent (recorded on loopback): a registration, then its deregistration. */
    private static final String JADE_REGISTERED = "((= (iota ?x (result (action (agent-identifier :name df@corpus) (search "
            + "(df-agent-description :services (set (service-description :type x))) (search-constraints :max-results -1))) ?x)) "
            + "(sequence (df-agent-description :name (agent-identifier :name reg@corpus) :services (set (service-description :name n :type x))))))";
    private static final String JADE_DEREGISTERED = "((= (iota ?x (result (action (agent-identifier :name df@corpus) (search "
            + "(df-agent-description :services (set (service-description :type x))) (search-constraints :max-results -1))) ?x)) "
            + "(sequence (df-agent-description :name (agent-identifier :name reg@corpus)))))";

    @Test
    void jadesRegistrationNotificationDecodes() throws Exception {
        DFAgentDescription[] d = DFService.decodeNotification(JADE_REGISTERED);
        assertEquals(1, d.length);
        assertEquals("reg@corpus", d[0].getName().getName());
        ServiceDescription s = (ServiceDescription) d[0].getAllServices().next();
        assertEquals("x", s.getType());
        assertEquals("n", s.getName());
    }

    @Test
    void jadesDeregistrationNotificationHasNoServices() throws Exception {
        DFAgentDescription[] d = DFService.decodeNotification(JADE_DEREGISTERED);
        assertEquals(1, d.length);
        assertFalse(d[0].getAllServices().hasNext());
    }

    @Test
    void whatConcordWritesReadsBackWithEverySlot() throws Exception {
        DFAgentDescription template = new DFAgentDescription();
        ServiceDescription t = new ServiceDescription();
        t.setType("book-selling");
        template.addServices(t);
        String subscription = DfSl.subscription(new AID("df@shop", AID.ISGUID), template, null);
        assertEquals("book-selling", ((ServiceDescription) DfSl.templateOf(subscription).getAllServices().next()).getType());

        DFAgentDescription d = new DFAgentDescription();
        d.setName(new AID("seller@shop", AID.ISGUID));
        ServiceDescription s = new ServiceDescription();
        s.setType("book-selling");
        s.setName("Dune \"first\" edition");
        s.addProperties(new Property("price", "42"));
        s.addLanguages("english");
        s.addProtocols("fipa-request");
        d.addServices(s);
        DFAgentDescription[] back = DFService.decodeNotification(DfSl.notification(subscription, List.of(d)));
        assertEquals(1, back.length);
        assertEquals(DfSl.description(d), DfSl.description(back[0]));
    }
}
