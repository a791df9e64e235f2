package jade.proto;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.SimpleBehaviour;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Vector;

/**
 * JADE's responder of FIPA-subscribe: for each SUBSCRIBE the template matches it calls
 * {@link #handleSubscription} (by default: creates the {@link Subscription} and registers it with
 * the {@link SubscriptionManager}, answering nothing) and sends what it returns (AGREE, REFUSE,
 * NOT_UNDERSTOOD; exceptions become REFUSE or NOT_UNDERSTOOD); for each CANCEL it calls
 * {@link #handleCancel} (by default: deregisters and closes the subscription) and sends what it
 * returns (a {@link FailureException} becomes a FAILURE). Notifications go through
 * {@link Subscription#notify}. It never ends.
 */
@SuppressWarnings({"rawtypes", "unchecked"})
public class SubscriptionResponder extends SimpleBehaviour implements FIPANames.InteractionProtocol {
    private static final long serialVersionUID = 1L;

    /** Data store keys, as JADE names them. */
    public final String SUBSCRIPTION_KEY = "__subscription" + hashCode();
    public final String CANCEL_KEY = "__cancel" + hashCode();
    public final String RESPONSE_KEY = "__response" + hashCode();

    private MessageTemplate template;
    /** The subscription manager given to the constructor, or null. */
    protected SubscriptionManager mySubscriptionManager;
    private final Map<String, Subscription> subscriptions = new LinkedHashMap<>();

    /**
     * Registers and deregisters the subscriptions a responder takes: the place an application keeps them.
     */
    public interface SubscriptionManager {
        /** A new subscription; throw to refuse it or say it was not understood. */
        boolean register(Subscription s) throws RefuseException, NotUnderstoodException;

        /** A subscription was cancelled; throw to answer the cancel with a FAILURE. */
        boolean deregister(Subscription s) throws FailureException;
    }

    /** One subscription a responder holds: its SUBSCRIBE message and the way to notify its subscriber. */
    public static class Subscription {
        private final SubscriptionResponder responder;
        private final ACLMessage message;
        private boolean closed;

        Subscription(SubscriptionResponder responder, ACLMessage message) {
            this.responder = responder;
            this.message = message;
        }

        /** The SUBSCRIBE message. */
        public ACLMessage getMessage() {
            return message;
        }

        /**
         * Sends a notification to the subscriber, completed with the subscription's conversation
         * id, in-reply-to, protocol and, if it has none, the subscriber as receiver.
         */
        public void notify(ACLMessage notification) {
            if (!closed) {
                responder.myAgent.send(Replies.complete(notification, message));
            }
        }

        /** Ends the subscription at this side: it is forgotten and notifies no more. */
        public void close() {
            closed = true;
            responder.subscriptions.remove(key(message));
        }

    }

    /** A template for a protocol's first message: here SUBSCRIBE (and the CANCEL that ends it) of FIPA-subscribe. */
    public static MessageTemplate createMessageTemplate(int perf) {
        return MessageTemplate.and(MessageTemplate.MatchProtocol(FIPA_SUBSCRIBE), MessageTemplate.or(
                MessageTemplate.MatchPerformative(perf), MessageTemplate.MatchPerformative(ACLMessage.CANCEL)));
    }

    public SubscriptionResponder(Agent a, MessageTemplate mt) {
        this(a, mt, null, new DataStore());
    }

    public SubscriptionResponder(Agent a, MessageTemplate mt, SubscriptionManager sm) {
        this(a, mt, sm, new DataStore());
    }

    public SubscriptionResponder(Agent a, MessageTemplate mt, SubscriptionManager sm, DataStore store) {
        super(a);
        this.template = mt;
        this.mySubscriptionManager = sm;
        setDataStore(store);
    }

    @Override
    public void action() {
        ACLMessage m = myAgent.receive(template);
        if (m == null) {
            block();
            return;
        }
        ACLMessage response;
        if (m.getPerformative() == ACLMessage.CANCEL) {
            getDataStore().put(CANCEL_KEY, m);
            response = Replies.answer(m, () -> handleCancel(m), ACLMessage.FAILURE);
        } else {
            getDataStore().put(SUBSCRIPTION_KEY, m);
            response = Replies.answer(m, () -> handleSubscription(m), ACLMessage.NOT_UNDERSTOOD, ACLMessage.REFUSE);
        }
        getDataStore().put(RESPONSE_KEY, response);
        Replies.send(myAgent, response, m);
    }

    /** Never ends. */
    @Override
    public boolean done() {
        return false;
    }

    /**
     * The answer to a subscription (AGREE, REFUSE, NOT_UNDERSTOOD, or null for none): what the
     * responder calls; by default {@link #prepareResponse}'s answer.
     */
    protected ACLMessage handleSubscription(ACLMessage subscription) throws NotUnderstoodException, RefuseException {
        return prepareResponse(subscription);
    }

    /**
     * JADE's older name for {@link #handleSubscription}. By default it creates the subscription,
     * registers it with the manager, and answers nothing.
     */
    protected ACLMessage prepareResponse(ACLMessage subscription) throws NotUnderstoodException, RefuseException {
        Subscription s = createSubscription(subscription);
        if (mySubscriptionManager != null) {
            mySubscriptionManager.register(s);
        }
        return null;
    }

    /** The answer to a cancel (or null for none). By default it deregisters and closes the subscription. */
    protected ACLMessage handleCancel(ACLMessage cancel) throws FailureException {
        Subscription s = getSubscription(cancel);
        if (s != null) {
            if (mySubscriptionManager != null) {
                mySubscriptionManager.deregister(s);
            }
            s.close();
        }
        return null;
    }

    /** A new subscription for this message, held by this responder. */
    public Subscription createSubscription(ACLMessage subscription) {
        Subscription s = new Subscription(this, subscription);
        subscriptions.put(key(subscription), s);
        return s;
    }

    /** The subscription of this message's conversation and sender, or null. */
    public Subscription getSubscription(ACLMessage m) {
        return subscriptions.get(key(m));
    }

    /** The subscription of this conversation, or null. */
    public Subscription getSubscription(String conversationId) {
        for (Subscription s : subscriptions.values()) {
            if (conversationId != null && conversationId.equals(s.getMessage().getConversationId())) {
                return s;
            }
        }
        return null;
    }

    /** Every subscription held. */
    public Vector getSubscriptions() {
        return new Vector(subscriptions.values());
    }

    /** The subscriptions of one subscriber. */
    public Vector getSubscriptions(AID subscriber) {
        List<Subscription> l = new ArrayList<>();
        for (Subscription s : subscriptions.values()) {
            if (subscriber.equals(s.getMessage().getSender())) {
                l.add(s);
            }
        }
        return new Vector(l);
    }

    private static String key(ACLMessage m) {
        return (m.getSender() == null ? "" : m.getSender().getName().toLowerCase()) + " " + m.getConversationId();
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
