package jade.content.onto;

/** The content holds a variable ({@code ?x}) where a Java object needs a value, as JADE throws it. */
public class UngroundedException extends OntologyException {
    private static final long serialVersionUID = 1L;

    /** The exception, with JADE's message. */
    public UngroundedException() {
        super("Ungrounded content: a variable where a value is needed");
    }
}
