package jade.domain.FIPAAgentManagement;

import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;

/** Thrown by a protocol responder's handler: the reply is a NotUnderstood with this text as content. */
public class NotUnderstoodException extends FIPAException {
    private static final long serialVersionUID = 1L;

    public NotUnderstoodException(String message) {
        super(message);
    }

    public NotUnderstoodException(ACLMessage message) {
        super(message);
    }
}
