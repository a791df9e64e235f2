package io.concord.core.proto;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The responder of FIPA-Subscribe (JADE's {@code SubscriptionResponder}): {@link #handleSubscription}
 * accepts (AGREE, or {@code null} to accept silently) or refuses a SUBSCRIBE; accepted ones are
 * kept as {@link Subscription}s, to which the agent sends notifications with
 * {@link Subscription#notify(AclMessage)}; a CANCEL removes one.
 */
public class SubscriptionResponder extends CyclicBehaviour {

    /** One accepted subscription. */
    public final class Subscription {
        private final AclMessage subscribe;
        private boolean closed;

        Subscription(AclMessage subscribe) {
            this.subscribe = subscribe;
        }

        /** The SUBSCRIBE message. */
        public AclMessage getMessage() {
            return subscribe;
        }

        /**
         * Sends a notification (an INFORM, usually) to the subscriber, as part of its conversation.
         *
         * @return false if the subscription is closed
         */
        public boolean notify(AclMessage notification) {
            if (closed) {
                return false;
            }
            Replies.complete(notification, subscribe);
            myAgent.send(notification);
            return true;
        }

        /** Ends the subscription from this side. */
        public void close() {
            closed = true;
            subscriptions.remove(Replies.sessionKey(subscribe));
        }

        public boolean isClosed() {
            return closed;
        }
    }

    private final MessageTemplate template;
    private final Map<String, Subscription> subscriptions = new LinkedHashMap<>();

    public SubscriptionResponder(Agent agent, MessageTemplate template) {
        super(agent);
        this.template = template;
    }

    /** SUBSCRIBE and CANCEL messages of the fipa-subscribe protocol. */
    public static MessageTemplate createMessageTemplate() {
        return MessageTemplate.matchProtocol(FipaProtocols.SUBSCRIBE)
                .and(MessageTemplate.matchPerformative(Performative.SUBSCRIBE)
                        .or(MessageTemplate.matchPerformative(Performative.CANCEL)));
    }


    @Override
    public void action() {
        AclMessage m = myAgent.receive(template);
        if (m == null) {
            block();
            return;
        }
        if (m.getPerformative() == Performative.CANCEL) {
            Subscription s = subscriptions.remove(Replies.sessionKey(m));
            if (s != null) {
                s.closed = true;
                handleCancel(m);
            }
            return;
        }
        if (m.getPerformative() != Performative.SUBSCRIBE) {
            return;
        }
        AclMessage response;
        try {
            response = handleSubscription(m);
        } catch (FipaException e) {
            response = e.toReply(m);
        }
        if (response == null || response.getPerformative() == Performative.AGREE) {
            subscriptions.put(Replies.sessionKey(m), new Subscription(m));
        }
        if (response != null) {
            Replies.complete(response, m);
            myAgent.send(response);
        }
    }

    /** Accepts (AGREE or {@code null}) or refuses ({@link RefuseException}) a subscription. */
    protected AclMessage handleSubscription(AclMessage subscribe) throws RefuseException, NotUnderstoodException {
        AclMessage agree = subscribe.createReply();
        agree.setPerformative(Performative.AGREE);
        return agree;
    }

    /** A subscriber cancelled. */
    protected void handleCancel(AclMessage cancel) {
    }

    /** The open subscriptions, oldest first. */
    public List<Subscription> getSubscriptions() {
        return new ArrayList<>(subscriptions.values());
    }
}
