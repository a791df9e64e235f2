package io.concord.bench.jade;

import jade.content.AgentAction;
import jade.content.Concept;
import jade.content.onto.BeanOntology;
import jade.content.onto.BeanOntologyException;
import jade.content.onto.Ontology;

import java.util.Date;
import java.util.List;

/**
 * The content benchmark's ontology as a JADE user writes it: a 10-slot agent action
 * ({@code Order}) with a nested concept ({@code Address}), for JADE's BeanOntology.
 */
public final class JadeOrderOntology {
    private JadeOrderOntology() {
    }

    /** Where to deliver. */
    @jade.content.onto.annotations.Element(name = "Address")
    public static class Address implements Concept {
        private String street;
        private String city;

        public String getStreet() { return street; }
        public void setStreet(String v) { street = v; }
        public String getCity() { return city; }
        public void setCity(String v) { city = v; }
    }

    /** The action: ten slots of every kind. */
    @jade.content.onto.annotations.Element(name = "Order")
    public static class Order implements AgentAction {
        private String title;
        private long quantity;
        private int edition;
        private double price;
        private float rating;
        private boolean express;
        private Date due;
        private List<String> tags;
        private String note;
        private Address address;

        public String getTitle() { return title; }
        public void setTitle(String v) { title = v; }
        public long getQuantity() { return quantity; }
        public void setQuantity(long v) { quantity = v; }
        public int getEdition() { return edition; }
        public void setEdition(int v) { edition = v; }
        public double getPrice() { return price; }
        public void setPrice(double v) { price = v; }
        public float getRating() { return rating; }
        public void setRating(float v) { rating = v; }
        public boolean isExpress() { return express; }
        public void setExpress(boolean v) { express = v; }
        public Date getDue() { return due; }
        public void setDue(Date v) { due = v; }
        public List<String> getTags() { return tags; }
        public void setTags(List<String> v) { tags = v; }
        public String getNote() { return note; }
        public void setNote(String v) { note = v; }
        public Address getAddress() { return address; }
        public void setAddress(Address v) { address = v; }
    }

    /** The ontology, named as Concord's twin. */
    public static Ontology ontology() throws BeanOntologyException {
        BeanOntology o = new BeanOntology("orders");
        o.add(Address.class);
        o.add(Order.class);
        return o;
    }

    /** The order every run fills and extracts. */
    public static Order sample() {
        Address a = new Address();
        a.setStreet("1 Main Street");
        a.setCity("Lisbon");
        Order o = new Order();
        o.setTitle("The \"Agents\" Book");
        o.setQuantity(3);
        o.setEdition(2);
        o.setPrice(49.95);
        o.setRating(4.5f);
        o.setExpress(true);
        o.setDue(new Date(1_700_000_000_123L));
        o.setTags(List.of("agents", "fipa", "sl"));
        o.setNote("leave at door");
        o.setAddress(a);
        return o;
    }
}
