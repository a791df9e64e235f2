import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.proto.ContractNetInitiator;

import java.util.ArrayList;
import java.util.Collections;
import java.util.Date;
import java.util.Enumeration;
import java.util.List;
import java.util.Vector;

/** JADE's contract-net example: CFP to four sellers, accept the cheapest, reject the others. */
public class Buyer extends Agent {
    private final List<String> events = new ArrayList<>();

    @Override
    protected void setup() {
        ACLMessage cfp = new ACLMessage(ACLMessage.CFP);
        for (String n : new String[] {"cheap", "dear", "middle", "closed"}) {
            cfp.addReceiver(new AID(n, AID.ISLOCALNAME));
        }
        cfp.setProtocol(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET);
        cfp.setReplyByDate(new Date(System.currentTimeMillis() + 20000));
        cfp.setContent("book");
        addBehaviour(new ContractNetInitiator(this, cfp) {
            @Override
            protected void handlePropose(ACLMessage propose, Vector acceptances) {
                events.add("propose " + propose.getContent() + " from " + propose.getSender().getLocalName()
                        + ", acceptances so far " + acceptances.size());
            }

            @Override
            protected void handleRefuse(ACLMessage refuse) {
                events.add("refuse from " + refuse.getSender().getLocalName() + ": " + refuse.getContent());
            }

            @Override
            protected void handleAllResponses(Vector responses, Vector acceptances) {
                System.out.println("responses " + responses.size());
                ACLMessage best = null;
                int bestPrice = Integer.MAX_VALUE;
                Enumeration e = responses.elements();
                while (e.hasMoreElements()) {
                    ACLMessage msg = (ACLMessage) e.nextElement();
                    if (msg.getPerformative() == ACLMessage.PROPOSE) {
                        ACLMessage reply = msg.createReply();
                        reply.setPerformative(ACLMessage.REJECT_PROPOSAL);
                        acceptances.addElement(reply);
                        int price = Integer.parseInt(msg.getContent());
                        if (price < bestPrice) {
                            bestPrice = price;
                            best = reply;
                        }
                    }
                }
                if (best != null) {
                    best.setPerformative(ACLMessage.ACCEPT_PROPOSAL);
                }
                System.out.println("accepting " + bestPrice + ", answers to send " + acceptances.size());
            }

            @Override
            protected void handleInform(ACLMessage inform) {
                events.add("inform from " + inform.getSender().getLocalName() + ": " + inform.getContent());
            }

            @Override
            protected void handleAllResultNotifications(Vector notifications) {
                Collections.sort(events);
                for (String s : events) {
                    System.out.println(s);
                }
                System.out.println("result notifications " + notifications.size());
                List<String> notes = new ArrayList<>();
                MessageTemplate t = MessageTemplate.MatchConversationId("rejections");
                for (int i = 0; i < 2; i++) {
                    ACLMessage note = myAgent.blockingReceive(t);
                    notes.add(note.getSender().getLocalName() + " " + note.getContent());
                }
                Collections.sort(notes);
                System.out.println("rejection notes " + notes);
                myAgent.doDelete();
            }
        });
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
