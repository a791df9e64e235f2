package jade.content;

/** The root of JADE's content exceptions ({@code CodecException}, {@code OntologyException}). */
public class ContentException extends Exception {
    private static final long serialVersionUID = 1L;

    /** An exception with that message. */
    public ContentException(String message) {
        super(message);
    }

    /** An exception with that message and cause. */
    public ContentException(String message, Throwable cause) {
        super(message, cause);
    }
}
