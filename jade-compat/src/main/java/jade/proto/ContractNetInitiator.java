package jade.proto;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.SimpleBehaviour;
import jade.lang.acl.ACLMessage;

import java.util.Map;
import java.util.Vector;

/**
 * JADE's initiator of the FIPA contract net: sends the CFP to each receiver, calls
 * {@link #handlePropose}, {@link #handleRefuse}, {@link #handleNotUnderstood},
 * {@link #handleFailure} for each answer, {@link #handleAllResponses(Vector, Vector)} once all
 * have answered (or the CFP's {@code :reply-by} time has passed), sends the acceptances and
 * rejections that handler put in its second vector, then calls {@link #handleInform} /
 * {@link #handleFailure} for each result and {@link #handleAllResultNotifications} at the end
 * (not at all when no proposal was accepted, as in JADE 4.3).
 */
@SuppressWarnings({"rawtypes", "unchecked"})
public class ContractNetInitiator extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;

    public final String CFP_KEY = "__cfp" + hashCode();
    public final String ALL_CFPS_KEY = "__all-cfps" + hashCode();
    public final String REPLY_KEY = "__reply" + hashCode();
    public final String ALL_RESPONSES_KEY = "__all-responses" + hashCode();
    public final String ALL_ACCEPTANCES_KEY = "__all-acceptances" + hashCode();
    public final String ALL_RESULT_NOTIFICATIONS_KEY = "__all-result-notifications" + hashCode();

    private static final int SEND_CFPS = 0;
    private static final int COLLECT_RESPONSES = 1;
    private static final int COLLECT_RESULTS = 2;

    private ACLMessage cfp;
    private final Initiations conversation = new Initiations(this, "R");
    private Vector responses = new Vector();
    private Vector acceptances = new Vector();
    private Vector resultNotifications = new Vector();
    private int phase = SEND_CFPS;
    private boolean finished;
    /** The registered steps ({@code registerXxx(Behaviour)}) by handler name. */
    private final java.util.Map<String, jade.core.behaviours.Behaviour> steps = new java.util.HashMap<>();

    public ContractNetInitiator(Agent a, ACLMessage cfp) {
        this(a, cfp, new DataStore());
    }

    public ContractNetInitiator(Agent a, ACLMessage cfp, DataStore store) {
        super(a);
        setDataStore(store);
        this.cfp = cfp;
    }

    @Override
    public void action() {
        if (phase == SEND_CFPS) {
            sendCfps();
            return;
        }
        conversation.receive(REPLY_KEY, phase == COLLECT_RESPONSES, reply -> {
            if (phase == COLLECT_RESPONSES) {
                onResponse(reply);
            } else {
                onResult(reply);
            }
            checkProgress();
        }, this::endResponses);
    }

    @Override
    public boolean done() {
        return finished;
    }

    private void sendCfps() {
        phase = COLLECT_RESPONSES;
        getDataStore().put(CFP_KEY, cfp);
        Vector toSend;
        if (States.run(this, steps.get("prepareCfps"), getDataStore(), ALL_CFPS_KEY)) {
            toSend = (Vector) getDataStore().get(ALL_CFPS_KEY);
        } else {
            toSend = prepareCfps(cfp);
        }
        getDataStore().put(ALL_CFPS_KEY, toSend);
        getDataStore().put(ALL_RESPONSES_KEY, responses);
        getDataStore().put(ALL_ACCEPTANCES_KEY, acceptances);
        getDataStore().put(ALL_RESULT_NOTIFICATIONS_KEY, resultNotifications);
        conversation.send(toSend);
        checkProgress();
    }

    private void onResponse(ACLMessage reply) {
        Session s = conversation.sessionOf(reply, true);
        if (s == null || s.state != Session.SENT) {
            step("handleOutOfSequence", reply, () -> handleOutOfSequence(reply));
            return;
        }
        switch (reply.getPerformative()) {
            case ACLMessage.PROPOSE -> {
                s.state = Session.RESPONDED;
                responses.add(reply);
                step("handlePropose", reply, () -> handlePropose(reply, acceptances));
            }
            case ACLMessage.REFUSE -> {
                s.state = Session.RESPONDED;
                responses.add(reply);
                step("handleRefuse", reply, () -> handleRefuse(reply));
            }
            case ACLMessage.NOT_UNDERSTOOD -> {
                s.state = Session.RESPONDED;
                responses.add(reply);
                step("handleNotUnderstood", reply, () -> handleNotUnderstood(reply));
            }
            case ACLMessage.FAILURE -> {
                s.state = Session.RESPONDED;
                responses.add(reply);
                step("handleFailure", reply, () -> handleFailure(reply));
            }
            default -> step("handleOutOfSequence", reply, () -> handleOutOfSequence(reply));
        }
    }

    private void onResult(ACLMessage reply) {
        Session s = conversation.sessionOf(reply, true);
        if (s == null || s.state != Session.SENT) {
            step("handleOutOfSequence", reply, () -> handleOutOfSequence(reply));
            return;
        }
        if (reply.getPerformative() == ACLMessage.INFORM) {
            s.state = Session.DONE;
            resultNotifications.add(reply);
            step("handleInform", reply, () -> handleInform(reply));
        } else if (reply.getPerformative() == ACLMessage.FAILURE) {
            s.state = Session.DONE;
            resultNotifications.add(reply);
            step("handleFailure", reply, () -> handleFailure(reply));
        } else {
            step("handleOutOfSequence", reply, () -> handleOutOfSequence(reply));
        }
    }

    private void checkProgress() {
        if (!conversation.allAnswered()) {
            return;
        }
        if (phase == COLLECT_RESPONSES) {
            endResponses();
        } else if (phase == COLLECT_RESULTS) {
            finished = true;
            step("handleAllResultNotifications", null, () -> handleAllResultNotifications(resultNotifications));
        }
    }

    /** All answered (or time is up): the user picks, the acceptances go out, results are awaited. */
    private void endResponses() {
        step("handleAllResponses", null, () -> handleAllResponses(responses, acceptances));
        Map<String, Session> sessions = conversation.sessions;
        sessions.clear();
        phase = COLLECT_RESULTS;
        int n = 0;
        for (Object o : acceptances) {
            ACLMessage m = (ACLMessage) o;
            if (m.getConversationId() == null) {
                m.setConversationId(conversation.conversationId());
            }
            if (m.getProtocol() == null) {
                m.setProtocol(cfp.getProtocol());
            }
            if (m.getPerformative() == ACLMessage.ACCEPT_PROPOSAL) {
                for (jade.util.leap.Iterator it = m.getAllReceiver(); it.hasNext(); ) {
                    AID r = (AID) it.next();
                    String key = m.getReplyWith() != null ? m.getReplyWith() : "A" + hashCode() + "_" + (n++);
                    m.setReplyWith(key);
                    sessions.put(key, new Session(key, r));
                }
            }
            myAgent.send(m);
        }
        if (sessions.isEmpty()) {
            // Nothing accepted: JADE 4.3 ends the protocol here, without handleAllResultNotifications.
            finished = true;
            return;
        }
        checkProgress();
    }

    /**
     * Runs the step registered for that handler (the reply, if any, under {@link #REPLY_KEY}; the
     * vectors under {@link #ALL_RESPONSES_KEY}, {@link #ALL_ACCEPTANCES_KEY} (a step adds its
     * acceptances there) and {@link #ALL_RESULT_NOTIFICATIONS_KEY}), or else the handler.
     */
    private void step(String handler, ACLMessage reply, Runnable otherwise) {
        if (reply != null) {
            getDataStore().put(REPLY_KEY, reply);
        }
        if (!States.run(this, steps.get(handler), getDataStore(), null)) {
            otherwise.run();
        }
    }

    /** In place of {@link #prepareCfps}: reads {@link #CFP_KEY}, puts the Vector of CFPs under {@link #ALL_CFPS_KEY}. Registered steps run on the spot, to their end. */
    public void registerPrepareCfps(jade.core.behaviours.Behaviour b) {
        steps.put("prepareCfps", b);
    }

    /** In place of {@link #handlePropose}: the PROPOSE is under {@link #REPLY_KEY}. */
    public void registerHandlePropose(jade.core.behaviours.Behaviour b) {
        steps.put("handlePropose", b);
    }

    /** In place of {@link #handleRefuse}: the REFUSE is under {@link #REPLY_KEY}. */
    public void registerHandleRefuse(jade.core.behaviours.Behaviour b) {
        steps.put("handleRefuse", b);
    }

    /** In place of {@link #handleInform}: the INFORM is under {@link #REPLY_KEY}. */
    public void registerHandleInform(jade.core.behaviours.Behaviour b) {
        steps.put("handleInform", b);
    }

    /** In place of {@link #handleNotUnderstood}: the message is under {@link #REPLY_KEY}. */
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

    /** In place of {@link #handleAllResponses}: the responses under {@link #ALL_RESPONSES_KEY}, the acceptances to fill under {@link #ALL_ACCEPTANCES_KEY}. */
    public void registerHandleAllResponses(jade.core.behaviours.Behaviour b) {
        steps.put("handleAllResponses", b);
    }

    /** In place of {@link #handleAllResultNotifications}: the Vector is under {@link #ALL_RESULT_NOTIFICATIONS_KEY}. */
    public void registerHandleAllResultNotifications(jade.core.behaviours.Behaviour b) {
        steps.put("handleAllResultNotifications", b);
    }

    /** The CFPs to send; by default the message given to the constructor. */
    protected Vector prepareCfps(ACLMessage cfp) {
        Vector v = new Vector(1);
        v.add(cfp);
        return v;
    }

    /** A responder proposed; {@code acceptances} is the vector {@link #handleAllResponses} gets too. */
    protected void handlePropose(ACLMessage propose, Vector acceptances) {
        // JADE's documented default: nothing.
    }

    /** A responder refused. */
    protected void handleRefuse(ACLMessage refuse) {
        // JADE's documented default: nothing.
    }

    /** A responder did not understand. */
    protected void handleNotUnderstood(ACLMessage notUnderstood) {
        // JADE's documented default: nothing.
    }

    /** A responder failed (to answer, or to carry out an accepted proposal). */
    protected void handleFailure(ACLMessage failure) {
        // JADE's documented default: nothing.
    }

    /** A responder whose proposal was accepted sent its result. */
    protected void handleInform(ACLMessage inform) {
        // JADE's documented default: nothing.
    }

    /** A message of this conversation that does not fit where it is. */
    protected void handleOutOfSequence(ACLMessage msg) {
        // JADE's documented default: nothing.
    }

    /**
     * Every responder answered (or time is up): put ACCEPT_PROPOSAL and REJECT_PROPOSAL replies in
     * {@code acceptances}; they are sent when this returns.
     */
    protected void handleAllResponses(Vector responses, Vector acceptances) {
        // JADE's documented default: nothing (no acceptance is sent).
    }

    /** Every accepted responder sent its result. */
    protected void handleAllResultNotifications(Vector resultNotifications) {
        // JADE's documented default: nothing.
    }

    /** Starts over with a new CFP. */
    public void reset(ACLMessage msg) {
        this.cfp = msg;
        reset();
    }

    @Override
    public void reset() {
        super.reset();
        conversation.clear();
        responses = new Vector();
        acceptances = new Vector();
        resultNotifications = new Vector();
        phase = SEND_CFPS;
        finished = false;
    }
}
