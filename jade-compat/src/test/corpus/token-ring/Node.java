import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

/** A ring of four agents passing a counter twice round; arguments are a String and an Integer. */
public class Node extends Agent {
    @Override
    protected void setup() {
        final AID next = new AID((String) getArguments()[0], AID.ISLOCALNAME);
        final int index = (Integer) getArguments()[1];
        if (index == 0) {
            ACLMessage m = new ACLMessage(ACLMessage.INFORM);
            m.addReceiver(next);
            m.setContent("1");
            send(m);
        }
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive();
                if (m == null) {
                    block();
                    return;
                }
                int hops = Integer.parseInt(m.getContent());
                System.out.println(myAgent.getLocalName() + " got hop " + hops + " from " + m.getSender().getLocalName());
                if (hops == 8) {
                    System.exit(0);
                }
                ACLMessage fwd = new ACLMessage(ACLMessage.INFORM);
                fwd.addReceiver(next);
                fwd.setContent(Integer.toString(hops + 1));
                myAgent.send(fwd);
            }
        });
    }
}
