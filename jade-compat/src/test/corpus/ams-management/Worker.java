import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;

/** Tells the boss (its first argument) that it started, and that it is going when it is killed. */
public class Worker extends Agent {
    private AID boss;

    @Override
    protected void setup() {
        boss = new AID((String) getArguments()[0], AID.ISLOCALNAME);
        tell("hello from " + getLocalName());
    }

    @Override
    protected void takeDown() {
        tell("bye from " + getLocalName());
    }

    private void tell(String s) {
        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
        m.addReceiver(boss);
        m.setContent(s);
        send(m);
    }
}
