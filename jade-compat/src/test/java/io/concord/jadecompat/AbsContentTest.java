package io.concord.jadecompat;

import jade.content.ContentManager;
import jade.content.abs.AbsAgentAction;
import jade.content.abs.AbsAggregate;
import jade.content.abs.AbsConcept;
import jade.content.abs.AbsContentElement;
import jade.content.abs.AbsIRE;
import jade.content.abs.AbsObject;
import jade.content.abs.AbsPredicate;
import jade.content.abs.AbsPrimitive;
import jade.content.abs.AbsVariable;
import jade.content.lang.StringCodec;
import jade.content.lang.sl.SLCodec;
import jade.content.lang.sl.SLVocabulary;
import jade.content.onto.BasicOntology;
import jade.content.onto.BeanOntology;
import jade.content.onto.Ontology;
import jade.content.onto.basic.Action;
import jade.core.AID;
import jade.lang.acl.ACLMessage;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

/** jade.content.abs: abstract descriptors written and read through the codecs, the ontologies and the content manager. */
class AbsContentTest {
    private static final String SELL = "((action (agent-identifier :name seller@P) (Sell :book (Book :authors (sequence Ann) :pages 10 :title X))))";

    private Ontology onto;
    private ContentManager cm;

    @BeforeEach
    void setUp() throws Exception {
        BeanOntology o = new BeanOntology("shop", BasicOntology.getInstance());
        o.add(ContentManagerTest.Book.class);
        o.add(ContentManagerTest.Sell.class);
        o.add(ContentManagerTest.Owns.class);
        onto = o;
        cm = new ContentManager();
        cm.registerLanguage(new SLCodec());
        cm.registerOntology(onto);
    }

    private static ACLMessage message(String language) {
        ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
        m.setLanguage(language);
        m.setOntology("shop");
        return m;
    }

    private AbsAgentAction sell() throws Exception {
        AbsConcept book = new AbsConcept("Book");
        book.set("title", "X");
        book.set("pages", 10);
        AbsAggregate authors = new AbsAggregate(BasicOntology.SEQUENCE);
        authors.add(AbsPrimitive.wrap("Ann"));
        book.set("authors", authors);
        AbsAgentAction sell = new AbsAgentAction("Sell");
        sell.set("book", book);
        AbsAgentAction action = new AbsAgentAction(BasicOntology.ACTION);
        action.set(BasicOntology.ACTION_ACTOR, (AbsConcept) onto.fromObject(new AID("seller@P", AID.ISGUID)));
        action.set(BasicOntology.ACTION_ACTION, sell);
        return action;
    }

    @Test
    void abstractContentIsWrittenAsObjectsAreAndReadBack() throws Exception {
        ACLMessage m = message("fipa-sl");
        cm.fillContent(m, sell());
        assertEquals(SELL, m.getContent());
        AbsContentElement back = cm.extractAbsContent(m);
        AbsAgentAction action = assertInstanceOf(AbsAgentAction.class, back);
        assertEquals("action", action.getTypeName());
        AbsConcept actor = (AbsConcept) action.getAbsObject("actor");
        assertEquals("seller@P", actor.getString("name"));
        AbsConcept book = (AbsConcept) ((AbsAgentAction) action.getAbsObject("action")).getAbsObject("book");
        assertEquals("X", book.getString("title"));
        assertEquals(10, book.getInteger("pages"));
        assertEquals("Ann", ((AbsPrimitive) ((AbsAggregate) book.getAbsObject("authors")).get(0)).getString());
        Action a = (Action) onto.toObject(back);
        assertEquals("X", ((ContentManagerTest.Sell) a.getAction()).getBook().getTitle());
    }

    @Test
    void positionalArgumentsGetTheSchemasSlotNames() throws Exception {
        ACLMessage m = message("fipa-sl");
        m.setContent("((Owns (Book :pages 1 :title Z) (agent-identifier :name a@P)))");
        AbsPredicate owns = assertInstanceOf(AbsPredicate.class, cm.extractAbsContent(m));
        assertEquals(List.of("book", "owner"), List.of(owns.getNames()));
        assertEquals("Z", ((AbsConcept) owns.getAbsObject("book")).getString("title"));
        cm.fillContent(m, owns);
        assertEquals("((Owns (Book :pages 1 :title Z) (agent-identifier :name a@P)))", m.getContent());
    }

    @Test
    void operatorsAndVariablesReadAndWriteBackAsJadeWritesThem() throws Exception {
        SLCodec sl = new SLCodec();
        for (String text : List.of("((and true (not false)))", "((iota ?x (= ?x ?x)))",
                "((B (agent-identifier :name a@P) (U (agent-identifier :name b@P) true)))", "(true (= 1 1) )")) {
            AbsContentElement e = sl.decode(onto, text);
            assertEquals(text, sl.encode(onto, e), text);
        }
        AbsPredicate and = (AbsPredicate) sl.decode("((and true (not false)))");
        assertEquals("true", and.getAbsObject("left").getTypeName());
        assertEquals("not", and.getAbsObject("right").getTypeName());
        AbsIRE iota = (AbsIRE) sl.decode("((iota ?x (= ?x ?x)))");
        assertEquals("x", iota.getVariable().getName());
        assertEquals("=", iota.getProposition().getTypeName());
        assertFalse(iota.isGrounded());
        AbsIRE all = (AbsIRE) sl.decode("((all (sequence ?x ?y) (= ?x ?y)))");
        assertEquals(2, all.getVariables().size());
        AbsIRE any = new AbsIRE(SLVocabulary.ANY);
        AbsVariable y = new AbsVariable("y", BasicOntology.STRING);
        AbsPredicate eq = new AbsPredicate(BasicOntology.EQUALS);
        eq.set(BasicOntology.EQUALS_LEFT, y);
        eq.set(BasicOntology.EQUALS_RIGHT, AbsPrimitive.wrap("a b"));
        any.setVariable(y);
        any.setProposition(eq);
        assertEquals("((any ?y (= ?y \"a b\")))", sl.encode(any));
    }

    /** A codec of one's own, as JADE lets a user write: SL read and written backwards. */
    static final class Backwards extends StringCodec {
        private final SLCodec sl = new SLCodec();

        Backwards() {
            super("backwards-sl");
        }

        @Override
        public String encode(AbsContentElement content) throws CodecException {
            return encode(BasicOntology.getInstance(), content);
        }

        @Override
        public String encode(Ontology ontology, AbsContentElement content) throws CodecException {
            return new StringBuilder(sl.encode(ontology, content)).reverse().toString();
        }

        @Override
        public AbsContentElement decode(String content) throws CodecException {
            return decode(BasicOntology.getInstance(), content);
        }

        @Override
        public AbsContentElement decode(Ontology ontology, String content) throws CodecException {
            return sl.decode(ontology, new StringBuilder(content).reverse().toString());
        }
    }

    @Test
    void aCodecOfOnesOwnCarriesObjects() throws Exception {
        cm.registerLanguage(new Backwards());
        ACLMessage m = message("backwards-sl");
        ContentManagerTest.Book b = new ContentManagerTest.Book();
        b.setTitle("X");
        b.setPages(10);
        b.setAuthors(List.of("Ann"));
        ContentManagerTest.Sell s = new ContentManagerTest.Sell();
        s.setBook(b);
        cm.fillContent(m, new Action(new AID("seller@P", AID.ISGUID), s));
        assertEquals(new StringBuilder(SELL).reverse().toString(), m.getContent());
        Action a = (Action) cm.extractContent(m);
        assertEquals(List.of("Ann"), ((ContentManagerTest.Sell) a.getAction()).getBook().getAuthors());
    }

    @Test
    void fromObjectGivesDescriptors() throws Exception {
        AbsObject aid = onto.fromObject(new AID("x@P", AID.ISGUID));
        assertEquals("agent-identifier", aid.getTypeName());
        assertEquals(AbsObject.ABS_CONCEPT, aid.getAbsType());
    }
}
