import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;

/** Lives in a peripheral container of the same platform and talks to an agent of the main container. */
public class Visitor extends Agent {
    @Override
    protected void setup() {
        ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
        m.addReceiver(new AID("home", AID.ISLOCALNAME));
        m.setContent("knock knock");
        send(m);
        ACLMessage r = blockingReceive();
        System.out.println("visitor got " + ACLMessage.getPerformative(r.getPerformative()) + " " + r.getContent());
        doDelete();
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
