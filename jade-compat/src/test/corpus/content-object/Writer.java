import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;

import java.io.IOException;
import java.util.ArrayList;

/** Sends Java objects with setContentObject, then a text message. */
public class Writer extends Agent {
    @Override
    protected void setup() {
        try {
            ACLMessage m = new ACLMessage(ACLMessage.INFORM);
            m.addReceiver(new AID("reader", AID.ISLOCALNAME));
            m.setContentObject(new Order("tea", 3));
            System.out.println("writer: byte content " + m.hasByteSequenceContent());
            send(m);
            ACLMessage l = new ACLMessage(ACLMessage.INFORM);
            l.addReceiver(new AID("reader", AID.ISLOCALNAME));
            ArrayList<String> list = new ArrayList<>();
            list.add("a");
            list.add("b");
            l.setContentObject(list);
            send(l);
            ACLMessage t = new ACLMessage(ACLMessage.INFORM);
            t.addReceiver(new AID("reader", AID.ISLOCALNAME));
            t.setContent("just text");
            send(t);
        } catch (IOException e) {
            System.out.println("writer: " + e);
        }
    }
}
