package jade.content.abs;

/** Content in abstract form, independent of Java classes, as JADE's abstract descriptors. */
public interface AbsObject extends jade.util.leap.Serializable {
    /** Not a known kind. */
    int UNKNOWN = -1;
    /** An {@link AbsPredicate}. */
    int ABS_PREDICATE = 1;
    /** An {@link AbsConcept}. */
    int ABS_CONCEPT = 2;
    /** An {@link AbsAgentAction}. */
    int ABS_AGENT_ACTION = 3;
    /** An {@link AbsPrimitive}. */
    int ABS_PRIMITIVE = 4;
    /** An {@link AbsAggregate}. */
    int ABS_AGGREGATE = 5;
    /** A referential expression (not represented here). */
    int ABS_IRE = 6;
    /** An {@link AbsVariable}. */
    int ABS_VARIABLE = 7;
    /** An {@link AbsContentElementList}. */
    int ABS_CONTENT_ELEMENT_LIST = 8;
    /** A concept slot function (not represented here). */
    int ABS_CONCEPT_SLOT_FUNCTION = 9;

    /** Its type: a schema name, such as {@code Book}, or a primitive's, such as {@code BO_String}. */
    String getTypeName();

    /** The value of that slot, or null. */
    AbsObject getAbsObject(String name);

    /** Its slot names. */
    String[] getNames();

    /** Whether it holds no variable. */
    boolean isGrounded();

    /** How many slots (or elements) it has. */
    int getCount();

    /** Its kind, one of the constants above. */
    int getAbsType();
}
