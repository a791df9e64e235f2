import jade.content.onto.BasicOntology;
import jade.content.onto.Ontology;
import jade.content.onto.OntologyException;
import jade.content.onto.ReflectiveIntrospector;
import jade.content.schema.AgentActionSchema;
import jade.content.schema.ConceptSchema;
import jade.content.schema.ObjectSchema;
import jade.content.schema.PredicateSchema;
import jade.content.schema.PrimitiveSchema;

/** The music shop of JADE's content tutorial, written from its description: items, CDs with tracks, books, people. */
public class MusicShopOntology extends Ontology {
    public static final String ONTOLOGY_NAME = "music-shop";

    public static final String ITEM = "item";
    public static final String ITEM_SERIAL = "serial-number";
    public static final String CD = "cd";
    public static final String CD_TITLE = "title";
    public static final String CD_TRACKS = "tracks";
    public static final String BOOK = "book";
    public static final String BOOK_TITLE = "title";
    public static final String BOOK_AUTHOR = "author";
    public static final String TRACK = "track";
    public static final String TRACK_NAME = "name";
    public static final String TRACK_DURATION = "duration";
    public static final String ADDRESS = "address";
    public static final String ADDRESS_STREET = "street";
    public static final String ADDRESS_NUMBER = "number";
    public static final String ADDRESS_CITY = "city";
    public static final String PERSON = "person";
    public static final String PERSON_NAME = "name";
    public static final String PERSON_ADDRESS = "address";
    public static final String SELL = "sell";
    public static final String SELL_BUYER = "buyer";
    public static final String SELL_ITEM = "item";
    public static final String SELL_CREDIT_CARD = "credit-card";
    public static final String COSTS = "costs";
    public static final String COSTS_ITEM = "item";
    public static final String COSTS_PRICE = "price";
    public static final String OWNS = "owns";
    public static final String OWNS_OWNER = "owner";
    public static final String OWNS_THING = "thing";

    private static Ontology theInstance = new MusicShopOntology();

    public static Ontology getInstance() {
        return theInstance;
    }

    private MusicShopOntology() {
        super(ONTOLOGY_NAME, BasicOntology.getInstance(), new ReflectiveIntrospector());
        try {
            add(new ConceptSchema(ITEM), Item.class);
            add(new ConceptSchema(CD), CD.class);
            add(new ConceptSchema(BOOK), Book.class);
            add(new ConceptSchema(TRACK), Track.class);
            add(new ConceptSchema(ADDRESS), Address.class);
            add(new ConceptSchema(PERSON), Person.class);
            add(new AgentActionSchema(SELL), Sell.class);
            add(new PredicateSchema(COSTS), Costs.class);
            add(new PredicateSchema(OWNS), Owns.class);

            ConceptSchema cs = (ConceptSchema) getSchema(ITEM);
            cs.add(ITEM_SERIAL, (PrimitiveSchema) getSchema(BasicOntology.INTEGER), ObjectSchema.OPTIONAL);

            cs = (ConceptSchema) getSchema(CD);
            cs.addSuperSchema((ConceptSchema) getSchema(ITEM));
            cs.add(CD_TITLE, (PrimitiveSchema) getSchema(BasicOntology.STRING));
            cs.add(CD_TRACKS, (ConceptSchema) getSchema(TRACK), 1, ObjectSchema.UNLIMITED);

            cs = (ConceptSchema) getSchema(BOOK);
            cs.addSuperSchema((ConceptSchema) getSchema(ITEM));
            cs.add(BOOK_TITLE, (PrimitiveSchema) getSchema(BasicOntology.STRING));
            cs.add(BOOK_AUTHOR, (PrimitiveSchema) getSchema(BasicOntology.STRING), ObjectSchema.OPTIONAL);

            cs = (ConceptSchema) getSchema(TRACK);
            cs.add(TRACK_NAME, (PrimitiveSchema) getSchema(BasicOntology.STRING));
            cs.add(TRACK_DURATION, (PrimitiveSchema) getSchema(BasicOntology.INTEGER), ObjectSchema.OPTIONAL);

            cs = (ConceptSchema) getSchema(ADDRESS);
            cs.add(ADDRESS_STREET, (PrimitiveSchema) getSchema(BasicOntology.STRING));
            cs.add(ADDRESS_NUMBER, (PrimitiveSchema) getSchema(BasicOntology.INTEGER));
            cs.add(ADDRESS_CITY, (PrimitiveSchema) getSchema(BasicOntology.STRING));

            cs = (ConceptSchema) getSchema(PERSON);
            cs.add(PERSON_NAME, (PrimitiveSchema) getSchema(BasicOntology.STRING));
            cs.add(PERSON_ADDRESS, (ConceptSchema) getSchema(ADDRESS), ObjectSchema.OPTIONAL);

            AgentActionSchema as = (AgentActionSchema) getSchema(SELL);
            as.add(SELL_BUYER, (ConceptSchema) getSchema(PERSON));
            as.add(SELL_ITEM, (ConceptSchema) getSchema(ITEM));
            as.add(SELL_CREDIT_CARD, (PrimitiveSchema) getSchema(BasicOntology.STRING), ObjectSchema.OPTIONAL);

            PredicateSchema ps = (PredicateSchema) getSchema(COSTS);
            ps.add(COSTS_ITEM, (ConceptSchema) getSchema(ITEM));
            ps.add(COSTS_PRICE, (PrimitiveSchema) getSchema(BasicOntology.FLOAT));

            ps = (PredicateSchema) getSchema(OWNS);
            ps.add(OWNS_OWNER, (ConceptSchema) getSchema(PERSON));
            ps.add(OWNS_THING, (ConceptSchema) ConceptSchema.getBaseSchema());
        } catch (OntologyException oe) {
            oe.printStackTrace();
        }
    }
}
