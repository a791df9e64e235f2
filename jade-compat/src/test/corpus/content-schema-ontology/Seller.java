import jade.content.ContentElement;
import jade.content.lang.Codec;
import jade.content.onto.OntologyException;
import jade.content.onto.UngroundedException;
import jade.content.onto.basic.Action;
import jade.content.onto.basic.Done;
import jade.content.onto.basic.Result;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

import java.util.Date;

/** Extracts each request, prints what it asks, and answers with an object or a NOT_UNDERSTOOD. */
public class Seller extends Agent {
    private int sold;

    @Override
    protected void setup() {
        getContentManager().registerLanguage(Shop.codec());
        getContentManager().registerOntology(Shop.ontology());
        ACLMessage ready = new ACLMessage(ACLMessage.INFORM);
        ready.addReceiver(new AID("buyer", AID.ISLOCALNAME));
        ready.setConversationId("ready");
        send(ready);
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive();
                if (m == null) {
                    block();
                    return;
                }
                serve(m);
            }
        });
    }

    private void serve(ACLMessage m) {
        ACLMessage reply = m.createReply();
        try {
            ContentElement ce = getContentManager().extractContent(m);
            Action a = (Action) ce;
            System.out.println("seller: " + m.getSender().getLocalName() + " asks " + a.getActor().getLocalName()
                    + " to " + a.getAction().getClass().getSimpleName());
            reply.setPerformative(ACLMessage.INFORM);
            if (Shop.TEXT && sold == 0) {
                System.out.println("seller:   as written: " + m.getContent().replace(m.getSender().getName(), "BUYER")
                        .replace(a.getActor().getName(), "SELLER"));
            }
            if (a.getAction() instanceof Sell s) {
                Book b = s.getBook();
                System.out.println("seller:   " + b.describe());
                sold++;
                if (sold == 1) {
                    getContentManager().fillContent(reply, new Done(a));
                } else {
                    getContentManager().fillContent(reply, Shop.owns(m.getSender(), b));
                }
            } else if (a.getAction() instanceof Browse br) {
                System.out.println("seller:   by " + br.getAuthor());
                jade.util.leap.List books = new jade.util.leap.ArrayList();
                books.add(Book.of("The Hobbit", 12.5f, 310, new Date(1234567890123L), br.getAuthor()));
                books.add(Book.of("The Silmarillion", 20f, 365, null, br.getAuthor(), "C. Tolkien"));
                getContentManager().fillContent(reply, new Result(a, books));
            }
        } catch (UngroundedException e) {
            refuse(reply, "ungrounded content", e);
        } catch (OntologyException e) {
            refuse(reply, "content outside the ontology", e);
        } catch (Codec.CodecException e) {
            refuse(reply, "unreadable content", e);
        }
        send(reply);
    }

    private void refuse(ACLMessage reply, String why, Exception e) {
        System.out.println("seller: " + why + " (" + e.getClass().getSimpleName() + ")");
        reply.setPerformative(ACLMessage.NOT_UNDERSTOOD);
        reply.setContent(why);
    }
}
