import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** Waits for "go", then takes messages out of its queue with templates of each kind. */
public class Picker extends Agent {
    @Override
    protected void setup() {
        blockingReceive(MessageTemplate.MatchContent("go"));
        System.out.println("queue " + getCurQueueSize());
        take("orders and inform", MessageTemplate.and(MessageTemplate.MatchOntology("orders"),
                MessageTemplate.MatchPerformative(ACLMessage.INFORM)));
        take("conversation c3", MessageTemplate.MatchConversationId("c3"));
        take("in reply to nothing", MessageTemplate.MatchInReplyTo("nothing"));
        take("reply-with rw-c5", MessageTemplate.MatchReplyWith("rw-c5"));
        take("not weather", MessageTemplate.not(MessageTemplate.MatchOntology("weather")));
        take("sender and language", MessageTemplate.and(MessageTemplate.MatchSender(new AID("sender", AID.ISLOCALNAME)),
                MessageTemplate.MatchLanguage("plain")));
        ACLMessage example = new ACLMessage(ACLMessage.REQUEST);
        example.setContent("buy");
        take("custom example, performative too", MessageTemplate.MatchCustom(example, true));
        take("request or propose", MessageTemplate.or(MessageTemplate.MatchPerformative(ACLMessage.REQUEST),
                MessageTemplate.MatchPerformative(ACLMessage.PROPOSE)));
        ACLMessage rest = receive();
        System.out.println("rest " + (rest == null ? "none" : rest.getContent()) + ", queue " + getCurQueueSize());
        System.out.println("receive on empty queue " + receive());
        doDelete();
    }

    private void take(String what, MessageTemplate t) {
        ACLMessage m = receive(t);
        System.out.println(what + ": " + (m == null ? "none" : ACLMessage.getPerformative(m.getPerformative()) + " "
                + m.getConversationId() + " " + m.getContent()));
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
