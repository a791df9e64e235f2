package jade.proto;

import io.concord.jadecompat.internal.Engine;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.SimpleBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

import java.util.LinkedHashMap;
import java.util.Map;
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
    private final Map<String, Session> sessions = new LinkedHashMap<>();
    private Vector responses = new Vector();
    private MessageTemplate template;
    private long deadlineMs = -1;
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
        ACLMessage reply = myAgent.receive(template);
        if (reply != null) {
            getDataStore().put(REPLY_KEY, reply);
            handleReply(reply);
            checkProgress();
            return;
        }
        if (deadlineMs >= 0) {
            long left = deadlineMs - Engine.nowMs();
            if (left <= 0) {
                finish();
                return;
            }
            block(left);
        } else {
            block();
        }
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
        String convId = null;
        int n = 0;
        for (Object o : toSend == null ? new Vector() : toSend) {
            ACLMessage m = (ACLMessage) o;
            if (convId == null) {
                convId = m.getConversationId() != null ? m.getConversationId()
                        : "C" + hashCode() + "_" + Engine.nowMs();
            }
            if (m.getReplyByDate() != null) {
                deadlineMs = deadlineMs < 0 ? m.getReplyByDate().getTime() : Math.min(deadlineMs, m.getReplyByDate().getTime());
            }
            for (jade.util.leap.Iterator it = m.getAllReceiver(); it.hasNext(); ) {
                AID r = (AID) it.next();
                ACLMessage copy = (ACLMessage) m.clone();
                copy.clearAllReceiver();
                copy.addReceiver(r);
                copy.setConversationId(convId);
                String key = "P" + hashCode() + "_" + (n++);
                copy.setReplyWith(key);
                sessions.put(key, new Session(key, r));
                myAgent.send(copy);
            }
        }
        String cid = convId;
        template = new MessageTemplate(msg -> cid != null && cid.equals(msg.getConversationId()));
        checkProgress();
    }

    private void handleReply(ACLMessage reply) {
        Session s = reply.getInReplyTo() == null ? null : sessions.get(reply.getInReplyTo());
        if (s == null) {
            for (Session x : sessions.values()) {
                if (x.state == Session.SENT && x.receiver.equals(reply.getSender())) {
                    s = x;
                    break;
                }
            }
        }
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
        for (Session s : sessions.values()) {
            if (s.state != Session.DONE) {
                return;
            }
        }
        finish();
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
        sessions.clear();
        responses = new Vector();
        template = null;
        deadlineMs = -1;
        sent = false;
        finished = false;
    }
}
