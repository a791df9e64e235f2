import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** Sends a request with every field set and a reply-to; prints what the reply made by createReply carries. */
public class Asker extends Agent {
    @Override
    protected void setup() {
        ACLMessage q = new ACLMessage(ACLMessage.QUERY_IF);
        q.addReceiver(new AID("answerer", AID.ISLOCALNAME));
        q.setConversationId("conv-7");
        q.setReplyWith("ask-1");
        q.setProtocol("fipa-query");
        q.setLanguage("fipa-sl");
        q.setOntology("weather");
        q.setEncoding("utf-8");
        q.setContent("(raining)");
        q.addUserDefinedParameter("trace-id", "42");
        send(q);
        ACLMessage r = blockingReceive(MessageTemplate.MatchConversationId("conv-7"));
        System.out.println("performative " + ACLMessage.getPerformative(r.getPerformative()));
        System.out.println("from " + r.getSender().getLocalName());
        System.out.println("in-reply-to " + r.getInReplyTo());
        System.out.println("protocol " + r.getProtocol() + " language " + r.getLanguage() + " ontology " + r.getOntology()
                + " encoding " + r.getEncoding());
        System.out.println("content " + r.getContent());
        System.out.println("reply-with starts with the asker's name " + (r.getReplyWith() != null && r.getReplyWith().startsWith("asker@corpus")));
        System.out.println("user parameter on the reply " + r.getUserDefinedParameter("trace-id"));
        ACLMessage viaReplyTo = new ACLMessage(ACLMessage.REQUEST);
        viaReplyTo.addReceiver(new AID("answerer", AID.ISLOCALNAME));
        viaReplyTo.addReplyTo(new AID("asker", AID.ISLOCALNAME));
        viaReplyTo.setConversationId("conv-8");
        viaReplyTo.setContent("again");
        send(viaReplyTo);
        ACLMessage r2 = blockingReceive(MessageTemplate.MatchConversationId("conv-8"));
        System.out.println("second reply " + ACLMessage.getPerformative(r2.getPerformative()) + " " + r2.getContent());
        doDelete();
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
