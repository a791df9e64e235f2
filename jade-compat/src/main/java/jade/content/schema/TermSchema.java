package jade.content.schema;

/** The schema of a term: a concept, a primitive, an aggregate. */
public class TermSchema extends ObjectSchema {
    private static final long serialVersionUID = 1L;
    /** The base name. */
    public static final String BASE_NAME = "Term";
    private static final ObjectSchema BASE = new TermSchema(BASE_NAME);

    /** The schema of any term (a slot of this schema takes any term). */
    public static ObjectSchema getBaseSchema() {
        return BASE;
    }

    /** A term schema of that name. */
    protected TermSchema(String typeName) {
        super(typeName);
    }
}
