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
 * JADE's initiator of FIPA-request-like protocols (request, query, request-when): sends the
 * request to each receiver, then calls {@link #handleAgree}, {@link #handleRefuse},
 * {@link #handleNotUnderstood}, {@link #handleInform}, {@link #handleFailure} for each reply,
 * {@link #handleAllResponses} once every receiver has answered the request, and
 * {@link #handleAllResultNotifications} once every one has sent its result (or the
 * {@code :reply-by} time of the request has passed). It is a behaviour; add it to an agent.
 */
@SuppressWarnings({"rawtypes", "unchecked"})
public class AchieveREInitiator extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;

    /** Data store keys, as JADE names them. */
    public final String REQUEST_KEY = "__request" + hashCode();
    public final String ALL_REQUESTS_KEY = "__all-requests" + hashCode();
    public final String REPLY_KEY = "__reply" + hashCode();
    public final String ALL_RESPONSES_KEY = "__all-responses" + hashCode();
    public final String ALL_RESULT_NOTIFICATIONS_KEY = "__all-result-notifications" + hashCode();

    private ACLMessage request;
    private final Map<String, Session> sessions = new LinkedHashMap<>();
    private Vector responses = new Vector();
    private Vector resultNotifications = new Vector();
    private MessageTemplate template;
    private long deadlineMs = -1;
    private boolean sent;
    private boolean allResponsesHandled;
    private boolean finished;

    public AchieveREInitiator(Agent a, ACLMessage msg) {
        this(a, msg, new DataStore());
    }

    public AchieveREInitiator(Agent a, ACLMessage msg, DataStore store) {
        super(a);
        setDataStore(store);
        this.request = msg;
    }

    @Override
    public void action() {
        if (!sent) {
            sendRequests();
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
                timeout();
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

    private void sendRequests() {
        sent = true;
        Vector toSend = prepareRequests(request);
        getDataStore().put(REQUEST_KEY, request);
        getDataStore().put(ALL_REQUESTS_KEY, toSend);
        getDataStore().put(ALL_RESPONSES_KEY, responses);
        getDataStore().put(ALL_RESULT_NOTIFICATIONS_KEY, resultNotifications);
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
                String key = "R" + hashCode() + "_" + (n++);
                copy.setReplyWith(key);
                sessions.put(key, new Session(key, r));
                myAgent.send(copy);
            }
        }
        String cid = convId;
        template = new MessageTemplate(msg -> cid != null && cid.equals(msg.getConversationId()));
        checkProgress();
    }

    private Session sessionOf(ACLMessage reply) {
        Session s = reply.getInReplyTo() == null ? null : sessions.get(reply.getInReplyTo());
        if (s == null) {
            for (Session x : sessions.values()) {
                if (x.state != Session.DONE && x.receiver.equals(reply.getSender())) {
                    return x;
                }
            }
        }
        return s;
    }

    private void handleReply(ACLMessage reply) {
        Session s = sessionOf(reply);
        int p = reply.getPerformative();
        if (s == null || s.state == Session.DONE) {
            handleOutOfSequence(reply);
            return;
        }
        if (s.state == Session.SENT && p == ACLMessage.AGREE) {
            s.state = Session.RESPONDED;
            responses.add(reply);
            handleAgree(reply);
        } else if (s.state == Session.SENT && p == ACLMessage.REFUSE) {
            s.state = Session.DONE;
            responses.add(reply);
            handleRefuse(reply);
        } else if (s.state == Session.SENT && p == ACLMessage.NOT_UNDERSTOOD) {
            s.state = Session.DONE;
            responses.add(reply);
            handleNotUnderstood(reply);
        } else if (p == ACLMessage.INFORM) {
            s.state = Session.DONE;
            resultNotifications.add(reply);
            handleInform(reply);
        } else if (p == ACLMessage.FAILURE) {
            s.state = Session.DONE;
            resultNotifications.add(reply);
            handleFailure(reply);
        } else {
            handleOutOfSequence(reply);
        }
    }

    private void checkProgress() {
        boolean allAnswered = true;
        boolean allDone = true;
        for (Session s : sessions.values()) {
            allAnswered &= s.state != Session.SENT;
            allDone &= s.state == Session.DONE;
        }
        if (allAnswered && !allResponsesHandled) {
            allResponsesHandled = true;
            handleAllResponses(responses);
        }
        if (allDone) {
            finished = true;
            handleAllResultNotifications(resultNotifications);
        }
    }

    private void timeout() {
        if (!allResponsesHandled) {
            allResponsesHandled = true;
            handleAllResponses(responses);
        }
        finished = true;
        handleAllResultNotifications(resultNotifications);
    }

    /** The requests to send; by default the message given to the constructor. */
    protected Vector prepareRequests(ACLMessage request) {
        Vector v = new Vector(1);
        v.add(request);
        return v;
    }

    /** A receiver agreed. */
    protected void handleAgree(ACLMessage agree) {
        // JADE's documented default: nothing. Override to act on it.
    }

    /** A receiver refused. */
    protected void handleRefuse(ACLMessage refuse) {
        // JADE's documented default: nothing.
    }

    /** A receiver did not understand. */
    protected void handleNotUnderstood(ACLMessage notUnderstood) {
        // JADE's documented default: nothing.
    }

    /** A receiver sent its result. */
    protected void handleInform(ACLMessage inform) {
        // JADE's documented default: nothing.
    }

    /** A receiver failed. */
    protected void handleFailure(ACLMessage failure) {
        // JADE's documented default: nothing.
    }

    /** A message of this conversation that does not fit where the conversation is. */
    protected void handleOutOfSequence(ACLMessage msg) {
        // JADE's documented default: nothing.
    }

    /** Every receiver has answered the request (AGREE, REFUSE, NOT_UNDERSTOOD), or time is up. */
    protected void handleAllResponses(Vector responses) {
        // JADE's documented default: nothing.
    }

    /** Every receiver has sent its result (INFORM, FAILURE), or time is up. */
    protected void handleAllResultNotifications(Vector resultNotifications) {
        // JADE's documented default: nothing.
    }

    /** Starts over with a new request. */
    public void reset(ACLMessage msg) {
        this.request = msg;
        reset();
    }

    @Override
    public void reset() {
        super.reset();
        sessions.clear();
        responses = new Vector();
        resultNotifications = new Vector();
        template = null;
        deadlineMs = -1;
        sent = false;
        allResponsesHandled = false;
        finished = false;
    }
}
