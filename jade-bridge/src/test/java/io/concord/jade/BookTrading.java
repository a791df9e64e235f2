package io.concord.jade;

import io.concord.core.content.AgentAction;
import io.concord.core.content.BeanOntology;
import io.concord.core.content.Concept;
import io.concord.core.content.Predicate;
import io.concord.core.content.Slot;

import java.util.List;

/**
 * The book-trading ontology of JADE's tutorial, written by us from its description, as Concord
 * records for Concord's {@link BeanOntology}: a Book (title, authors, price), the action Sell of
 * an item, and the predicate Costs (item, price). {@link JadeBookTrading} is the same ontology as
 * JADE beans for JADE's BeanOntology.
 */
public final class BookTrading {
    public static final String NAME = "book-trading";

    private BookTrading() {
    }

    /** A book: its title is mandatory, authors and price are optional. */
    public record Book(@Slot(mandatory = true) String title, List<String> authors, Double price) implements Concept {
    }

    /** Selling an item. */
    public record Sell(@Slot(mandatory = true) Book item) implements AgentAction {
    }

    /** An item costs a price. */
    public record Costs(@Slot(mandatory = true) Book item, double price) implements Predicate {
    }

    public static BeanOntology ontology() {
        return new BeanOntology(NAME, Book.class, Sell.class, Costs.class);
    }
}
