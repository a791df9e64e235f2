import jade.core.Agent;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** Hears that the thrower is gone. */
public class Watcher extends Agent {
    @Override
    protected void setup() {
        ACLMessage gone = blockingReceive(MessageTemplate.MatchContent("thrower is gone"));
        System.out.println("watcher heard: " + gone.getContent());
        doDelete();
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
