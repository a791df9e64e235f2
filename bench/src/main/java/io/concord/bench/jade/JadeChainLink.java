package io.concord.bench.jade;

import io.concord.bench.support.Rounds;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

/**
 * A link of the chain on JADE: passes the content to the next link; the first link checks it came
 * back unchanged and starts the next round. Arguments: Rounds, index, N, content.
 */
public class JadeChainLink extends Agent {
    private Rounds rounds;
    private int index;
    private int n;
    private String secret;

    @Override
    protected void setup() {
        Object[] args = getArguments();
        rounds = (Rounds) args[0];
        index = (Integer) args[1];
        n = (Integer) args[2];
        secret = (String) args[3];
        setEnabledO2ACommunication(true, 0);
        AID next = new AID("link" + ((index + 1) % n), AID.ISLOCALNAME);
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                if (index == 0 && getO2AObject() != null) {
                    pass(next, secret);
                    return;
                }
                ACLMessage m = receive();
                if (m == null) {
                    block();
                    return;
                }
                if (index != 0) {
                    pass(next, m.getContent());
                } else if (!secret.equals(m.getContent())) {
                    rounds.fail("the secret came back changed");
                } else if (rounds.roundDone()) {
                    pass(next, secret);
                }
            }
        });
        rounds.agentReady();
    }

    private void pass(AID next, String content) {
        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
        m.addReceiver(next);
        m.setContent(content);
        send(m);
    }
}
