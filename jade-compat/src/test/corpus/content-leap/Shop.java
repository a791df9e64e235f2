import jade.content.lang.Codec;
import jade.content.lang.leap.LEAPCodec;
import jade.content.onto.BasicOntology;
import jade.content.onto.BeanOntology;
import jade.content.onto.BeanOntologyException;
import jade.content.onto.Ontology;

/** The shop's language and ontology: LEAP (binary content) and a bean ontology of annotated classes. */
public final class Shop {
    /** Whether the language is text (the raw-text cases apply). */
    public static final boolean TEXT = false;

    private Shop() {
    }

    public static Codec codec() {
        return new LEAPCodec();
    }

    public static Ontology ontology() {
        BeanOntology o = new BeanOntology("book-shop", BasicOntology.getInstance());
        try {
            o.add(Book.class);
            o.add(Sell.class);
            o.add(Browse.class);
            o.add(Owns.class);
        } catch (BeanOntologyException e) {
            throw new IllegalStateException(e);
        }
        return o;
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
