package jade.proto;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.SimpleBehaviour;
import jade.lang.acl.ACLMessage;

import java.util.Map;
import java.util.Vector;

/**
 * JADE's initiator of FIPA-subscribe: sends the subscription to each receiver, then calls
 * {@link #handleAgree}, {@link #handleRefuse}, {@link #handleNotUnderstood} for the answers,
 * {@link #handleAllResponses} once every receiver has answered (a notification before any agree
 * counts as the answer, as JADE's DF sends no agree), {@link #handleInform} for every
 * notification, and {@link #handleFailure} when a receiver ends the subscription. It lasts until
 * every subscription has ended: refused, failed, or cancelled with {@link #cancel}.
 */
@SuppressWarnings({"rawtypes", "unchecked"})
public class SubscriptionInitiator extends SimpleBehaviour {
    private static final long serialVersionUID = 1L;

    /** Data store keys, as JADE names them. */
    public final String SUBSCRIPTION_KEY = "__subscription" + hashCode();
    public final String ALL_SUBSCRIPTIONS_KEY = "__all-subscriptions" + hashCode();
    public final String REPLY_KEY = "__reply" + hashCode();
    public final String ALL_RESPONSES_KEY = "__all-responses" + hashCode();

    private static final int CANCELLING = 3;

    private ACLMessage subscription;
    private final Initiations conversation = new Initiations(this, "S");
    private final Map<String, Session> sessions = conversation.sessions;
    private Vector responses = new Vector();
    private boolean sent;
    private boolean allResponsesHandled;
    private boolean finished;

    public SubscriptionInitiator(Agent a, ACLMessage msg) {
        this(a, msg, new DataStore());
    }

    public SubscriptionInitiator(Agent a, ACLMessage msg, DataStore store) {
        super(a);
        setDataStore(store);
        this.subscription = msg;
    }

    @Override
    public void action() {
        if (!sent) {
            sendSubscriptions();
            return;
        }
        conversation.receive(REPLY_KEY, !allResponsesHandled, reply -> {
            handleReply(reply);
            checkProgress();
        }, () -> {
            allResponsesHandled = true;
            handleAllResponses(responses);
        });
    }

    @Override
    public boolean done() {
        return finished;
    }

    private void sendSubscriptions() {
        sent = true;
        Vector toSend = prepareSubscriptions(subscription);
        getDataStore().put(SUBSCRIPTION_KEY, subscription);
        getDataStore().put(ALL_SUBSCRIPTIONS_KEY, toSend);
        getDataStore().put(ALL_RESPONSES_KEY, responses);
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
        if (s.state == CANCELLING) {
            // The answer to a cancel goes to the handlers as any message of the conversation does
            // (as JADE 4.3 does), and ends the subscription there.
            s.state = Session.DONE;
            if (p == ACLMessage.INFORM) {
                handleInform(reply);
            } else if (p == ACLMessage.FAILURE) {
                handleFailure(reply);
            } else {
                handleOutOfSequence(reply);
            }
            cancellationCompleted(s.receiver);
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
            if (s.state == Session.SENT) {
                s.state = Session.RESPONDED;
                responses.add(reply);
            }
            handleInform(reply);
        } else if (p == ACLMessage.FAILURE) {
            s.state = Session.DONE;
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
        }
    }

    /**
     * Cancels the subscription at this receiver: sends CANCEL in the conversation (its content is
     * filled by {@link #fillCancelContent}). With {@code ignoreResponse} the subscription ends at
     * once (JADE 4.3 calls no handler then); else the receiver's answer goes to the handlers, the
     * subscription ends, and {@link #cancellationCompleted} is called.
     */
    public void cancel(AID receiver, boolean ignoreResponse) {
        for (Session s : new java.util.ArrayList<>(sessions.values())) {
            if (s.receiver.equals(receiver) && s.state != Session.DONE && s.state != CANCELLING) {
                ACLMessage c = new ACLMessage(ACLMessage.CANCEL);
                c.addReceiver(receiver);
                c.setConversationId(conversation.conversationId());
                c.setProtocol(subscription.getProtocol());
                c.setLanguage(subscription.getLanguage());
                c.setOntology(subscription.getOntology());
                fillCancelContent(subscription, c);
                c.setReplyWith("C" + s.key);
                myAgent.send(c);
                if (ignoreResponse) {
                    s.state = Session.DONE;
                } else {
                    sessions.put("C" + s.key, s);
                    s.state = CANCELLING;
                }
            }
        }
        checkProgress();
        restart();
    }

    /** Fills the CANCEL's content; by default with the subscription's content. */
    protected void fillCancelContent(ACLMessage subscription, ACLMessage cancel) {
        cancel.setContent(subscription.getContent());
    }

    /** The subscription at this receiver has been cancelled. */
    public void cancellationCompleted(AID receiver) {
        // JADE's documented default: nothing.
    }

    /** The subscriptions to send; by default the message given to the constructor. */
    protected Vector prepareSubscriptions(ACLMessage subscription) {
        Vector v = new Vector(1);
        v.add(subscription);
        return v;
    }

    /** A receiver agreed to the subscription. */
    protected void handleAgree(ACLMessage agree) {
        // JADE's documented default: nothing.
    }

    /** A receiver refused the subscription. */
    protected void handleRefuse(ACLMessage refuse) {
        // JADE's documented default: nothing.
    }

    /** A receiver did not understand the subscription. */
    protected void handleNotUnderstood(ACLMessage notUnderstood) {
        // JADE's documented default: nothing.
    }

    /** A notification. */
    protected void handleInform(ACLMessage inform) {
        // JADE's documented default: nothing.
    }

    /** A receiver ended the subscription with a failure. */
    protected void handleFailure(ACLMessage failure) {
        // JADE's documented default: nothing.
    }

    /** A message of this conversation that does not fit where the conversation is. */
    protected void handleOutOfSequence(ACLMessage msg) {
        // JADE's documented default: nothing.
    }

    /** Every receiver has answered the subscription, or its {@code :reply-by} time has passed. */
    protected void handleAllResponses(Vector responses) {
        // JADE's documented default: nothing.
    }

    /** Starts over with a new subscription. */
    public void reset(ACLMessage msg) {
        this.subscription = msg;
        reset();
    }

    @Override
    public void reset() {
        super.reset();
        conversation.clear();
        responses = new Vector();
        sent = false;
        allResponsesHandled = false;
        finished = false;
    }
}
