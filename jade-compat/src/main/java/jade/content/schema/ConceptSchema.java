package jade.content.schema;

/** The schema of a concept: named slots, written {@code (Book :title X)}. */
public class ConceptSchema extends TermSchema {
    private static final long serialVersionUID = 1L;
    /** The base name. */
    public static final String BASE_NAME = "Concept";
    private static final ObjectSchema BASE = new ConceptSchema(BASE_NAME);

    /** The schema of any concept (a slot of this schema takes any concept). */
    public static ObjectSchema getBaseSchema() {
        return BASE;
    }

    /** A concept schema of that name. */
    public ConceptSchema(String typeName) {
        super(typeName);
    }

    /** Adds a mandatory slot. */
    public void add(String name, TermSchema slotSchema) {
        super.add(name, slotSchema);
    }

    /** Adds a slot, {@link #MANDATORY} or {@link #OPTIONAL}. */
    public void add(String name, TermSchema slotSchema, int optionality) {
        super.add(name, slotSchema, optionality);
    }

    /** Adds a {@code sequence} slot of elements of that schema, with that cardinality. */
    public void add(String name, TermSchema elementsSchema, int cardMin, int cardMax) {
        super.add(name, elementsSchema, cardMin, cardMax);
    }

    /** Adds an aggregate slot of that type ({@code sequence} or {@code set}). */
    public void add(String name, TermSchema elementsSchema, int cardMin, int cardMax, String aggregateType) {
        super.add(name, elementsSchema, cardMin, cardMax, aggregateType);
    }

    /** Adds an aggregate slot of that type and optionality. */
    public void add(String name, ObjectSchema elementsSchema, int cardMin, int cardMax, String aggregateType, int optionality) {
        super.add(name, elementsSchema, cardMin, cardMax, aggregateType, optionality);
    }

    /** Makes this concept inherit that one's slots. */
    public void addSuperSchema(ConceptSchema superSchema) {
        super.addSuperSchema(superSchema);
    }
}
