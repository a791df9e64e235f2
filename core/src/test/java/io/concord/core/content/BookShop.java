package io.concord.core.content;

import io.concord.core.acl.AID;

import java.time.Instant;
import java.util.List;
import java.util.Set;

/** The test ontology: nested concepts, aggregates, optional and repeated slots, every primitive. */
final class BookShop {
    private BookShop() {
    }

    record Author(@Slot(mandatory = true) String name, List<String> aliases, Author mentor) implements Concept {
    }

    record Book(@Slot(mandatory = true) String title, long pages, Integer edition, double price, float rating,
                boolean used, Instant published, byte[] cover, List<String> tags, Set<Long> isbns,
                List<Author> authors) implements Concept {
    }

    record Sell(@Slot(mandatory = true) Book book, List<Book> more, AID buyer, @Slot(name = "note") String remark)
            implements AgentAction {
    }

    record Owns(AID owner, Book book) implements Predicate {
    }

    static BeanOntology ontology() {
        return new BeanOntology("book-shop", Author.class, Book.class, Sell.class, Owns.class);
    }
}
