package jade.domain.FIPAAgentManagement;

import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;

/** Thrown by a protocol responder's handler: the reply is a Failure with this text as content. */
public class FailureException extends FIPAException {
    private static final long serialVersionUID = 1L;

    public FailureException(String message) {
        super(message);
    }

    public FailureException(ACLMessage message) {
        super(message);
    }
}
