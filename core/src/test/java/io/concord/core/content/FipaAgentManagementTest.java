package io.concord.core.content;

import io.concord.core.acl.AID;
import io.concord.core.content.FipaAgentManagement.AmsAgentDescription;
import io.concord.core.content.FipaAgentManagement.DfAgentDescription;
import io.concord.core.content.FipaAgentManagement.Deregister;
import io.concord.core.content.FipaAgentManagement.Modify;
import io.concord.core.content.FipaAgentManagement.Property;
import io.concord.core.content.FipaAgentManagement.Register;
import io.concord.core.content.FipaAgentManagement.Search;
import io.concord.core.content.FipaAgentManagement.SearchConstraints;
import io.concord.core.content.FipaAgentManagement.ServiceDescription;
import jade.content.lang.sl.SLCodec;
import jade.domain.FIPAAgentManagement.FIPAManagementOntology;
import jade.lang.acl.ACLMessage;
import org.junit.jupiter.api.Test;

import java.time.Instant;
import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The FIPA agent-management ontology against JADE 4.3's own {@code FIPAManagementOntology} and
 * {@code SLCodec} (SL0, as JADE's DFService speaks to a DF): JADE's text reads as the expected
 * objects, and what Concord writes JADE reads as the same content (JADE writes it back exactly as
 * it writes its own objects).
 */
class FipaAgentManagementTest {
    static final SlCodec SL0 = new SlCodec(SlCodec.Profile.SL0, SlCodec.DEFAULT_MAX_DEPTH, SlCodec.DEFAULT_MAX_CHARS);
    static final Ontology ONTO = FipaAgentManagement.ontology();

    static final AID DF = new AID("df@P");
    static final ServiceDescription SERVICE = new ServiceDescription("n", "t", null, null, Set.of("fipa-sl"), null,
            Set.of(new Property("k", "v")));
    static final DfAgentDescription DFD = new DfAgentDescription(new AID("x@P", "http://h:1/acc"), Set.of(SERVICE), null,
            null, null, null);
    static final SearchConstraints ALL = new SearchConstraints(null, -1L, null);

    /** The same objects in JADE. */
    static jade.domain.FIPAAgentManagement.DFAgentDescription jadeDfd() {
        jade.domain.FIPAAgentManagement.DFAgentDescription d = new jade.domain.FIPAAgentManagement.DFAgentDescription();
        jade.core.AID x = new jade.core.AID("x@P", true);
        x.addAddresses("http://h:1/acc");
        d.setName(x);
        jade.domain.FIPAAgentManagement.ServiceDescription s = new jade.domain.FIPAAgentManagement.ServiceDescription();
        s.setType("t");
        s.setName("n");
        s.addLanguages("fipa-sl");
        s.addProperties(new jade.domain.FIPAAgentManagement.Property("k", "v"));
        d.addServices(s);
        return d;
    }

    static jade.domain.FIPAAgentManagement.SearchConstraints jadeAll() {
        jade.domain.FIPAAgentManagement.SearchConstraints c = new jade.domain.FIPAAgentManagement.SearchConstraints();
        c.setMaxResults(-1L);
        return c;
    }

    static jade.content.ContentManager jadeCm() {
        jade.content.ContentManager cm = new jade.content.ContentManager();
        cm.registerLanguage(new SLCodec(0));
        cm.registerOntology(FIPAManagementOntology.getInstance());
        return cm;
    }

    static String jadeWrites(jade.content.ContentElement ce) throws Exception {
        ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
        m.setLanguage("fipa-sl0");
        m.setOntology(FIPAManagementOntology.NAME);
        jadeCm().fillContent(m, ce);
        return m.getContent();
    }

    static jade.content.ContentElement jadeReads(String text) throws Exception {
        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
        m.setLanguage("fipa-sl0");
        m.setOntology(FIPAManagementOntology.NAME);
        m.setContent(text);
        return jadeCm().extractContent(m);
    }

    static Object concordReads(String text) throws Exception {
        List<AbsObject> abs = SL0.read(text);
        assertEquals(1, abs.size());
        return ONTO.fromAbs(abs.get(0));
    }

    static String concordWrites(Object content) throws Exception {
        return SL0.write(ONTO.toAbs(content));
    }

    /** Each pair: the Concord content and JADE's. */
    static List<Object[]> pairs() {
        jade.core.AID jdf = new jade.core.AID("df@P", true);
        jade.domain.FIPAAgentManagement.Search search = new jade.domain.FIPAAgentManagement.Search();
        search.setDescription(jadeDfd());
        search.setConstraints(jadeAll());
        jade.domain.FIPAAgentManagement.Register register = new jade.domain.FIPAAgentManagement.Register();
        register.setDescription(jadeDfd());
        jade.domain.FIPAAgentManagement.Deregister deregister = new jade.domain.FIPAAgentManagement.Deregister();
        deregister.setDescription(jadeDfd());
        jade.domain.FIPAAgentManagement.Modify modify = new jade.domain.FIPAAgentManagement.Modify();
        modify.setDescription(jadeDfd());
        jade.domain.FIPAAgentManagement.AMSAgentDescription ad = new jade.domain.FIPAAgentManagement.AMSAgentDescription();
        ad.setName(new jade.core.AID("x@P", true));
        ad.setState("active");
        jade.domain.FIPAAgentManagement.Search amsSearch = new jade.domain.FIPAAgentManagement.Search();
        amsSearch.setDescription(ad);
        amsSearch.setConstraints(jadeAll());
        jade.util.leap.List found = new jade.util.leap.ArrayList();
        found.add(jadeDfd());
        jade.domain.FIPAAgentManagement.DFAgentDescription leased = jadeDfd();
        leased.setLeaseTime(new java.util.Date(1_700_000_000_123L));
        jade.domain.FIPAAgentManagement.Register leasedRegister = new jade.domain.FIPAAgentManagement.Register();
        leasedRegister.setDescription(leased);

        Action cSearch = new Action(DF, new Search(DFD, ALL));
        Action cRegister = new Action(DF, new Register(DFD));
        return List.of(
                new Object[]{cSearch, new jade.content.onto.basic.Action(jdf, search)},
                new Object[]{cRegister, new jade.content.onto.basic.Action(jdf, register)},
                new Object[]{new Action(DF, new Deregister(DFD)), new jade.content.onto.basic.Action(jdf, deregister)},
                new Object[]{new Action(DF, new Modify(DFD)), new jade.content.onto.basic.Action(jdf, modify)},
                new Object[]{new Action(new AID("ams@P"), new Search(new AmsAgentDescription(new AID("x@P"), null, "active"), ALL)),
                        new jade.content.onto.basic.Action(new jade.core.AID("ams@P", true), amsSearch)},
                new Object[]{new Done(cRegister), new jade.content.onto.basic.Done(new jade.content.onto.basic.Action(jdf, register))},
                new Object[]{new Result(cSearch, List.of(DFD)),
                        new jade.content.onto.basic.Result(new jade.content.onto.basic.Action(jdf, search), found)},
                new Object[]{new Action(DF, new Register(new DfAgentDescription(DFD.name(), DFD.services(), null, null, null,
                        Instant.ofEpochMilli(1_700_000_000_123L)))), new jade.content.onto.basic.Action(jdf, leasedRegister)});
    }

    @Test
    void jadesTextReadsAsTheSameObjects() throws Exception {
        for (Object[] p : pairs()) {
            String jade = jadeWrites((jade.content.ContentElement) p[1]);
            assertEquals(p[0], concordReads(jade), jade);
        }
    }

    @Test
    void jadeReadsConcordsTextAsTheSameContent() throws Exception {
        for (Object[] p : pairs()) {
            String ours = concordWrites(p[0]);
            String jade = jadeWrites((jade.content.ContentElement) p[1]);
            assertEquals(jade, jadeWrites(jadeReads(ours)), ours);
        }
    }

    @Test
    void actionsAreWrittenByPositionAsJadeWritesThem() throws Exception {
        String ours = concordWrites(new Action(DF, new Search(new DfAgentDescription(null, null, null, null, null, null), ALL)));
        assertEquals("((action (agent-identifier :name df@P) (search (df-agent-description) (search-constraints :max-results -1))))", ours);
        assertEquals(ours, jadeWrites(jadeReads(ours)));
    }

    @Test
    void theBridgesRequestsOfTodayRead() throws Exception {
        Object o = concordReads("((action (agent-identifier :name df@C) (search (df-agent-description :services (set "
                + "(service-description :type jade-echo-service))) (search-constraints :max-results -1))))");
        Search s = (Search) ((Action) o).action();
        DfAgentDescription d = (DfAgentDescription) s.description();
        assertEquals("jade-echo-service", d.services().iterator().next().type());
        assertEquals(-1L, s.constraints().maxResults());
        assertTrue(concordReads("((action (agent-identifier :name ams@C) (get-description)))") instanceof Action);
        ContentException e = assertThrows(ContentException.class,
                () -> concordReads("((action (agent-identifier :name df@C) (search (df-agent-description))))"));
        assertTrue(e.reason().contains("constraints"), e.reason());
    }
}
