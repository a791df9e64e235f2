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
    /** The registered steps ({@code registerXxx(Behaviour)}) by handler name. */
    private final java.util.Map<String, jade.core.behaviours.Behaviour> steps = new java.util.HashMap<>();

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
        Vector toSend;
        if (States.run(this, steps.get("prepareRequests"), getDataStore(), ALL_REQUESTS_KEY)) {
            toSend = (Vector) getDataStore().get(ALL_REQUESTS_KEY);
        } else {
            toSend = prepareRequests(request);
        }
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
            step("handleOutOfSequence", reply, () -> handleOutOfSequence(reply));
            return;
        }
        if (s.state == Session.SENT && p == ACLMessage.AGREE) {
            s.state = Session.RESPONDED;
            responses.add(reply);
            step("handleAgree", reply, () -> handleAgree(reply));
        } else if (s.state == Session.SENT && p == ACLMessage.REFUSE) {
            s.state = Session.DONE;
            responses.add(reply);
            step("handleRefuse", reply, () -> handleRefuse(reply));
        } else if (s.state == Session.SENT && p == ACLMessage.NOT_UNDERSTOOD) {
            s.state = Session.DONE;
            responses.add(reply);
            step("handleNotUnderstood", reply, () -> handleNotUnderstood(reply));
        } else if (p == ACLMessage.INFORM) {
            s.state = Session.DONE;
            resultNotifications.add(reply);
            step("handleInform", reply, () -> handleInform(reply));
        } else if (p == ACLMessage.FAILURE) {
            s.state = Session.DONE;
            resultNotifications.add(reply);
            step("handleFailure", reply, () -> handleFailure(reply));
        } else {
            step("handleOutOfSequence", reply, () -> handleOutOfSequence(reply));
        }
    }

    private void checkProgress() {
        if (conversation.allAnswered() && !allResponsesHandled) {
            allResponsesHandled = true;
            step("handleAllResponses", null, () -> handleAllResponses(responses));
        }
        if (conversation.allDone()) {
            finished = true;
            step("handleAllResultNotifications", null, () -> handleAllResultNotifications(resultNotifications));
        }
    }

    private void timeout() {
        if (!allResponsesHandled) {
            allResponsesHandled = true;
            step("handleAllResponses", null, () -> handleAllResponses(responses));
        }
        finished = true;
        step("handleAllResultNotifications", null, () -> handleAllResultNotifications(resultNotifications));
    }

    /**
     * Runs the step registered for that handler (the reply, if any, under {@link #REPLY_KEY};
     * the vectors under {@link #ALL_RESPONSES_KEY} and {@link #ALL_RESULT_NOTIFICATIONS_KEY}), or else the handler.
     */
    private void step(String handler, ACLMessage reply, Runnable otherwise) {
        if (reply != null) {
            getDataStore().put(REPLY_KEY, reply);
        }
        if (!States.run(this, steps.get(handler), getDataStore(), null)) {
            otherwise.run();
        }
    }

    /** In place of {@link #prepareRequests}: reads {@link #REQUEST_KEY}, puts the Vector of requests under {@link #ALL_REQUESTS_KEY}. */
    public void registerPrepareRequests(jade.core.behaviours.Behaviour b) {
        steps.put("prepareRequests", b);
    }

    /** In place of {@link #handleAgree}: the AGREE is under {@link #REPLY_KEY}. Registered steps run on the spot, to their end. */
    public void registerHandleAgree(jade.core.behaviours.Behaviour b) {
        steps.put("handleAgree", b);
    }

    /** In place of {@link #handleInform}: the INFORM is under {@link #REPLY_KEY}. */
    public void registerHandleInform(jade.core.behaviours.Behaviour b) {
        steps.put("handleInform", b);
    }

    /** In place of {@link #handleRefuse}: the REFUSE is under {@link #REPLY_KEY}. */
    public void registerHandleRefuse(jade.core.behaviours.Behaviour b) {
        steps.put("handleRefuse", b);
    }

    /** In place of {@link #handleNotUnderstood}: the NOT_UNDERSTOOD is under {@link #REPLY_KEY}. */
    public void registerHandleNotUnderstood(jade.core.behaviours.Behaviour b) {
        steps.put("handleNotUnderstood", b);
    }

    /** In place of {@link #handleFailure}: the FAILURE is under {@link #REPLY_KEY}. */
    public void registerHandleFailure(jade.core.behaviours.Behaviour b) {
        steps.put("handleFailure", b);
    }

    /** In place of {@link #handleOutOfSequence}: the message is under {@link #REPLY_KEY}. */
    public void registerHandleOutOfSequence(jade.core.behaviours.Behaviour b) {
        steps.put("handleOutOfSequence", b);
    }

    /** In place of {@link #handleAllResponses}: the Vector is under {@link #ALL_RESPONSES_KEY}. */
    public void registerHandleAllResponses(jade.core.behaviours.Behaviour b) {
        steps.put("handleAllResponses", b);
    }

    /** In place of {@link #handleAllResultNotifications}: the Vector is under {@link #ALL_RESULT_NOTIFICATIONS_KEY}. */
    public void registerHandleAllResultNotifications(jade.core.behaviours.Behaviour b) {
        steps.put("handleAllResultNotifications", b);
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
