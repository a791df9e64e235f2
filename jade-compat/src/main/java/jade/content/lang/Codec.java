package jade.content.lang;

import jade.content.ContentException;
import jade.content.onto.Ontology;

/** A content language, registered with a {@link jade.content.ContentManager} under its name. */
public abstract class Codec implements jade.util.leap.Serializable {
    private static final long serialVersionUID = 1L;
    /** The prefix JADE gives a codec without a name. */
    public static final String UNNAMEDPREFIX = "Codec-unnamed";

    private final String name;
    private Ontology innerOntology;

    /** A codec for that language name (the message's {@code :language}). */
    protected Codec(String name) {
        this.name = name;
    }

    /** The language's name. */
    public String getName() {
        return name;
    }

    /** The ontology of the language's own symbols; null here (the operators are built into the codec). */
    public Ontology getInnerOntology() {
        return innerOntology;
    }

    /** The content cannot be written or read in this language. */
    public static class CodecException extends ContentException {
        private static final long serialVersionUID = 1L;

        /** An exception with that message. */
        public CodecException(String message) {
            super(message);
        }

        /** An exception with that message and cause. */
        public CodecException(String message, Throwable cause) {
            super(message, cause);
        }
    }
}
