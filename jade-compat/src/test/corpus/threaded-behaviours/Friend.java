import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.ACLMessage;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** Pings the worker (which wakes its sleeper), then asks its echo behaviour twice, then tells it to stop. */
public class Friend extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                AID worker = new AID("worker", AID.ISLOCALNAME);
                myAgent.send(message(ACLMessage.REQUEST, worker, "ping"));
                List<String> got = new ArrayList<>();
                for (int i = 0; i < 2; i++) {
                    got.add(myAgent.blockingReceive().getContent());
                }
                Collections.sort(got);
                System.out.println("friend: " + got);
                for (String word : new String[] {"hello", "again"}) {
                    myAgent.send(message(ACLMessage.QUERY_REF, worker, word));
                    System.out.println("friend: " + myAgent.blockingReceive().getContent());
                }
                myAgent.send(message(ACLMessage.REQUEST, worker, "stop"));
            }
        });
    }

    private static ACLMessage message(int performative, AID to, String content) {
        ACLMessage m = new ACLMessage(performative);
        m.addReceiver(to);
        m.setContent(content);
        return m;
    }
}
