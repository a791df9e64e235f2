package jade.content.onto;

import jade.content.ContentException;

/** An object does not fit its ontology: no schema, a missing mandatory slot, a wrong type. */
public class OntologyException extends ContentException {
    private static final long serialVersionUID = 1L;

    /** An exception with that message. */
    public OntologyException(String message) {
        super(message);
    }

    /** An exception with that message and cause. */
    public OntologyException(String message, Throwable cause) {
        super(message, cause);
    }
}
