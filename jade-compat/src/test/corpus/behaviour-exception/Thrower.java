import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.ACLMessage;

/** A behaviour throws: in JADE the agent dies (its takeDown runs) and its other behaviours stop. */
public class Thrower extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive();
                if (m == null) {
                    block();
                } else {
                    System.out.println("thrower should not be here any more");
                }
            }
        });
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                System.out.println("about to throw");
                throw new IllegalStateException("boom");
            }
        });
    }

    @Override
    protected void takeDown() {
        System.out.println("thrower's takeDown runs");
        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
        m.addReceiver(new AID("watcher", AID.ISLOCALNAME));
        m.setContent("thrower is gone");
        send(m);
    }
}
