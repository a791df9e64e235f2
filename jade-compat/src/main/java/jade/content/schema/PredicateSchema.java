package jade.content.schema;

/** The schema of a predicate: slots written by position in their order, {@code (Owns buyer book)}. */
public class PredicateSchema extends ContentElementSchema {
    private static final long serialVersionUID = 1L;
    /** The base name. */
    public static final String BASE_NAME = "Predicate";
    private static final ObjectSchema BASE = new PredicateSchema(BASE_NAME);

    /** The schema of any predicate. */
    public static ObjectSchema getBaseSchema() {
        return BASE;
    }

    /** A predicate schema of that name. */
    public PredicateSchema(String typeName) {
        super(typeName);
    }

    /** Adds a mandatory slot. */
    public void add(String name, ObjectSchema slotSchema) {
        super.add(name, slotSchema);
    }

    /** Adds a slot, {@link #MANDATORY} or {@link #OPTIONAL}. */
    public void add(String name, ObjectSchema slotSchema, int optionality) {
        super.add(name, slotSchema, optionality);
    }

    /** Adds a {@code sequence} slot of elements of that schema, with that cardinality. */
    public void add(String name, TermSchema elementsSchema, int cardMin, int cardMax) {
        super.add(name, elementsSchema, cardMin, cardMax);
    }

    /** Adds an aggregate slot of that type. */
    public void add(String name, TermSchema elementsSchema, int cardMin, int cardMax, String aggregateType) {
        super.add(name, elementsSchema, cardMin, cardMax, aggregateType);
    }

    /** Adds an aggregate slot of that type and optionality. */
    public void add(String name, ObjectSchema elementsSchema, int cardMin, int cardMax, String aggregateType, int optionality) {
        super.add(name, elementsSchema, cardMin, cardMax, aggregateType, optionality);
    }

    /** Makes this predicate inherit that one's slots. */
    public void addSuperSchema(PredicateSchema superSchema) {
        super.addSuperSchema(superSchema);
    }
}
