package io.concord.jade;

import java.util.List;

/** {@link BookTrading}'s ontology as JADE beans, for JADE 4.3's own BeanOntology. */
public final class JadeBookTrading {
    private JadeBookTrading() {
    }

    /** A book. */
    public static class Book implements jade.content.Concept {
        private String title;
        private List<String> authors;
        private Double price;

        @jade.content.onto.annotations.Slot(mandatory = true)
        public String getTitle() { return title; }
        public void setTitle(String v) { title = v; }
        public List<String> getAuthors() { return authors; }
        public void setAuthors(List<String> v) { authors = v; }
        public Double getPrice() { return price; }
        public void setPrice(Double v) { price = v; }

        @Override
        public String toString() {
            return "Book(" + title + ", " + authors + ", " + price + ")";
        }
    }

    /** Selling an item. */
    public static class Sell implements jade.content.AgentAction {
        private Book item;

        @jade.content.onto.annotations.Slot(mandatory = true)
        public Book getItem() { return item; }
        public void setItem(Book v) { item = v; }

        @Override
        public String toString() {
            return "Sell(" + item + ")";
        }
    }

    /** An item costs a price. */
    public static class Costs implements jade.content.Predicate {
        private Book item;
        private double price;

        @jade.content.onto.annotations.Slot(mandatory = true)
        public Book getItem() { return item; }
        public void setItem(Book v) { item = v; }
        public double getPrice() { return price; }
        public void setPrice(double v) { price = v; }

        @Override
        public String toString() {
            return "Costs(" + item + ", " + price + ")";
        }
    }

    static Book book(String title, List<String> authors, Double price) {
        Book b = new Book();
        b.setTitle(title);
        b.setAuthors(authors);
        b.setPrice(price);
        return b;
    }

    static jade.content.onto.Ontology ontology() throws jade.content.onto.BeanOntologyException {
        jade.content.onto.BeanOntology o = new jade.content.onto.BeanOntology(BookTrading.NAME);
        o.add(Book.class);
        o.add(Sell.class);
        o.add(Costs.class);
        return o;
    }
}
