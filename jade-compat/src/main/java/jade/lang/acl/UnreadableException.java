package jade.lang.acl;

/** The content of a message could not be read as a Java object ({@link ACLMessage#getContentObject}). */
public class UnreadableException extends Exception {
    private static final long serialVersionUID = 1L;

    public UnreadableException(String msg) {
        super(msg);
    }
}
