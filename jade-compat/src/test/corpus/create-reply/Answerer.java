import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.util.leap.Iterator;

/** Answers with createReply(): first keeping the performative it got, then as INFORM. */
public class Answerer extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive();
                if (m == null) {
                    block();
                    return;
                }
                ACLMessage reply = m.createReply();
                int receivers = 0;
                for (Iterator it = reply.getAllReceiver(); it.hasNext(); it.next()) {
                    receivers++;
                }
                if (m.getPerformative() == ACLMessage.QUERY_IF) {
                    reply.setContent("receivers " + receivers + ", performative kept " + ACLMessage.getPerformative(reply.getPerformative()));
                    reply.setPerformative(ACLMessage.INFORM);
                } else {
                    reply.setPerformative(ACLMessage.AGREE);
                    reply.setContent("to " + ((AID) reply.getAllReceiver().next()).getLocalName());
                }
                myAgent.send(reply);
            }
        });
    }
}
