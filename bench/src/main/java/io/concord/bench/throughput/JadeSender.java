package io.concord.bench.throughput;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/**
 * JADE's sender: 32 INFORMs in each action. JADE has no flow control (its queues grow without
 * bound), so the application gives it one: at most {@link #WINDOW} messages unacknowledged; the
 * receiver acknowledges every {@link JadeReceiver#ACK_EVERY}. Arguments: receiver's local name,
 * content bytes.
 */
public class JadeSender extends Agent {
    static final int WINDOW = 2_048;
    private long sent;
    private long acked;

    @Override
    protected void setup() {
        AID to = new AID((String) getArguments()[0], AID.ISLOCALNAME);
        String content = Counters.content((Integer) getArguments()[1]);
        MessageTemplate acks = MessageTemplate.MatchPerformative(ACLMessage.CONFIRM);
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage a;
                while ((a = myAgent.receive(acks)) != null) {
                    acked = Math.max(acked, Long.parseLong(a.getContent()));
                }
                if (Counters.stopped()) {
                    myAgent.removeBehaviour(this);
                    return;
                }
                if (sent - acked >= WINDOW) {
                    block();
                    return;
                }
                for (int i = 0; i < 32; i++) {
                    ACLMessage m = new ACLMessage(ACLMessage.INFORM);
                    m.addReceiver(to);
                    m.setContent(content);
                    send(m);
                }
                sent += 32;
                Counters.SENT.addAndGet(32);
            }
        });
    }
}
