import jade.content.onto.BeanOntology;
import jade.content.onto.BeanOntologyException;
import jade.content.onto.Ontology;

/** The shop's bean ontology. */
public final class ShopOntology {
    private static Ontology instance;

    private ShopOntology() {
    }

    public static synchronized Ontology getInstance() {
        if (instance == null) {
            try {
                BeanOntology o = new BeanOntology("shop");
                o.add(Sell.class);
                o.add(Buy.class);
                o.add(Owns.class);
                instance = o;
            } catch (BeanOntologyException e) {
                throw new IllegalStateException(e);
            }
        }
        return instance;
    }
}
