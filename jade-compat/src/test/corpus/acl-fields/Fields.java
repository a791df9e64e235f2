import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;

import java.util.Date;

/** ACLMessage's accessors, performative names and numbers, clone and reset. */
public class Fields extends Agent {
    @Override
    protected void setup() {
        System.out.println("INFORM " + ACLMessage.INFORM + " REQUEST " + ACLMessage.REQUEST + " CFP " + ACLMessage.CFP
                + " PROPOSE " + ACLMessage.PROPOSE + " PROXY " + ACLMessage.PROXY);
        String[] names = ACLMessage.getAllPerformativeNames();
        System.out.println("names " + names.length + " first " + names[0] + " last " + names[names.length - 1]);
        System.out.println("name of 13 " + ACLMessage.getPerformative(13) + ", number of query-if " + ACLMessage.getInteger("query-if")
                + ", number of nonsense " + ACLMessage.getInteger("nonsense"));
        ACLMessage m = new ACLMessage();
        System.out.println("default performative " + ACLMessage.getPerformative(m.getPerformative()));
        m.setPerformative(ACLMessage.REQUEST);
        m.addReceiver(new AID("a", AID.ISLOCALNAME));
        m.addReceiver(new AID("b", AID.ISLOCALNAME));
        m.removeReceiver(new AID("a", AID.ISLOCALNAME));
        m.setSender(getAID());
        m.setContent("hello");
        m.setLanguage("l");
        m.setOntology("o");
        m.setProtocol("p");
        m.setConversationId("c");
        m.setReplyWith("rw");
        m.setInReplyTo("irt");
        m.setEncoding("e");
        m.setReplyByDate(new Date(1000));
        m.addUserDefinedParameter("color", "blue");
        ACLMessage c = (ACLMessage) m.clone();
        m.setContent("changed");
        System.out.println("clone content " + c.getContent() + " receiver " + ((AID) c.getAllReceiver().next()).getLocalName()
                + " sender " + c.getSender().getLocalName());
        System.out.println("fields " + c.getLanguage() + c.getOntology() + c.getProtocol() + c.getConversationId() + c.getReplyWith()
                + c.getInReplyTo() + c.getEncoding() + " reply-by " + c.getReplyByDate().getTime() + " color " + c.getUserDefinedParameter("color"));
        System.out.println("remove parameter " + c.removeUserDefinedParameter("color") + " then " + c.getUserDefinedParameter("color"));
        c.setByteSequenceContent(new byte[] {104, 105});
        System.out.println("bytes " + c.hasByteSequenceContent() + " as text " + c.getContent());
        c.setContent("text again");
        System.out.println("bytes after text " + c.hasByteSequenceContent());
        m.reset();
        System.out.println("after reset " + ACLMessage.getPerformative(m.getPerformative()) + " content " + m.getContent()
                + " receivers " + m.getAllReceiver().hasNext() + " sender " + m.getSender());
        doDelete();
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
