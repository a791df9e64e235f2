package jade.content.schema;

/** The schema of an agent action: a concept that can be requested, written with named slots. */
public class AgentActionSchema extends ConceptSchema {
    private static final long serialVersionUID = 1L;
    /** The base name. */
    public static final String BASE_NAME = "AgentAction";
    private static final ObjectSchema BASE = new AgentActionSchema(BASE_NAME);

    /** The schema of any agent action. */
    public static ObjectSchema getBaseSchema() {
        return BASE;
    }
    private TermSchema resultSchema;

    /** An agent-action schema of that name. */
    public AgentActionSchema(String typeName) {
        super(typeName);
    }

    /** Adds a mandatory slot holding a proposition. */
    public void add(String name, PredicateSchema slotSchema) {
        super.add(name, slotSchema);
    }

    /** Adds a slot holding a proposition, {@link #MANDATORY} or {@link #OPTIONAL}. */
    public void add(String name, PredicateSchema slotSchema, int optionality) {
        super.add(name, slotSchema, optionality);
    }

    /** Records the schema of the action's result (documentation: not checked). */
    public void setResult(TermSchema schema) {
        this.resultSchema = schema;
    }

    /** Records the schema of the action's result, an aggregate (documentation: not checked). */
    public void setResult(TermSchema elementsSchema, int cardMin, int cardMax) {
        this.resultSchema = new AggregateSchema("sequence", elementsSchema);
    }

    /** The schema of the action's result, or null. */
    public TermSchema getResultSchema() {
        return resultSchema;
    }
}
