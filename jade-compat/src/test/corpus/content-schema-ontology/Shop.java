import jade.content.lang.Codec;
import jade.content.lang.sl.SLCodec;


import jade.content.onto.Ontology;

/** The shop's language and ontology: SL and an ontology written by hand. */
public final class Shop {
    /** Whether the language is text (the raw-text cases apply). */
    public static final boolean TEXT = true;

    private Shop() {
    }

    public static Codec codec() {
        return new SLCodec();
    }

    public static Ontology ontology() {
        return BookShopOntology.getInstance();
    }

    /** A new Sell of that book. */
    public static Sell sell(Book b) {
        Sell s = new Sell();
        s.setBook(b);
        return s;
    }

    /** A new Browse of that author. */
    public static Browse browse(String author) {
        Browse b = new Browse();
        b.setAuthor(author);
        return b;
    }

    /** A new Owns. */
    public static Owns owns(jade.core.AID owner, Book b) {
        Owns o = new Owns();
        o.setOwner(owner);
        o.setBook(b);
        return o;
    }
}
