import jade.core.Agent;
import jade.lang.acl.ACLMessage;

/** Lives in the main container; answers the visitor from the other container. */
public class Home extends Agent {
    @Override
    protected void setup() {
        ACLMessage m = blockingReceive();
        System.out.println("home got '" + m.getContent() + "' from " + m.getSender().getName());
        ACLMessage r = m.createReply();
        r.setPerformative(ACLMessage.INFORM);
        r.setContent("welcome");
        send(r);
    }
}
