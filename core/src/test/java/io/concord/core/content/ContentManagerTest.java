package io.concord.core.content;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.content.BookShop.Author;
import io.concord.core.content.BookShop.Book;
import io.concord.core.content.BookShop.Owns;
import io.concord.core.content.BookShop.Sell;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Filling and extracting content through the ontology, and the reasons given when it is refused. */
class ContentManagerTest {
    private final ContentManager manager = new ContentManager().register(new SlCodec()).register(BookShop.ontology());
    private final AID seller = new AID("seller@P", "http://h:7778/acc");

    private static Book book(String title) {
        return new Book(title, 100, null, 9.5, 4.5f, false, null, null, List.of("x"), Set.of(7L), null);
    }

    @Test
    void fillWritesTheContentAndNamesLanguageAndOntology() throws Exception {
        AclMessage msg = new AclMessage(Performative.REQUEST);
        manager.fill(msg, new Action(seller, new Sell(book("X"), null, null, null)));
        assertEquals("fipa-sl", msg.getLanguage());
        assertEquals("book-shop", msg.getOntology());
        assertEquals("((action (agent-identifier :name seller@P :addresses (sequence http://h:7778/acc)) (Sell :book "
                + "(Book :isbns (set 7) :pages 100 :price 9.5 :rating 4.5 :tags (sequence x) :title X :used false))))",
                msg.getContent());
    }

    @Test
    void extractGivesBackTheSameObjects() throws Exception {
        Owns owns = new Owns(seller, new Book("T", 1, 2, 0.5, 0.25f, true, java.time.Instant.ofEpochMilli(1_700_000_000_123L),
                null, null, null, List.of(new Author("Ann", List.of("A."), new Author("Bob", null, null)))));
        AclMessage msg = new AclMessage(Performative.INFORM);
        manager.fill(msg, owns);
        assertEquals(JadeMapping.canon(owns), JadeMapping.canon(manager.extract(msg)));
    }

    private String reason(String content) {
        AclMessage msg = new AclMessage(Performative.REQUEST).setLanguage("fipa-sl").setOntology("book-shop").setContent(content);
        return assertThrows(ContentException.class, () -> manager.extract(msg)).reason();
    }

    @Test
    void extractExplainsWhatIsWrong() {
        assertEquals("missing mandatory slot :title of Book", reason("((Owns (Book :pages 1 :price 1.0 :rating 1.0 :used true) (agent-identifier :name a@P)))"));
        assertEquals("unknown slot :colour of Book", reason("((Owns (Book :title x :colour red) (agent-identifier :name a@P)))"));
        assertEquals("slot :pages of Book: expected integer, got string", reason("((Owns (Book :title x :pages many) (agent-identifier :name a@P)))"));
        assertEquals("argument 2 of action: no schema in ontology book-shop for symbol Buy",
                reason("((action (agent-identifier :name a@P) (Buy)))"));
        assertEquals("content element Book is neither a proposition nor an action", reason("((Book :title x))"));
        assertTrue(reason("((Owns (agent-identifier :name a@P)").contains("unexpected end of text at position"));
        assertEquals("slot :isbns of Book must be a set", reason("((Owns (Book :title x :pages 1 :price 1.0 :rating 1.0 :used true :isbns (sequence 1)) (agent-identifier :name a@P)))"));
    }

    @Test
    void unknownLanguageOrOntologyIsNamed() {
        AclMessage msg = new AclMessage(Performative.REQUEST).setLanguage("fipa-sl").setOntology("cooking").setContent("((true))");
        assertEquals("unknown ontology cooking", assertThrows(ContentException.class, () -> manager.extract(msg)).reason());
        msg.setLanguage("kif").setOntology("book-shop");
        assertEquals("unknown language kif", assertThrows(ContentException.class, () -> manager.extract(msg)).reason());
    }

    @Test
    void fillRefusesContentThatBreaksTheSchema() {
        AclMessage msg = new AclMessage(Performative.INFORM);
        assertEquals("missing mandatory slot :title of Book",
                assertThrows(ContentException.class, () -> manager.fill(msg, new Owns(seller, book(null)))).reason());
        assertTrue(assertThrows(ContentException.class, () -> manager.fill(msg, book("X"))).reason().contains("cannot be content on its own"));
    }

    @Test
    void cardinalityIsChecked() throws Exception {
        BeanOntology o = new BeanOntology("lists", Shelf.class);
        ContentManager m = new ContentManager().register(new SlCodec()).register(o);
        AclMessage msg = new AclMessage(Performative.INFORM);
        assertEquals("slot :titles of Shelf has 0 element(s), allowed 1..2",
                assertThrows(ContentException.class, () -> m.fill(msg, new Shelf(List.of()))).reason());
        m.fill(msg, new Shelf(List.of("a", "b")));
        assertEquals("((Shelf (sequence a b)))", msg.getContent());
        msg.setContent("((Shelf (sequence a b c)))");
        assertEquals("slot :titles of Shelf has 3 element(s), allowed 1..2", assertThrows(ContentException.class, () -> m.extract(msg)).reason());
    }

    record Shelf(@Slot(cardMin = 1, cardMax = 2) List<String> titles) implements Predicate {
    }

    @Test
    void theBasicOntologyCarriesDoneResultEqualsAndTrue() throws Exception {
        Action act = new Action(seller, new Sell(book("X"), null, null, null));
        for (Object content : List.of(new Done(act), new Result(act, List.of(1L, "two")), new Equals("a", 2L), new TrueProposition(), new FalseProposition())) {
            AclMessage msg = new AclMessage(Performative.INFORM);
            manager.fill(msg, content);
            assertEquals(JadeMapping.canon(content), JadeMapping.canon(manager.extract(msg)), msg.getContent());
        }
    }
}
