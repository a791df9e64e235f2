package io.concord.bench.throughput;

import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

import java.util.HashMap;
import java.util.Map;

/** JADE's receiver: counts every message and tells each sender every {@link #ACK_EVERY} how many it got. */
public class JadeReceiver extends Agent {
    static final int ACK_EVERY = 256;
    private final Map<jade.core.AID, Long> bySender = new HashMap<>();

    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m;
                int got = 0;
                while ((m = myAgent.receive()) != null) {
                    got++;
                    long n = bySender.merge(m.getSender(), 1L, Long::sum);
                    if (n % ACK_EVERY == 0) {
                        ACLMessage ack = new ACLMessage(ACLMessage.CONFIRM);
                        ack.addReceiver(m.getSender());
                        ack.setContent(Long.toString(n));
                        myAgent.send(ack);
                    }
                }
                if (got > 0) {
                    Counters.RECEIVED.addAndGet(got);
                }
                block();
            }
        });
    }
}
