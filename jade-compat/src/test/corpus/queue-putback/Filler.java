import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;

/** Sends five numbered messages and an end mark. */
public class Filler extends Agent {
    @Override
    protected void setup() {
        for (int i = 1; i <= 5; i++) {
            ACLMessage m = new ACLMessage(ACLMessage.INFORM);
            m.addReceiver(new AID("queue", AID.ISLOCALNAME));
            m.setContent("m" + i);
            send(m);
        }
        ACLMessage end = new ACLMessage(ACLMessage.CONFIRM);
        end.addReceiver(new AID("queue", AID.ISLOCALNAME));
        end.setContent("end");
        send(end);
    }
}
