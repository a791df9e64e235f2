package jade.content.schema;

/** The schema of a primitive: {@code BasicOntology.STRING}, {@code INTEGER}, {@code FLOAT}, ... */
public class PrimitiveSchema extends TermSchema {
    private static final long serialVersionUID = 1L;
    /** The base name. */
    public static final String BASE_NAME = "Primitive";
    private static final ObjectSchema BASE = new PrimitiveSchema(BASE_NAME);

    /** The schema of any primitive. */
    public static ObjectSchema getBaseSchema() {
        return BASE;
    }

    /** A primitive schema of that name. */
    public PrimitiveSchema(String typeName) {
        super(typeName);
    }
}
