package jade.domain;

import jade.lang.acl.ACLMessage;

/** A FIPA error: the DF or AMS refused, failed or did not understand, or a protocol answered so. */
public class FIPAException extends Exception {
    private static final long serialVersionUID = 1L;

    /** The message that carried the error, if any. */
    protected ACLMessage msg;
    private String text;

    public FIPAException(String message) {
        super(message);
        this.text = message;
    }

    /** An error carried by a message (its content is the error's text). */
    public FIPAException(ACLMessage message) {
        this(message.getContent());
        this.msg = (ACLMessage) message.clone();
    }

    public ACLMessage getACLMessage() {
        return msg;
    }

    protected void setMessage(String message) {
        this.text = message;
    }

    @Override
    public String getMessage() {
        return text;
    }
}
