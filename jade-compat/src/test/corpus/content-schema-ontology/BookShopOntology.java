import jade.content.onto.BasicOntology;
import jade.content.onto.Ontology;
import jade.content.onto.OntologyException;
import jade.content.schema.AgentActionSchema;
import jade.content.schema.ConceptSchema;
import jade.content.schema.ObjectSchema;
import jade.content.schema.PredicateSchema;
import jade.content.schema.PrimitiveSchema;

/** The book shop's ontology written by hand, as JADE's older tutorials write one: a singleton of schemas. */
public class BookShopOntology extends Ontology {
    public static final String NAME = "book-shop";

    public static final String BOOK = "Book";
    public static final String BOOK_TITLE = "title";
    public static final String BOOK_AUTHORS = "authors";
    public static final String BOOK_PRICE = "price";
    public static final String BOOK_PAGES = "pages";
    public static final String BOOK_PUBLISHED = "published";

    public static final String SELL = "Sell";
    public static final String SELL_BOOK = "book";

    public static final String BROWSE = "browse-books";
    public static final String BROWSE_AUTHOR = "author";

    public static final String OWNS = "Owns";
    public static final String OWNS_OWNER = "owner";
    public static final String OWNS_BOOK = "book";

    private static final Ontology INSTANCE = new BookShopOntology();

    public static Ontology getInstance() {
        return INSTANCE;
    }

    private BookShopOntology() {
        super(NAME, BasicOntology.getInstance());
        try {
            add(new ConceptSchema(BOOK), Book.class);
            add(new AgentActionSchema(SELL), Sell.class);
            add(new AgentActionSchema(BROWSE), Browse.class);
            add(new PredicateSchema(OWNS), Owns.class);

            ConceptSchema cs = (ConceptSchema) getSchema(BOOK);
            cs.add(BOOK_TITLE, (PrimitiveSchema) getSchema(BasicOntology.STRING));
            cs.add(BOOK_AUTHORS, (PrimitiveSchema) getSchema(BasicOntology.STRING), 1, ObjectSchema.UNLIMITED);
            cs.add(BOOK_PRICE, (PrimitiveSchema) getSchema(BasicOntology.FLOAT), ObjectSchema.OPTIONAL);
            cs.add(BOOK_PAGES, (PrimitiveSchema) getSchema(BasicOntology.INTEGER), ObjectSchema.OPTIONAL);
            cs.add(BOOK_PUBLISHED, (PrimitiveSchema) getSchema(BasicOntology.DATE), ObjectSchema.OPTIONAL);

            AgentActionSchema as = (AgentActionSchema) getSchema(SELL);
            as.add(SELL_BOOK, (ConceptSchema) getSchema(BOOK));

            as = (AgentActionSchema) getSchema(BROWSE);
            as.add(BROWSE_AUTHOR, (PrimitiveSchema) getSchema(BasicOntology.STRING));

            PredicateSchema ps = (PredicateSchema) getSchema(OWNS);
            ps.add(OWNS_OWNER, (ConceptSchema) getSchema(BasicOntology.AID));
            ps.add(OWNS_BOOK, (ConceptSchema) getSchema(BOOK));
        } catch (OntologyException oe) {
            oe.printStackTrace();
        }
    }
}
