package io.concord.bench.jade;

import io.concord.bench.support.Rounds;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

/**
 * A JADE agent that REQUESTs a foreign agent over HTTP and waits for its INFORM, round after
 * round. Arguments: Rounds, the target's name, its HTTP address, the content.
 */
public class JadeHttpRequester extends Agent {
    @Override
    protected void setup() {
        Object[] a = getArguments();
        Rounds rounds = (Rounds) a[0];
        AID target = new AID((String) a[1], AID.ISGUID);
        target.addAddresses((String) a[2]);
        String content = (String) a[3];
        setEnabledO2ACommunication(true, 0);
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                if (getO2AObject() != null) {
                    ask();
                    return;
                }
                ACLMessage m = receive();
                if (m == null) {
                    block();
                    return;
                }
                if (m.getPerformative() != ACLMessage.INFORM) {
                    rounds.fail("the target answered " + ACLMessage.getPerformative(m.getPerformative()) + ": " + m.getContent());
                } else if (!content.equals(m.getContent())) {
                    rounds.fail("the answer came back changed");
                } else if (rounds.roundDone()) {
                    ask();
                }
            }

            private void ask() {
                ACLMessage r = new ACLMessage(ACLMessage.REQUEST);
                r.addReceiver(target);
                r.setContent(content);
                send(r);
            }
        });
        rounds.agentReady();
    }
}
