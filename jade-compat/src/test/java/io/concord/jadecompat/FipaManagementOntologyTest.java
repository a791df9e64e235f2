package io.concord.jadecompat;

import jade.content.ContentManager;
import jade.content.lang.sl.SLCodec;
import jade.content.onto.basic.Action;
import jade.content.onto.basic.Done;
import jade.content.onto.basic.Result;
import jade.core.AID;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.FIPAManagementOntology;
import jade.domain.FIPAAgentManagement.FIPAManagementVocabulary;
import jade.domain.FIPAAgentManagement.Property;
import jade.domain.FIPAAgentManagement.Register;
import jade.domain.FIPAAgentManagement.Search;
import jade.domain.FIPAAgentManagement.SearchConstraints;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.lang.acl.ACLMessage;
import org.junit.jupiter.api.Test;

import java.util.Date;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * JADE's FIPAManagementOntology under its name. The expected texts are what JADE 4.3 writes for the
 * same objects (its SLCodec(0) and FIPAManagementOntology, run once outside this module, which has
 * no JADE on its test class path); Concord writes the same and reads them back as the objects.
 */
class FipaManagementOntologyTest {
    private static final String REGISTER = "((action (agent-identifier :name df@P) (register (df-agent-description"
            + " :name (agent-identifier :name seller@P) :services (set (service-description :name shop :type book-selling"
            + " :protocols (set fipa-request) :languages (set fipa-sl) :properties (set (property :name country :value it))))"
            + " :ontologies (set book-shop) :lease-time 20090213T233130123Z))))";
    private static final String SEARCH = "((action (agent-identifier :name df@P) (search (df-agent-description"
            + " :services (set (service-description :type book-selling))) (search-constraints :max-results 5))))";
    private static final String RESULT = "((result " + SEARCH.substring(1, SEARCH.length() - 1)
            + " (sequence (df-agent-description :name (agent-identifier :name seller@P) :services (set (service-description"
            + " :name shop :type book-selling :protocols (set fipa-request) :languages (set fipa-sl) :properties (set"
            + " (property :name country :value it)))) :ontologies (set book-shop) :lease-time 20090213T233130123Z))))";
    private static final String DONE = "((done " + REGISTER.substring(1, REGISTER.length() - 1) + "))";

    private final AID df = new AID("df@P", AID.ISGUID);

    private static ContentManager manager() {
        ContentManager cm = new ContentManager();
        cm.registerLanguage(new SLCodec(0));
        cm.registerOntology(FIPAManagementOntology.getInstance());
        return cm;
    }

    private static ACLMessage message() {
        ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
        m.setLanguage("fipa-sl0");
        m.setOntology(FIPAManagementVocabulary.NAME);
        return m;
    }

    private static DFAgentDescription seller() {
        DFAgentDescription dfd = new DFAgentDescription();
        dfd.setName(new AID("seller@P", AID.ISGUID));
        ServiceDescription sd = new ServiceDescription();
        sd.setName("shop");
        sd.setType("book-selling");
        sd.addProtocols("fipa-request");
        sd.addLanguages("fipa-sl");
        sd.addProperties(new Property("country", "it"));
        dfd.addServices(sd);
        dfd.addOntologies("book-shop");
        dfd.setLeaseTime(new Date(1234567890123L));
        return dfd;
    }

    private static Search search() {
        Search s = new Search();
        DFAgentDescription t = new DFAgentDescription();
        ServiceDescription ts = new ServiceDescription();
        ts.setType("book-selling");
        t.addServices(ts);
        s.setDescription(t);
        SearchConstraints c = new SearchConstraints();
        c.setMaxResults(5L);
        s.setConstraints(c);
        return s;
    }

    @Test
    void writesWhatJadeWrites() throws Exception {
        ContentManager cm = manager();
        ACLMessage m = message();
        Register r = new Register();
        r.setDescription(seller());
        cm.fillContent(m, new Action(df, r));
        assertEquals(REGISTER, m.getContent());
        cm.fillContent(m, new Action(df, search()));
        assertEquals(SEARCH, m.getContent());
        jade.util.leap.List l = new jade.util.leap.ArrayList();
        l.add(seller());
        cm.fillContent(m, new Result(new Action(df, search()), l));
        assertEquals(RESULT, m.getContent());
        cm.fillContent(m, new Done(new Action(df, r)));
        assertEquals(DONE, m.getContent());
    }

    @Test
    void readsWhatJadeWrites() throws Exception {
        ContentManager cm = manager();
        ACLMessage m = message();
        m.setContent(REGISTER);
        Action a = (Action) cm.extractContent(m);
        DFAgentDescription dfd = (DFAgentDescription) ((Register) a.getAction()).getDescription();
        assertEquals("seller@P", dfd.getName().getName());
        assertEquals(1234567890123L, dfd.getLeaseTime().getTime());
        assertEquals("book-shop", dfd.getAllOntologies().next());
        ServiceDescription sd = (ServiceDescription) dfd.getAllServices().next();
        assertEquals("book-selling", sd.getType());
        assertEquals("fipa-request", sd.getAllProtocols().next());
        Property p = (Property) sd.getAllProperties().next();
        assertEquals("country", p.getName());
        assertEquals("it", p.getValue());

        m.setContent(RESULT);
        Result r = (Result) cm.extractContent(m);
        Search s = (Search) ((Action) r.getAction()).getAction();
        assertEquals(5L, s.getConstraints().getMaxResults());
        assertEquals(1, r.getItems().size());
        DFAgentDescription found = (DFAgentDescription) r.getItems().get(0);
        assertEquals("seller@P", found.getName().getName());
        assertFalse(found.getAllLanguages().hasNext());

        m.setContent(DONE);
        assertEquals(Register.class, ((Action) ((Done) cm.extractContent(m)).getAction()).getAction().getClass());
    }
}
