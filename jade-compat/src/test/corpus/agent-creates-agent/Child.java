import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;

/** Says hello to its parent (its first argument) when it starts, and goodbye when it is killed. */
public class Child extends Agent {
    private AID parent;

    @Override
    protected void setup() {
        parent = new AID((String) getArguments()[0], AID.ISLOCALNAME);
        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
        m.addReceiver(parent);
        m.setContent("hello from " + getLocalName() + " " + getArguments()[1]);
        send(m);
    }

    @Override
    protected void takeDown() {
        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
        m.addReceiver(parent);
        m.setContent("bye from " + getLocalName());
        send(m);
    }
}
