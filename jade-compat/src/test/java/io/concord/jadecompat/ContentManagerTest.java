package io.concord.jadecompat;

import jade.content.AgentAction;
import jade.content.Concept;
import jade.content.ContentElement;
import jade.content.ContentElementList;
import jade.content.ContentManager;
import jade.content.Predicate;
import jade.content.lang.Codec;
import jade.content.lang.leap.LEAPCodec;
import jade.content.lang.sl.SLCodec;
import jade.content.onto.BasicOntology;
import jade.content.onto.BeanOntology;
import jade.content.onto.BeanOntologyException;
import jade.content.onto.Ontology;
import jade.content.onto.OntologyException;
import jade.content.onto.UngroundedException;
import jade.content.onto.annotations.AggregateSlot;
import jade.content.onto.annotations.Slot;
import jade.content.onto.annotations.SuppressSlot;
import jade.content.onto.basic.Action;
import jade.content.onto.basic.Done;
import jade.content.onto.basic.TrueProposition;
import jade.core.AID;
import jade.lang.acl.ACLMessage;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * jade.content's ContentManager over Concord: what it writes, and what it throws where JADE throws
 * (the classes are the ones JADE 4.3 throws in the same cases; the corpus programs
 * content-bean-ontology and content-schema-ontology print them on both).
 */
class ContentManagerTest {

    /** A concept bean. */
    public static class Book implements Concept {
        private String title;
        private List<String> authors;
        private int pages;
        private String secret;

        @Slot(mandatory = true)
        public String getTitle() {
            return title;
        }

        public void setTitle(String title) {
            this.title = title;
        }

        @AggregateSlot(cardMax = 2)
        public List<String> getAuthors() {
            return authors;
        }

        public void setAuthors(List<String> authors) {
            this.authors = authors;
        }

        public int getPages() {
            return pages;
        }

        public void setPages(int pages) {
            this.pages = pages;
        }

        @SuppressSlot
        public String getSecret() {
            return secret;
        }

        public void setSecret(String secret) {
            this.secret = secret;
        }
    }

    /** An action bean. */
    public static class Sell implements AgentAction {
        private Book book;

        public Book getBook() {
            return book;
        }

        public void setBook(Book book) {
            this.book = book;
        }
    }

    /** A predicate bean, written by position. */
    public static class Owns implements Predicate {
        private AID owner;
        private Book book;

        public AID getOwner() {
            return owner;
        }

        public void setOwner(AID owner) {
            this.owner = owner;
        }

        public Book getBook() {
            return book;
        }

        public void setBook(Book book) {
            this.book = book;
        }
    }

    /** A bean with a subclass. */
    public static class Item implements Concept {
        private int serial;
        private String zeta;

        public int getSerial() {
            return serial;
        }

        public void setSerial(int serial) {
            this.serial = serial;
        }

        public String getZeta() {
            return zeta;
        }

        public void setZeta(String zeta) {
            this.zeta = zeta;
        }
    }

    /** A bean subclass: with buildHierarchy, Item's slots come first. */
    public static class Disc extends Item {
        private String title;
        private String alpha;

        public String getTitle() {
            return title;
        }

        public void setTitle(String title) {
            this.title = title;
        }

        public String getAlpha() {
            return alpha;
        }

        public void setAlpha(String alpha) {
            this.alpha = alpha;
        }
    }

    /** A predicate about an item. */
    public static class Has implements Predicate {
        private Item item;

        public Item getItem() {
            return item;
        }

        public void setItem(Item item) {
            this.item = item;
        }
    }

    private final AID seller = new AID("seller@P", AID.ISGUID);
    private ContentManager cm;

    @BeforeEach
    void setUp() throws BeanOntologyException {
        BeanOntology onto = new BeanOntology("shop", BasicOntology.getInstance());
        onto.add(Book.class);
        onto.add(Sell.class);
        onto.add(Owns.class);
        cm = new ContentManager();
        cm.registerLanguage(new SLCodec());
        cm.registerLanguage(new LEAPCodec());
        cm.registerOntology(onto);
    }

    private static ACLMessage message(String language, String content) {
        ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
        m.setLanguage(language);
        m.setOntology("shop");
        if (content != null) {
            m.setContent(content);
        }
        return m;
    }

    private static Book book(String title, int pages, String... authors) {
        Book b = new Book();
        b.setTitle(title);
        b.setPages(pages);
        b.setAuthors(authors.length == 0 ? null : List.of(authors));
        return b;
    }

    private static Sell sell(Book b) {
        Sell s = new Sell();
        s.setBook(b);
        return s;
    }

    @Test
    void registrationAndLookup() {
        assertArrayEquals(new String[]{"fipa-sl", "LEAP"}, cm.getLanguageNames());
        assertArrayEquals(new String[]{"shop"}, cm.getOntologyNames());
        assertInstanceOf(SLCodec.class, cm.lookupLanguage("fipa-sl"));
        assertNull(cm.lookupLanguage("nope"));
        assertEquals("shop", cm.lookupOntology("shop").getName());
        assertEquals("fipa-sl0", new SLCodec(0).getName());
        assertEquals("fipa-sl2", new SLCodec(2).getName());
        assertEquals("fipa-sl", new SLCodec(true).getName());
        cm.registerLanguage(new SLCodec(0), "my-sl");
        assertEquals("fipa-sl0", cm.lookupLanguage("my-sl").getName());
    }

    @Test
    void fillsSlAsJadeWritesItAndReadsItBack() throws Exception {
        ACLMessage m = message("fipa-sl", null);
        cm.fillContent(m, new Action(seller, sell(book("X Y", 10, "Ann"))));
        assertEquals("((action (agent-identifier :name seller@P) (Sell :book (Book :authors (sequence Ann) :pages 10 :title \"X Y\"))))",
                m.getContent());
        Action a = (Action) cm.extractContent(m);
        assertEquals("seller@P", a.getActor().getName());
        Book b = ((Sell) a.getAction()).getBook();
        assertEquals("X Y", b.getTitle());
        assertEquals(List.of("Ann"), b.getAuthors());
        assertEquals(10, b.getPages());

        Owns o = new Owns();
        o.setOwner(seller);
        o.setBook(book("Z", 1));
        cm.fillContent(m, o);
        assertEquals("((Owns (Book :pages 1 :title Z) (agent-identifier :name seller@P)))", m.getContent());
        assertEquals("Z", ((Owns) cm.extractContent(m)).getBook().getTitle());
    }

    @Test
    void severalElementsAreAContentElementList() throws Exception {
        ACLMessage m = message("fipa-sl", null);
        ContentElementList l = new ContentElementList();
        l.add(new TrueProposition());
        l.add(new Done(new Action(seller, sell(book("A", 2)))));
        cm.fillContent(m, l);
        ContentElement ce = cm.extractContent(m);
        ContentElementList back = assertInstanceOf(ContentElementList.class, ce);
        assertEquals(2, back.size());
        assertInstanceOf(TrueProposition.class, back.get(0));
        assertInstanceOf(Done.class, back.get(1));
    }

    @Test
    void leapCarriesTheSameObjectsAsBytes() throws Exception {
        ACLMessage m = message("LEAP", null);
        cm.fillContent(m, new Action(seller, sell(book("B", 3, "Ann", "Bob"))));
        assertTrue(m.hasByteSequenceContent());
        Book b = ((Sell) ((Action) cm.extractContent(m)).getAction()).getBook();
        assertEquals(List.of("Ann", "Bob"), b.getAuthors());
    }

    @Test
    void unknownLanguageIsACodecException() {
        Codec.CodecException e = assertThrows(Codec.CodecException.class, () -> cm.extractContent(message("klingon", "((true))")));
        assertEquals("Unknown language klingon", e.getMessage());
        assertThrows(Codec.CodecException.class, () -> cm.fillContent(message(null, null), new TrueProposition()));
    }

    @Test
    void unknownOntologyIsAnOntologyException() {
        ACLMessage m = message("fipa-sl", "(true)");
        m.setOntology("other");
        OntologyException e = assertThrows(OntologyException.class, () -> cm.extractContent(m));
        assertEquals("Unknown ontology other", e.getMessage());
    }

    @Test
    void missingMandatorySlotIsAnOntologyExceptionBothWays() {
        OntologyException read = assertThrows(OntologyException.class, () -> cm.extractContent(message("fipa-sl",
                "((action (agent-identifier :name s@P) (Sell :book (Book :pages 3))))")));
        assertEquals("missing mandatory slot :title of Book", read.getMessage());
        OntologyException write = assertThrows(OntologyException.class,
                () -> cm.fillContent(message("fipa-sl", null), new Action(seller, sell(book(null, 3)))));
        assertEquals("missing mandatory slot :title of Book", write.getMessage());
        OntologyException actor = assertThrows(OntologyException.class,
                () -> cm.fillContent(message("fipa-sl", null), new Action(null, sell(book("T", 3)))));
        assertEquals("missing mandatory slot :actor of action", actor.getMessage());
    }

    @Test
    void withoutValidationAMissingSlotReadsAsNull() throws Exception {
        cm.setValidationMode(false);
        Action a = (Action) cm.extractContent(message("fipa-sl", "((action (agent-identifier :name s@P) (Sell :book (Book :pages 3))))"));
        assertNull(((Sell) a.getAction()).getBook().getTitle());
    }

    @Test
    void aSlotTheSchemaLacksIsIgnoredAsJadeIgnoresIt() throws Exception {
        Action a = (Action) cm.extractContent(message("fipa-sl",
                "((action (agent-identifier :name s@P) (Sell :book (Book :title T :pages 2 :secret s))))"));
        Book b = ((Sell) a.getAction()).getBook();
        assertEquals("T", b.getTitle());
        assertNull(b.getSecret());
    }

    @Test
    void variableIsUngrounded() {
        assertThrows(UngroundedException.class, () -> cm.extractContent(message("fipa-sl",
                "((action (agent-identifier :name s@P) (Sell :book ?b)))")));
    }

    @Test
    void malformedTextIsACodecException() {
        assertThrows(Codec.CodecException.class, () -> cm.extractContent(message("fipa-sl", "((action (agent-identifier")));
        assertThrows(Codec.CodecException.class, () -> cm.extractContent(message("fipa-sl", null)));
    }

    @Test
    void contentOutsideTheSchemasIsAnOntologyException() {
        OntologyException type = assertThrows(OntologyException.class, () -> cm.extractContent(message("fipa-sl",
                "((action (agent-identifier :name s@P) (Sell :book (Book :title T :pages ten))))")));
        assertEquals("slot :pages of Book: expected BO_Integer, got a string", type.getMessage());
        OntologyException symbol = assertThrows(OntologyException.class, () -> cm.extractContent(message("fipa-sl",
                "((Rents x y))")));
        assertTrue(symbol.getMessage().contains("no schema in ontology shop for symbol Rents"), symbol.getMessage());
        OntologyException card = assertThrows(OntologyException.class, () -> cm.extractContent(message("fipa-sl",
                "((action (agent-identifier :name s@P) (Sell :book (Book :title T :authors (sequence a b c)))))")));
        assertEquals("slot :authors of Book has 3 element(s), allowed 0..2", card.getMessage());
        OntologyException concept = assertThrows(OntologyException.class, () -> cm.extractContent(message("fipa-sl",
                "((Book :title T :pages 1))")));
        assertTrue(concept.getMessage().contains("neither a predicate nor an agent action"), concept.getMessage());
    }

    @Test
    void aBeanSubclassHasItsSuperclassAsSuperSchemaAsInJade() throws Exception {
        BeanOntology o = new BeanOntology("items");
        o.add(Item.class);
        o.add(Disc.class);
        o.add(Has.class);
        cm.registerOntology(o);
        Disc d = new Disc();
        d.setSerial(3);
        d.setZeta("z");
        d.setTitle("T");
        d.setAlpha("A");
        Has h = new Has();
        h.setItem(d);
        ACLMessage m = message("fipa-sl", null);
        m.setOntology("items");
        cm.fillContent(m, h);
        // JADE 4.3's BeanOntology, given the same Item and Disc, wrote (Disc :serial 3 :zeta z :alpha A :title T):
        // add(Class) builds the hierarchy, the super-schema's slots first, each schema's own alphabetically
        assertEquals("((Has (Disc :serial 3 :zeta z :alpha A :title T)))", m.getContent());
        Disc back = (Disc) ((Has) cm.extractContent(m)).getItem();
        assertEquals(3, back.getSerial());
        assertEquals("A", back.getAlpha());
        assertArrayEquals(new String[]{"serial", "zeta", "alpha", "title"}, o.getSchema("Disc").getNames());
    }

    @Test
    void aPackageIsAddedWhole() throws Exception {
        BeanOntology o = new BeanOntology("sky");
        o.add("io.concord.jadecompat.beans");
        assertEquals(io.concord.jadecompat.beans.Planet.class, o.getClassForElement("Planet"));
        assertEquals(io.concord.jadecompat.beans.Orbits.class, o.getClassForElement("Orbits"));
        assertNull(o.getSchema("NotContent"));
        assertThrows(BeanOntologyException.class, () -> o.add("io.concord.jadecompat.nothing.here"));
    }

    @Test
    void agentHasOneContentManager() {
        jade.core.Agent a = new jade.core.Agent();
        assertSame(a.getContentManager(), a.getContentManager());
    }

    @Test
    void handWrittenSchemasAreReadBack() throws Exception {
        Ontology basic = BasicOntology.getInstance();
        assertEquals(BasicOntology.STRING, basic.getSchema(BasicOntology.STRING).getTypeName());
        assertEquals("agent-identifier", basic.getSchema(AID.class).getTypeName());
        Ontology shop = cm.lookupOntology("shop");
        assertArrayEquals(new String[]{"authors", "pages", "title"}, shop.getSchema("Book").getNames());
        assertTrue(shop.getSchema("Book").isMandatory("pages"), "an int slot is mandatory");
        assertEquals(Book.class, shop.getClassForElement("Book"));
    }
}
