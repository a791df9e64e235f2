package jade.proto;

import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.lang.acl.ACLMessage;

/**
 * JADE's single-session responder of the iterated contract net: as {@link SSContractNetResponder},
 * and a CFP of the same conversation after its PROPOSE opens a new round, answered by
 * {@link #handleCfp} again, until the initiator accepts or rejects.
 */
public class SSIteratedContractNetResponder extends SSContractNetResponder {
    private static final long serialVersionUID = 1L;

    public SSIteratedContractNetResponder(Agent a, ACLMessage cfp) {
        super(a, cfp);
    }

    public SSIteratedContractNetResponder(Agent a, ACLMessage cfp, DataStore store) {
        super(a, cfp, store);
    }

    @Override
    boolean iterated() {
        return true;
    }
}
