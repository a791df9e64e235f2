package jade.content.onto;

/** A class cannot be added to a {@link BeanOntology}. */
public class BeanOntologyException extends OntologyException {
    private static final long serialVersionUID = 1L;

    /** An exception with that message. */
    public BeanOntologyException(String message) {
        super(message);
    }

    /** An exception with that message and cause. */
    public BeanOntologyException(String message, Throwable cause) {
        super(message, cause);
    }
}
