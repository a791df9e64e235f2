package io.concord.dist;

import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

/**
 * The book seller of the dissertation's annex D, written for JADE as a JADE user writes it:
 * QUERY-REF gets an INFORM with the price, an order (REQUEST with a quantity) gets AGREE, or
 * REFUSE below one. Argument: the price.
 */
public class JadeAnnexSeller extends Agent {
    @Override
    protected void setup() {
        String price = String.valueOf(getArguments()[0]);
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = receive();
                if (m == null) {
                    block();
                    return;
                }
                ACLMessage reply = m.createReply();
                if (m.getPerformative() == ACLMessage.QUERY_REF) {
                    reply.setPerformative(ACLMessage.INFORM);
                    reply.setContent(price);
                } else if (m.getPerformative() == ACLMessage.REQUEST) {
                    int offer = Integer.parseInt(m.getContent().trim());
                    reply.setPerformative(offer >= 1 ? ACLMessage.AGREE : ACLMessage.REFUSE);
                } else {
                    return;
                }
                System.out.println(getLocalName() + ": " + ACLMessage.getPerformative(reply.getPerformative()) + " to "
                        + m.getSender().getName());
                send(reply);
            }
        });
    }
}
