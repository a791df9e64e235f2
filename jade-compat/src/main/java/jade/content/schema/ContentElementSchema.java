package jade.content.schema;

/** The schema of a content element: a predicate (or an agent action). */
public class ContentElementSchema extends ObjectSchema {
    private static final long serialVersionUID = 1L;
    /** The base name. */
    public static final String BASE_NAME = "ContentElement";
    private static final ObjectSchema BASE = new ContentElementSchema(BASE_NAME);

    /** The schema of any content element. */
    public static ObjectSchema getBaseSchema() {
        return BASE;
    }

    /** A content-element schema of that name. */
    protected ContentElementSchema(String typeName) {
        super(typeName);
    }
}
