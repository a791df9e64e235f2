package io.concord.dist;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

import java.util.ArrayList;
import java.util.List;

/**
 * The book buyer of the dissertation's annex C, written for JADE as a JADE user writes it, with
 * nothing of Concord in it: it finds the sellers in its own DF ({@code book-selling}), sends each
 * a QUERY-REF, orders one book (REQUEST {@code 1}) from the cheapest, and prints the AGREE.
 * Argument: how many sellers to wait for in the DF.
 */
public class JadeAnnexBuyer extends Agent {
    private final List<AID> sellers = new ArrayList<>();
    private int wanted;
    private int quotes;
    private int best = Integer.MAX_VALUE;
    private AID bestSeller;
    private boolean ordered;
    private long nextSearch;

    @Override
    protected void setup() {
        wanted = Integer.parseInt(String.valueOf(getArguments()[0]));
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                if (sellers.size() < wanted) {
                    if (System.currentTimeMillis() >= nextSearch) {
                        search();
                    }
                    block(100);
                    return;
                }
                ACLMessage m = receive(MessageTemplate.MatchConversationId("annex-c"));
                if (m == null) {
                    block();
                    return;
                }
                if (m.getPerformative() == ACLMessage.INFORM && !ordered) {
                    int price = Integer.parseInt(m.getContent().trim());
                    System.out.println("jbuyer: quote $" + price + " from " + m.getSender().getName());
                    if (price < best) {
                        best = price;
                        bestSeller = m.getSender();
                    }
                    if (++quotes == sellers.size()) {
                        ordered = true;
                        ACLMessage order = new ACLMessage(ACLMessage.REQUEST);
                        order.addReceiver(bestSeller);
                        order.setConversationId("annex-c");
                        order.setContent("1");
                        send(order);
                    }
                } else if (m.getPerformative() == ACLMessage.AGREE) {
                    System.out.println("jbuyer: AGREE from " + m.getSender().getName() + " at $" + best);
                } else {
                    System.out.println("jbuyer: " + ACLMessage.getPerformative(m.getPerformative()) + " from "
                            + m.getSender().getName() + ": " + m.getContent());
                }
            }
        });
    }

    private void search() {
        nextSearch = System.currentTimeMillis() + 200;
        DFAgentDescription template = new DFAgentDescription();
        ServiceDescription sd = new ServiceDescription();
        sd.setType("book-selling");
        template.addServices(sd);
        try {
            DFAgentDescription[] found = DFService.search(this, template);
            if (found.length >= wanted) {
                for (DFAgentDescription d : found) {
                    sellers.add(d.getName());
                }
                System.out.println("jbuyer: found " + found.length + " sellers in the DF");
                ACLMessage q = new ACLMessage(ACLMessage.QUERY_REF);
                sellers.forEach(q::addReceiver);
                q.setConversationId("annex-c");
                q.setContent("(price (book \"The Art of Agents\"))");
                send(q);
            }
        } catch (FIPAException e) {
            System.out.println("jbuyer: DF search failed: " + e.getMessage());
        }
    }
}
