import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;

/** Sends a mix of messages, then "go". */
public class Sender extends Agent {
    @Override
    protected void setup() {
        AID picker = new AID("picker", AID.ISLOCALNAME);
        String[][] mix = {
            {"INFORM", "c1", "weather", "sunny"},
            {"REQUEST", "c2", "orders", "buy"},
            {"QUERY-REF", "c3", "weather", "tomorrow?"},
            {"INFORM", "c4", "orders", "shipped"},
            {"PROPOSE", "c5", "prices", "12"},
        };
        for (String[] m : mix) {
            ACLMessage msg = new ACLMessage(ACLMessage.getInteger(m[0]));
            msg.addReceiver(picker);
            msg.setConversationId(m[1]);
            msg.setOntology(m[2]);
            msg.setContent(m[3]);
            msg.setLanguage("plain");
            msg.setReplyWith("rw-" + m[1]);
            send(msg);
        }
        ACLMessage go = new ACLMessage(ACLMessage.INFORM);
        go.addReceiver(picker);
        go.setContent("go");
        send(go);
    }
}
