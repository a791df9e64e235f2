import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

/** Prints the first greeting and ends the program. */
public class Listener extends Agent {
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
                System.out.println(myAgent.getLocalName() + " heard: " + m.getContent() + " (" + m.getSender().getLocalName() + ")");
                System.exit(0);
            }
        });
    }
}
