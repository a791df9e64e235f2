package jade.content.schema;

/** The schema of a term: a concept, a primitive, an aggregate. */
public class TermSchema extends ObjectSchema {
    private static final long serialVersionUID = 1L;
    /** The base name. */
    public static final String BASE_NAME = "Term";

    /** A term schema of that name. */
    protected TermSchema(String typeName) {
        super(typeName);
    }
}
