package jade.proto;

import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.SimpleBehaviour;
import jade.lang.acl.ACLMessage;

import java.util.Vector;

/**
 * JADE's initiator of FIPA-propose: sends the proposal to each receiver, then calls
 * {@link #handleAcceptProposal}, {@link #handleRejectProposal}, {@link #handleNotUnderstood} for
 * each answer ({@link #handleOutOfSequence} for anything else in the conversation), and
 * {@link #handleAllResponses} once every receiver has answered or the proposal's {@code :reply-by}
 * time has passed; then it ends. It is a behaviour; add it to an agent.
 */
@SuppressWarnings({"rawtypes", "unchecked"})
public class ProposeInitiator extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;

    /** Data store keys, as JADE names them. */
    public final String PROPOSE_KEY = "__propose" + hashCode();
    public final String ALL_PROPOSES_KEY = "__all-proposes" + hashCode();
    public final String REPLY_KEY = "__reply" + hashCode();
    public final String ALL_RESPONSES_KEY = "__all-responses" + hashCode();

    private ACLMessage proposal;
    private final Initiations conversation = new Initiations(this, "P");
    private Vector responses = new Vector();
    private boolean sent;
    private boolean finished;

    public ProposeInitiator(Agent a, ACLMessage msg) {
        this(a, msg, new DataStore());
    }

    public ProposeInitiator(Agent a, ACLMessage msg, DataStore store) {
        super(a);
        setDataStore(store);
        this.proposal = msg;
    }

    @Override
    public void action() {
        if (!sent) {
            sendProposals();
            return;
        }
        conversation.receive(REPLY_KEY, true, reply -> {
            handleReply(reply);
            checkProgress();
        }, this::finish);
    }

    @Override
    public boolean done() {
        return finished;
    }

    private void sendProposals() {
        sent = true;
        Vector toSend = prepareInitiations(proposal);
        getDataStore().put(PROPOSE_KEY, proposal);
        getDataStore().put(ALL_PROPOSES_KEY, toSend);
        getDataStore().put(ALL_RESPONSES_KEY, responses);
        conversation.send(toSend);
        checkProgress();
    }

    private void handleReply(ACLMessage reply) {
        // A proposal's session is only ever SENT or DONE: the first open one is the first SENT one.
        Session s = conversation.sessionOf(reply, false);
        int p = reply.getPerformative();
        boolean answer = p == ACLMessage.ACCEPT_PROPOSAL || p == ACLMessage.REJECT_PROPOSAL || p == ACLMessage.NOT_UNDERSTOOD;
        if (s == null || s.state != Session.SENT || !answer) {
            handleOutOfSequence(reply);
            return;
        }
        s.state = Session.DONE;
        responses.add(reply);
        if (p == ACLMessage.ACCEPT_PROPOSAL) {
            handleAcceptProposal(reply);
        } else if (p == ACLMessage.REJECT_PROPOSAL) {
            handleRejectProposal(reply);
        } else {
            handleNotUnderstood(reply);
        }
    }

    private void checkProgress() {
        if (conversation.allDone()) {
            finish();
        }
    }

    private void finish() {
        finished = true;
        handleAllResponses(responses);
    }

    /** The proposals to send; by default the message given to the constructor. */
    protected Vector prepareInitiations(ACLMessage propose) {
        Vector v = new Vector(1);
        v.add(propose);
        return v;
    }

    /** A receiver accepted the proposal. */
    protected void handleAcceptProposal(ACLMessage accept) {
        // JADE's documented default: nothing. Override to act on it.
    }

    /** A receiver rejected the proposal. */
    protected void handleRejectProposal(ACLMessage reject) {
        // JADE's documented default: nothing.
    }

    /** A receiver did not understand the proposal. */
    protected void handleNotUnderstood(ACLMessage notUnderstood) {
        // JADE's documented default: nothing.
    }

    /** A message of this conversation that is not an answer to the proposal. */
    protected void handleOutOfSequence(ACLMessage msg) {
        // JADE's documented default: nothing.
    }

    /** Every receiver has answered (ACCEPT_PROPOSAL, REJECT_PROPOSAL, NOT_UNDERSTOOD), or time is up. */
    protected void handleAllResponses(Vector responses) {
        // JADE's documented default: nothing.
    }

    /** Starts over with a new proposal. */
    public void reset(ACLMessage msg) {
        this.proposal = msg;
        reset();
    }

    @Override
    public void reset() {
        super.reset();
        conversation.clear();
        responses = new Vector();
        sent = false;
        finished = false;
    }
}
