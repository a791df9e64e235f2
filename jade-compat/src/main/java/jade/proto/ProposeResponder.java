package jade.proto;

import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.SimpleBehaviour;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/**
 * JADE's responder of FIPA-propose: for each PROPOSE the template matches it calls
 * {@link #prepareResponse} and sends what it returns (ACCEPT_PROPOSAL, REJECT_PROPOSAL,
 * NOT_UNDERSTOOD, or nothing for null; a {@link NotUnderstoodException} becomes NOT_UNDERSTOOD, a
 * {@link RefuseException} REFUSE). It never ends.
 */
public class ProposeResponder extends SimpleBehaviour implements FIPANames.InteractionProtocol {
    private static final long serialVersionUID = 1L;

    /** Data store keys, as JADE names them. */
    public final String PROPOSE_KEY = "__propose" + hashCode();
    public final String RESPONSE_KEY = "__response" + hashCode();

    private MessageTemplate template;

    /** A template for the proposals of a protocol: its name and PROPOSE. */
    public static MessageTemplate createMessageTemplate(String iprotocol) {
        return MessageTemplate.and(MessageTemplate.MatchProtocol(iprotocol),
                MessageTemplate.MatchPerformative(ACLMessage.PROPOSE));
    }

    public ProposeResponder(Agent a, MessageTemplate mt) {
        this(a, mt, new DataStore());
    }

    public ProposeResponder(Agent a, MessageTemplate mt, DataStore store) {
        super(a);
        this.template = mt;
        setDataStore(store);
    }

    @Override
    public void action() {
        ACLMessage propose = myAgent.receive(template);
        if (propose == null) {
            block();
            return;
        }
        getDataStore().put(PROPOSE_KEY, propose);
        ACLMessage response = Replies.answer(propose, () -> prepareResponse(propose),
                ACLMessage.NOT_UNDERSTOOD, ACLMessage.REFUSE);
        getDataStore().put(RESPONSE_KEY, response);
        Replies.send(myAgent, response, propose);
    }

    /** Never ends. */
    @Override
    public boolean done() {
        return false;
    }

    /**
     * The answer to a proposal: ACCEPT_PROPOSAL, REJECT_PROPOSAL or NOT_UNDERSTOOD, or null to
     * send none. Override it; by default it answers nothing.
     */
    protected ACLMessage prepareResponse(ACLMessage propose) throws NotUnderstoodException, RefuseException {
        return null;
    }

    /** Serves another template from now on. */
    public void reset(MessageTemplate mt) {
        this.template = mt;
        reset();
    }

    @Override
    public void reset() {
        super.reset();
    }
}
