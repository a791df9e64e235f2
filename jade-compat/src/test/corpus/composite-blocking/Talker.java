import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.TickerBehaviour;
import jade.lang.acl.ACLMessage;

/** Sends "one", "two", "three" to the listener, one a tick. */
public class Talker extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new TickerBehaviour(this, 30) {
            @Override
            protected void onTick() {
                String[] words = {"one", "two", "three"};
                ACLMessage m = new ACLMessage(ACLMessage.INFORM);
                m.addReceiver(new AID("listener", AID.ISLOCALNAME));
                m.setContent(words[getTickCount() - 1]);
                myAgent.send(m);
                if (getTickCount() == 3) {
                    stop();
                }
            }
        });
    }
}
