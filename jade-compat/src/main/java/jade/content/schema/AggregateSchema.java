package jade.content.schema;

/** The schema of an aggregate, {@code sequence} or {@code set}, and of its elements. */
public class AggregateSchema extends TermSchema {
    private static final long serialVersionUID = 1L;
    /** The base name. */
    public static final String BASE_NAME = "Aggregate";
    private static final ObjectSchema BASE = new AggregateSchema(BASE_NAME);

    /** The schema of any aggregate (a sequence or a set). */
    public static ObjectSchema getBaseSchema() {
        return BASE;
    }
    private final TermSchema elementsSchema;

    /** An aggregate of any terms. */
    public AggregateSchema(String typeName) {
        this(typeName, null);
    }

    /** An aggregate of terms of that schema. */
    public AggregateSchema(String typeName, TermSchema elementsSchema) {
        super(typeName);
        this.elementsSchema = elementsSchema;
    }

    /** The schema of its elements, or null for any term. */
    public TermSchema getElementsSchema() {
        return elementsSchema;
    }
}
