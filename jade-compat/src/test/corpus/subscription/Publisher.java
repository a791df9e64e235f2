import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.proto.SubscriptionResponder;
import jade.proto.SubscriptionResponder.Subscription;
import jade.proto.SubscriptionResponder.SubscriptionManager;

import java.util.ArrayList;
import java.util.List;

/**
 * A newsletter: a SubscriptionResponder with a SubscriptionManager that keeps the subscriptions
 * (refusing those to "gossip"), agrees to each, and sends an issue to every subscriber when asked.
 */
public class Publisher extends Agent {
    private final List<Subscription> subscribers = new ArrayList<>();

    @Override
    protected void setup() {
        SubscriptionManager manager = new SubscriptionManager() {
            @Override
            public boolean register(Subscription s) throws RefuseException, NotUnderstoodException {
                String topic = s.getMessage().getContent();
                if ("gossip".equals(topic)) {
                    System.out.println("publisher: refusing a subscription to " + topic);
                    throw new RefuseException("no gossip here");
                }
                subscribers.add(s);
                System.out.println("publisher: registered " + s.getMessage().getSender().getLocalName() + " for " + topic);
                return true;
            }

            @Override
            public boolean deregister(Subscription s) throws FailureException {
                subscribers.remove(s);
                System.out.println("publisher: deregistered " + s.getMessage().getSender().getLocalName()
                        + ", " + subscribers.size() + " left");
                return true;
            }
        };
        MessageTemplate mt = SubscriptionResponder.createMessageTemplate(ACLMessage.SUBSCRIBE);
        addBehaviour(new SubscriptionResponder(this, mt, manager) {
            @Override
            protected ACLMessage handleSubscription(ACLMessage subscription) throws NotUnderstoodException, RefuseException {
                super.handleSubscription(subscription);
                ACLMessage agree = subscription.createReply();
                agree.setPerformative(ACLMessage.AGREE);
                return agree;
            }

        });
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive(MessageTemplate.MatchPerformative(ACLMessage.REQUEST));
                if (m == null) {
                    block();
                    return;
                }
                for (Subscription s : subscribers) {
                    ACLMessage issue = new ACLMessage(ACLMessage.INFORM);
                    issue.setContent(m.getContent());
                    s.notify(issue);
                }
            }
        });
    }
}
