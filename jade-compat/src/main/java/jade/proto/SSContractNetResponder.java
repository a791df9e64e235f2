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
 * JADE's single-session contract-net responder: made with the CFP it answers (usually by an
 * {@link SSResponderDispatcher}), it calls {@link #handleCfp}, sends its answer, and after a
 * PROPOSE waits for the initiator's decision in that conversation: {@link #handleAcceptProposal}
 * (its INFORM or FAILURE is sent), {@link #handleRejectProposal}, or {@link #handleOutOfSequence}.
 * Then it ends. A plain behaviour here (JADE's is an FSM of {@code SSResponder}); registered
 * steps ({@code registerHandleXxx}) run on the spot, to their end.
 */
public class SSContractNetResponder extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;
    public static final String HANDLE_CFP = "Handle-Cfp";
    public static final String HANDLE_ACCEPT_PROPOSAL = "Handle-Accept-Proposal";
    public static final String HANDLE_REJECT_PROPOSAL = "Handle-Reject-Proposal";

    public final String CFP_KEY = "__cfp" + hashCode();
    public final String PROPOSE_KEY = "__propose" + hashCode();
    public final String ACCEPT_PROPOSAL_KEY = "__accept-proposal" + hashCode();
    public final String REJECT_PROPOSAL_KEY = "__reject-proposal" + hashCode();
    /** Where a registered step puts its answer, and where the last message received is. */
    public final String REPLY_KEY = "__reply" + hashCode();

    private ACLMessage cfp;
    private ACLMessage propose;
    private MessageTemplate decision;
    private boolean finished;
    private Behaviour cfpStep;
    private Behaviour acceptStep;
    private Behaviour rejectStep;
    private Behaviour outOfSequenceStep;

    public SSContractNetResponder(Agent a, ACLMessage cfp) {
        this(a, cfp, new DataStore());
    }

    public SSContractNetResponder(Agent a, ACLMessage cfp, DataStore store) {
        super(a);
        this.cfp = cfp;
        setDataStore(store);
    }

    @Override
    public void action() {
        if (finished) {
            return;
        }
        if (decision == null) {
            answerCfp();
            return;
        }
        ACLMessage m = myAgent.receive(decision);
        if (m == null) {
            block();
            return;
        }
        getDataStore().put(REPLY_KEY, m);
        if (!checkInSequence(m)) {
            if (!States.run(this, outOfSequenceStep, getDataStore(), null)) {
                handleOutOfSequence(cfp, propose, m);
            }
            finished = true;
            return;
        }
        if (iterated() && m.getPerformative() == ACLMessage.CFP) {
            // a new round of an iterated contract net: the new CFP is answered as the first was
            cfp = m;
            decision = null;
            answerCfp();
            return;
        }
        if (m.getPerformative() == ACLMessage.ACCEPT_PROPOSAL) {
            getDataStore().put(ACCEPT_PROPOSAL_KEY, m);
            ACLMessage result;
            if (States.run(this, acceptStep, getDataStore(), REPLY_KEY)) {
                result = (ACLMessage) getDataStore().get(REPLY_KEY);
            } else {
                result = Replies.answer(m, () -> handleAcceptProposal(cfp, propose, m), ACLMessage.FAILURE);
            }
            if (result != null) {
                Replies.complete(result, m);
                beforeReply(result);
                myAgent.send(result);
                afterReply(result);
            }
        } else if (m.getPerformative() == ACLMessage.REJECT_PROPOSAL) {
            getDataStore().put(REJECT_PROPOSAL_KEY, m);
            if (!States.run(this, rejectStep, getDataStore(), null)) {
                handleRejectProposal(cfp, propose, m);
            }
        } else if (!States.run(this, outOfSequenceStep, getDataStore(), null)) {
            handleOutOfSequence(cfp, propose, m);
        }
        finished = true;
    }

    private void answerCfp() {
        getDataStore().put(CFP_KEY, cfp);
        ACLMessage reply;
        if (States.run(this, cfpStep, getDataStore(), REPLY_KEY)) {
            reply = (ACLMessage) getDataStore().get(REPLY_KEY);
        } else {
            reply = Replies.answer(cfp, () -> handleCfp(cfp), ACLMessage.REFUSE, ACLMessage.FAILURE, ACLMessage.NOT_UNDERSTOOD);
        }
        if (reply != null) {
            Replies.complete(reply, cfp);
            getDataStore().put(PROPOSE_KEY, reply);
            beforeReply(reply);
            myAgent.send(reply);
            afterReply(reply);
        }
        if (reply != null && reply.getPerformative() == ACLMessage.PROPOSE) {
            propose = reply;
            String conv = cfp.getConversationId();
            jade.core.AID from = cfp.getSender();
            decision = new MessageTemplate(x -> java.util.Objects.equals(conv, x.getConversationId())
                    && (from == null || from.equals(x.getSender())));
        } else {
            finished = true;
        }
    }

    @Override
    public boolean done() {
        return finished;
    }

    /** Whether a CFP after the PROPOSE opens a new round (an iterated contract net); here no. */
    boolean iterated() {
        return false;
    }

    /**
     * Whether a message of the conversation after the PROPOSE fits it (by default: an
     * ACCEPT_PROPOSAL or REJECT_PROPOSAL, and a CFP in an iterated contract net); one that does
     * not goes to {@link #handleOutOfSequence} and ends the responder.
     */
    protected boolean checkInSequence(ACLMessage received) {
        int p = received.getPerformative();
        return p == ACLMessage.ACCEPT_PROPOSAL || p == ACLMessage.REJECT_PROPOSAL || iterated() && p == ACLMessage.CFP;
    }

    /** Called just before each reply is sent. JADE's default does nothing. */
    protected void beforeReply(ACLMessage reply) {
        // JADE's documented default: nothing (a hook for subclasses).
    }

    /** Called just after each reply is sent. JADE's default does nothing. */
    protected void afterReply(ACLMessage reply) {
        // JADE's documented default: nothing (a hook for subclasses).
    }

    /** The answer to the CFP: PROPOSE, REFUSE or NOT_UNDERSTOOD; by default none (null), and the responder ends. */
    protected ACLMessage handleCfp(ACLMessage cfp) throws RefuseException, FailureException, NotUnderstoodException {
        return null;
    }

    /** The proposal was accepted: the result, INFORM or FAILURE; by default none (null). */
    protected ACLMessage handleAcceptProposal(ACLMessage cfp, ACLMessage propose, ACLMessage accept) throws FailureException {
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

    /** In place of {@link #handleCfp}: reads {@link #CFP_KEY}, puts its answer under {@link #REPLY_KEY}. */
    public void registerHandleCfp(Behaviour b) {
        cfpStep = b;
    }

    /** In place of {@link #handleAcceptProposal}: reads {@link #ACCEPT_PROPOSAL_KEY}, puts the result under {@link #REPLY_KEY}. */
    public void registerHandleAcceptProposal(Behaviour b) {
        acceptStep = b;
    }

    /** In place of {@link #handleRejectProposal}: reads {@link #REJECT_PROPOSAL_KEY}. */
    public void registerHandleRejectProposal(Behaviour b) {
        rejectStep = b;
    }

    /** In place of {@link #handleOutOfSequence}: reads {@link #REPLY_KEY}. */
    public void registerHandleOutOfSequence(Behaviour b) {
        outOfSequenceStep = b;
    }
}
