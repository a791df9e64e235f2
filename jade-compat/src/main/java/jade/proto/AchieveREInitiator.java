package jade.proto;

import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.SimpleBehaviour;
import jade.lang.acl.ACLMessage;

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
    private final Initiations conversation = new Initiations(this, "R");
    private Vector responses = new Vector();
    private Vector resultNotifications = new Vector();
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
        conversation.receive(REPLY_KEY, true, reply -> {
            handleReply(reply);
            checkProgress();
        }, this::timeout);
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
        conversation.send(toSend);
        checkProgress();
    }

    private void handleReply(ACLMessage reply) {
        Session s = conversation.sessionOf(reply, false);
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
        if (conversation.allAnswered() && !allResponsesHandled) {
            allResponsesHandled = true;
            handleAllResponses(responses);
        }
        if (conversation.allDone()) {
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
        conversation.clear();
        responses = new Vector();
        resultNotifications = new Vector();
        sent = false;
        allResponsesHandled = false;
        finished = false;
    }
}
