import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.core.behaviours.TickerBehaviour;
import jade.lang.acl.ACLMessage;

/** Ticks three times while the other agent blocks, then wakes it; answers its "awake". */
public class Ticking extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new TickerBehaviour(this, 30) {
            @Override
            protected void onTick() {
                System.out.println("tick " + getTickCount() + " while the sleeper blocks");
                if (getTickCount() == 3) {
                    ACLMessage go = new ACLMessage(ACLMessage.INFORM);
                    go.addReceiver(new AID("sleeper", AID.ISLOCALNAME));
                    go.setContent("go");
                    myAgent.send(go);
                    stop();
                }
            }
        });
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive();
                if (m == null) {
                    block();
                    return;
                }
                System.out.println("ticker got: " + m.getContent());
                ACLMessage r = m.createReply();
                r.setContent("good morning");
                myAgent.send(r);
            }
        });
    }
}
