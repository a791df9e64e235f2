package jade.proto;

import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.SimpleBehaviour;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/**
 * JADE's responder of the FIPA contract net, one CFP after the other: {@link #handleCfp} (by
 * default {@link #prepareResponse}) answers each CFP (PROPOSE, REFUSE, NOT_UNDERSTOOD; exceptions
 * become REFUSE, FAILURE, NOT_UNDERSTOOD); after a PROPOSE it waits for the initiator's decision
 * and calls {@link #handleAcceptProposal} (by default {@link #prepareResultNotification}), whose
 * INFORM or FAILURE it sends, or {@link #handleRejectProposal}. It never ends.
 */
public class ContractNetResponder extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;

    public final String CFP_KEY = "__cfp" + hashCode();
    public final String PROPOSE_KEY = "__propose" + hashCode();
    public final String ACCEPT_PROPOSAL_KEY = "__accept-proposal" + hashCode();
    public final String REJECT_PROPOSAL_KEY = "__reject-proposal" + hashCode();
    public final String REPLY_KEY = "__reply" + hashCode();

    private MessageTemplate template;
    private ACLMessage cfp;
    private ACLMessage propose;
    private MessageTemplate decision;
    private Behaviour cfpStep;
    private Behaviour acceptStep;
    private Behaviour rejectStep;
    private Behaviour outOfSequenceStep;

    /** A template for the CFPs of a protocol. */
    public static MessageTemplate createMessageTemplate(String iprotocol) {
        return MessageTemplate.and(MessageTemplate.MatchProtocol(iprotocol), MessageTemplate.MatchPerformative(ACLMessage.CFP));
    }

    public ContractNetResponder(Agent a, MessageTemplate mt) {
        this(a, mt, new DataStore());
    }

    public ContractNetResponder(Agent a, MessageTemplate mt, DataStore store) {
        super(a);
        this.template = mt;
        setDataStore(store);
    }

    @Override
    public void action() {
        if (decision == null) {
            ACLMessage m = myAgent.receive(template);
            if (m == null) {
                block();
                return;
            }
            onCfp(m);
        } else {
            ACLMessage m = myAgent.receive(decision);
            if (m == null) {
                block();
                return;
            }
            onDecision(m);
        }
    }

    private void onCfp(ACLMessage m) {
        cfp = m;
        getDataStore().put(CFP_KEY, m);
        ACLMessage reply;
        if (States.run(this, cfpStep, getDataStore(), REPLY_KEY)) {
            reply = (ACLMessage) getDataStore().get(REPLY_KEY);
        } else {
            reply = Replies.answer(m, () -> handleCfp(m), ACLMessage.REFUSE, ACLMessage.FAILURE, ACLMessage.NOT_UNDERSTOOD);
        }
        if (reply != null) {
            Replies.complete(reply, m);
            getDataStore().put(PROPOSE_KEY, reply);
            myAgent.send(reply);
        }
        if (reply != null && reply.getPerformative() == ACLMessage.PROPOSE) {
            propose = reply;
            String conv = m.getConversationId();
            jade.core.AID from = m.getSender();
            decision = new MessageTemplate(x -> java.util.Objects.equals(conv, x.getConversationId())
                    && (from == null || from.equals(x.getSender())));
        } else {
            end();
        }
    }

    private void onDecision(ACLMessage m) {
        getDataStore().put(REPLY_KEY, m);
        if (m.getPerformative() == ACLMessage.ACCEPT_PROPOSAL) {
            getDataStore().put(ACCEPT_PROPOSAL_KEY, m);
            ACLMessage result;
            if (States.run(this, acceptStep, getDataStore(), REPLY_KEY)) {
                result = (ACLMessage) getDataStore().get(REPLY_KEY);
            } else {
                result = Replies.answer(m, () -> handleAcceptProposal(cfp, propose, m), ACLMessage.FAILURE);
            }
            Replies.send(myAgent, result, m);
        } else if (m.getPerformative() == ACLMessage.REJECT_PROPOSAL) {
            getDataStore().put(REJECT_PROPOSAL_KEY, m);
            if (!States.run(this, rejectStep, getDataStore(), null)) {
                handleRejectProposal(cfp, propose, m);
            }
        } else if (!States.run(this, outOfSequenceStep, getDataStore(), null)) {
            handleOutOfSequence(cfp, propose, m);
        }
        end();
    }

    private void end() {
        cfp = null;
        propose = null;
        decision = null;
        sessionTerminated();
    }

    /** Never ends. */
    @Override
    public boolean done() {
        return false;
    }

    /** The answer to a CFP: PROPOSE, REFUSE or NOT_UNDERSTOOD; by default {@link #prepareResponse}'s. */
    protected ACLMessage handleCfp(ACLMessage cfp) throws RefuseException, FailureException, NotUnderstoodException {
        return prepareResponse(cfp);
    }

    /** JADE's older name for {@link #handleCfp}; by default no answer (null). */
    protected ACLMessage prepareResponse(ACLMessage cfp) throws NotUnderstoodException, RefuseException {
        return null;
    }

    /** The proposal was accepted: the result, INFORM or FAILURE; by default {@link #prepareResultNotification}'s. */
    protected ACLMessage handleAcceptProposal(ACLMessage cfp, ACLMessage propose, ACLMessage accept) throws FailureException {
        return prepareResultNotification(cfp, propose, accept);
    }

    /** JADE's older name for {@link #handleAcceptProposal}; by default no result (null). */
    protected ACLMessage prepareResultNotification(ACLMessage cfp, ACLMessage propose, ACLMessage accept)
            throws FailureException {
        return null;
    }

    /** The proposal was rejected. */
    protected void handleRejectProposal(ACLMessage cfp, ACLMessage propose, ACLMessage reject) {
        // JADE's documented default: nothing.
    }

    /** A message of the conversation that is neither an acceptance nor a rejection. */
    protected void handleOutOfSequence(ACLMessage cfp, ACLMessage propose, ACLMessage msg) {
        // JADE's documented default: nothing.
    }

    /** A conversation ended (after a result, a rejection, or an answer other than PROPOSE). */
    protected void sessionTerminated() {
        // JADE's documented default: nothing.
    }

    /**
     * Puts a behaviour in place of {@link #handleCfp}: it reads the CFP under {@link #CFP_KEY} and
     * puts its answer (PROPOSE, REFUSE, ...) under {@link #REPLY_KEY}. Registered steps run on the spot, to their end.
     */
    public void registerHandleCfp(Behaviour b) {
        cfpStep = b;
    }

    /** As {@link #registerHandleCfp} (JADE's older name). */
    public void registerPrepareResponse(Behaviour b) {
        registerHandleCfp(b);
    }

    /** In place of {@link #handleAcceptProposal}: reads {@link #CFP_KEY}, {@link #PROPOSE_KEY}, {@link #ACCEPT_PROPOSAL_KEY}; puts the result under {@link #REPLY_KEY}. */
    public void registerHandleAcceptProposal(Behaviour b) {
        acceptStep = b;
    }

    /** As {@link #registerHandleAcceptProposal} (JADE's older name). */
    public void registerPrepareResultNotification(Behaviour b) {
        registerHandleAcceptProposal(b);
    }

    /** In place of {@link #handleRejectProposal}: reads {@link #REJECT_PROPOSAL_KEY}. */
    public void registerHandleRejectProposal(Behaviour b) {
        rejectStep = b;
    }

    /** In place of {@link #handleOutOfSequence}: reads the message under {@link #REPLY_KEY}. */
    public void registerHandleOutOfSequence(Behaviour b) {
        outOfSequenceStep = b;
    }

    /** Serves another template. */
    public void reset(MessageTemplate mt) {
        this.template = mt;
        reset();
    }

    @Override
    public void reset() {
        super.reset();
        end();
    }
}
