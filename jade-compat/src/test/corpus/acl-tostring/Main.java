import jade.core.AID;
import jade.lang.acl.ACLMessage;

import java.util.Date;

/** What ACLMessage.toString() prints (programs print messages to trace them), without a platform. */
public class Main {
    public static void main(String[] args) {
        ACLMessage empty = new ACLMessage(ACLMessage.REQUEST);
        System.out.println(empty);
        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
        m.setSender(new AID("seller@shop", AID.ISGUID));
        m.addReceiver(new AID("buyer@shop", AID.ISGUID));
        m.addReceiver(new AID("other@shop", AID.ISGUID));
        m.addReplyTo(new AID("desk@shop", AID.ISGUID));
        m.setContent("price \"Dune\" 30");
        m.setLanguage("fipa-sl");
        m.setEncoding("utf-8");
        m.setOntology("book-shop");
        m.setProtocol("fipa-request");
        m.setConversationId("c-1");
        m.setReplyWith("r-1");
        m.setInReplyTo("q-1");
        m.setReplyByDate(new Date(1700000000123L));
        m.addUserDefinedParameter("X-note", "kept");
        System.out.println(m);
        ACLMessage plain = new ACLMessage(ACLMessage.CFP);
        plain.setContent("just words");
        plain.addReceiver(new AID("x@shop", AID.ISGUID));
        System.out.println(plain.toString());
        AID rich = new AID("agent@shop", AID.ISGUID);
        rich.addAddresses("http://host:7778/acc");
        rich.addAddresses("http://host:7779/acc");
        rich.addResolvers(new AID("resolver@shop", AID.ISGUID));
        ACLMessage withRich = new ACLMessage(ACLMessage.PROPOSE);
        withRich.setSender(rich);
        withRich.addReplyTo(new AID("a@shop", AID.ISGUID));
        withRich.addReplyTo(new AID("b@shop", AID.ISGUID));
        withRich.setReplyWith("r");
        withRich.setProtocol("p");
        withRich.setContent("  padded  ");
        System.out.println(withRich);
        System.out.println(rich);
        ACLMessage param = new ACLMessage(ACLMessage.AGREE);
        param.setConversationId("c");
        param.addUserDefinedParameter("X-only", "v");
        System.out.println(param);
        System.out.println("done");
    }
}
