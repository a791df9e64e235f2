import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** Sends "one", "two", "three" to the listener, each after the listener acknowledged the one before. */
public class Talker extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                for (String word : new String[] {"one", "two", "three"}) {
                    ACLMessage m = new ACLMessage(ACLMessage.INFORM);
                    m.addReceiver(new AID("listener", AID.ISLOCALNAME));
                    m.setContent(word);
                    myAgent.send(m);
                    myAgent.blockingReceive(MessageTemplate.MatchContent("ack " + word));
                }
            }
        });
    }
}
