package io.concord.bench.jade;

import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

/** A JADE agent that answers every REQUEST with an INFORM of the same content. */
public class JadeHttpEcho extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = receive();
                if (m == null) {
                    block();
                    return;
                }
                ACLMessage r = m.createReply();
                r.setPerformative(ACLMessage.INFORM);
                r.setContent(m.getContent());
                send(r);
            }
        });
    }
}
