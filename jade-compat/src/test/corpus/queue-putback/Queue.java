import jade.core.Agent;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** Messages come out in arrival order; putBack puts one at the head again. */
public class Queue extends Agent {
    @Override
    protected void setup() {
        blockingReceive(MessageTemplate.MatchPerformative(ACLMessage.CONFIRM));
        System.out.println("waiting " + getCurQueueSize());
        ACLMessage first = receive();
        ACLMessage second = receive();
        putBack(second);
        System.out.println("took " + first.getContent() + ", put back " + second.getContent() + ", waiting " + getCurQueueSize());
        StringBuilder order = new StringBuilder();
        ACLMessage m;
        while ((m = receive()) != null) {
            order.append(m.getContent()).append(' ');
        }
        System.out.println("order " + order.toString().trim());
        doDelete();
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
