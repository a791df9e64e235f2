package jade.content.onto;

import jade.content.lang.sl.SL0Vocabulary;
import jade.content.onto.basic.Action;
import jade.content.onto.basic.Done;
import jade.content.onto.basic.Equals;
import jade.content.onto.basic.FalseProposition;
import jade.content.onto.basic.Result;
import jade.content.onto.basic.TrueProposition;
import jade.content.schema.AgentActionSchema;
import jade.content.schema.AggregateSchema;
import jade.content.schema.ConceptSchema;
import jade.content.schema.ObjectSchema;
import jade.content.schema.PredicateSchema;
import jade.content.schema.PrimitiveSchema;
import jade.content.schema.TermSchema;
import jade.core.AID;

import java.util.Date;

/**
 * The ontology every other extends, as JADE's: the primitive schemas ({@link #STRING},
 * {@link #INTEGER}, {@link #FLOAT}, {@link #BOOLEAN}, {@link #DATE}, {@link #BYTE_SEQUENCE}), the
 * aggregates ({@code sequence}, {@code set}), {@code agent-identifier} ({@link AID}), and the
 * elements of {@code jade.content.onto.basic}: {@code action}, {@code done}, {@code result},
 * {@code =}, {@code true}, {@code false}.
 */
public class BasicOntology extends Ontology implements SL0Vocabulary {
    private static final long serialVersionUID = 1L;
    /** The schema of strings. */
    public static final String STRING = "BO_String";
    /** The schema of floating-point numbers. */
    public static final String FLOAT = "BO_Float";
    /** The schema of integers. */
    public static final String INTEGER = "BO_Integer";
    /** The schema of booleans. */
    public static final String BOOLEAN = "BO_Boolean";
    /** The schema of dates. */
    public static final String DATE = "BO_Date";
    /** The schema of byte strings. */
    public static final String BYTE_SEQUENCE = "BO_Byte-sequence";
    /** The name of a list of content elements. */
    public static final String CONTENT_ELEMENT_LIST = "ContentElementList";

    private static final BasicOntology INSTANCE = new BasicOntology();

    private BasicOntology() {
        super("BASIC_ONTOLOGY", (Ontology) null);
        try {
            PrimitiveSchema string = new PrimitiveSchema(STRING);
            add(string, String.class);
            add(new PrimitiveSchema(INTEGER), Long.class);
            add(new PrimitiveSchema(FLOAT), Double.class);
            add(new PrimitiveSchema(BOOLEAN), Boolean.class);
            add(new PrimitiveSchema(DATE), Date.class);
            add(new PrimitiveSchema(BYTE_SEQUENCE), byte[].class);
            add(new AggregateSchema(SEQUENCE), jade.util.leap.List.class);
            add(new AggregateSchema(SET), jade.util.leap.Set.class);
            ConceptSchema aid = new ConceptSchema(AID);
            aid.add(AID_NAME, string);
            aid.add(AID_ADDRESSES, string, 0, ObjectSchema.UNLIMITED);
            add(aid, AID.class);
            aid.add(AID_RESOLVERS, aid, 0, ObjectSchema.UNLIMITED);
            TermSchema anyTerm = new TermSchema(TermSchema.BASE_NAME) {
                private static final long serialVersionUID = 1L;
            };
            AgentActionSchema action = new AgentActionSchema(ACTION);
            action.add(ACTION_ACTOR, aid);
            action.add(ACTION_ACTION, anyTerm);
            action.setEncodingByOrder(true);
            add(action, Action.class);
            PredicateSchema done = new PredicateSchema(DONE);
            done.add(DONE_ACTION, action);
            add(done, Done.class);
            PredicateSchema result = new PredicateSchema(RESULT);
            result.add(RESULT_ACTION, action);
            result.add(RESULT_VALUE, anyTerm);
            add(result, Result.class);
            PredicateSchema equals = new PredicateSchema(EQUALS);
            equals.add(EQUALS_LEFT, anyTerm);
            equals.add(EQUALS_RIGHT, anyTerm);
            add(equals, Equals.class);
            add(new PredicateSchema(TRUE_PROPOSITION), TrueProposition.class);
            add(new PredicateSchema(FALSE_PROPOSITION), FalseProposition.class);
        } catch (OntologyException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The one instance. */
    public static Ontology getInstance() {
        return INSTANCE;
    }

    /** The primitive schema of a Java primitive or boxed class, or the schema of that class. */
    @Override
    public ObjectSchema getSchema(Class javaClass) throws OntologyException {
        String primitive = primitiveName(javaClass);
        return primitive != null ? getSchema(primitive) : super.getSchema(javaClass);
    }

    static String primitiveName(Class<?> c) {
        if (c == String.class) {
            return STRING;
        }
        if (c == int.class || c == Integer.class || c == long.class || c == Long.class || c == short.class || c == Short.class) {
            return INTEGER;
        }
        if (c == float.class || c == Float.class || c == double.class || c == Double.class) {
            return FLOAT;
        }
        if (c == boolean.class || c == Boolean.class) {
            return BOOLEAN;
        }
        if (c == Date.class) {
            return DATE;
        }
        if (c == byte[].class) {
            return BYTE_SEQUENCE;
        }
        return null;
    }
}
