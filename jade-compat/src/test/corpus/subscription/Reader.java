import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.SubscriptionInitiator;

import java.util.Vector;

/**
 * Subscribes to the publisher's news with a SubscriptionInitiator, asks for two issues one after
 * the other, cancels (not waiting for an answer); then tries a subscription the
 * publisher refuses. Every step follows the one before, so the lines come in one order.
 */
public class Reader extends Agent {
    private static final AID PUBLISHER = new AID("publisher", AID.ISLOCALNAME);

    @Override
    protected void setup() {
        addBehaviour(new SubscriptionInitiator(this, subscription("news")) {
            private int issues;

            @Override
            protected void handleAgree(ACLMessage agree) {
                System.out.println("reader: agreed by " + agree.getSender().getLocalName() + ", protocol " + agree.getProtocol());
                publish("issue 1");
            }

            @Override
            protected void handleAllResponses(Vector responses) {
                System.out.println("reader: all responses " + responses.size());
            }

            @Override
            protected void handleInform(ACLMessage inform) {
                issues++;
                System.out.println("reader: got " + inform.getContent() + " in reply to my subscription: "
                        + (inform.getInReplyTo() != null));
                if (issues == 1) {
                    publish("issue 2");
                } else {
                    cancel(PUBLISHER, true);
                    myAgent.addBehaviour(new SubscriptionInitiator(myAgent, subscription("gossip")) {
                        @Override
                        protected void handleRefuse(ACLMessage refuse) {
                            System.out.println("reader: refused: " + refuse.getContent());
                            myAgent.doDelete();
                        }
                    });
                }
            }
        });
    }

    private ACLMessage subscription(String topic) {
        ACLMessage m = new ACLMessage(ACLMessage.SUBSCRIBE);
        m.addReceiver(PUBLISHER);
        m.setProtocol(FIPANames.InteractionProtocol.FIPA_SUBSCRIBE);
        m.setContent(topic);
        return m;
    }

    private void publish(String issue) {
        ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
        m.addReceiver(PUBLISHER);
        m.setContent(issue);
        send(m);
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
