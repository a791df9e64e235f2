import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;

/** Greets the agent named by its first argument. */
public class Greeter extends Agent {
    @Override
    protected void setup() {
        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
        m.addReceiver(new AID((String) getArguments()[0], AID.ISLOCALNAME));
        m.setContent("hello from " + getLocalName());
        System.out.println(getLocalName() + " sends its greeting");
        send(m);
    }
}
