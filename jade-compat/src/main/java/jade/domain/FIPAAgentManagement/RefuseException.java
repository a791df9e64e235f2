package jade.domain.FIPAAgentManagement;

import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;

/** Thrown by a protocol responder's handler: the reply is a Refuse with this text as content. */
public class RefuseException extends FIPAException {
    private static final long serialVersionUID = 1L;

    public RefuseException(String message) {
        super(message);
    }

    public RefuseException(ACLMessage message) {
        super(message);
    }
}
