import jade.content.ContentElement;
import jade.content.lang.Codec;
import jade.content.onto.OntologyException;
import jade.content.onto.basic.Action;
import jade.content.onto.basic.Done;
import jade.content.onto.basic.Result;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

import java.util.Date;

/**
 * Asks the seller for one thing at a time and prints what comes back: the seller's answers as
 * objects (Done, Owns, Result), and its NOT_UNDERSTOOD for content it cannot take.
 */
public class Buyer extends Agent {
    private final Codec codec = Shop.codec();
    private AID seller;
    private int step;

    @Override
    protected void setup() {
        getContentManager().registerLanguage(codec);
        getContentManager().registerOntology(Shop.ontology());
        seller = new AID("seller", AID.ISLOCALNAME);
        System.out.println("buyer: languages " + String.join(",", getContentManager().getLanguageNames())
                + " ontologies " + String.join(",", getContentManager().getOntologyNames()));
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive();
                if (m == null) {
                    block();
                    return;
                }
                if (!"ready".equals(m.getConversationId())) {
                    answer(m);
                }
                next();
            }
        });
    }

    private void answer(ACLMessage m) {
        String p = ACLMessage.getPerformative(m.getPerformative());
        if (m.getPerformative() != ACLMessage.INFORM) {
            System.out.println("buyer: " + p + " " + m.getContent());
            return;
        }
        try {
            ContentElement ce = getContentManager().extractContent(m);
            if (Shop.TEXT && ce instanceof Done) {
                System.out.println("buyer:   as written: " + m.getContent().replace(getAID().getName(), "BUYER")
                        .replace(seller.getName(), "SELLER"));
            }
            if (ce instanceof Done d) {
                Action a = (Action) d.getAction();
                System.out.println("buyer: done by " + a.getActor().getLocalName() + ": sold "
                        + ((Sell) a.getAction()).getBook().describe());
            } else if (ce instanceof Owns o) {
                System.out.println("buyer: " + o.getOwner().getLocalName() + " owns " + o.getBook().describe());
            } else if (ce instanceof Result r) {
                jade.util.leap.List items = r.getItems();
                System.out.println("buyer: result of " + ((Action) r.getAction()).getAction().getClass().getSimpleName()
                        + ", " + items.size() + " book(s)");
                for (int i = 0; i < items.size(); i++) {
                    System.out.println("buyer:   " + ((Book) items.get(i)).describe());
                }
            } else {
                System.out.println("buyer: unexpected " + ce.getClass().getSimpleName());
            }
        } catch (Exception e) {
            System.out.println("buyer: cannot read the answer: " + e.getClass().getSimpleName());
        }
    }

    private ACLMessage request() {
        ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
        m.addReceiver(seller);
        m.setLanguage(codec.getName());
        m.setOntology("book-shop");
        return m;
    }

    private void send(ContentElement ce, String what) {
        ACLMessage m = request();
        try {
            getContentManager().fillContent(m, ce);
            System.out.println("buyer: asks " + what);
            send(m);
        } catch (Exception e) {
            System.out.println("buyer: cannot fill " + what + ": " + e.getClass().getSimpleName());
            next();
        }
    }

    private void sendText(String content, String what) {
        ACLMessage m = request();
        m.setContent(content);
        System.out.println("buyer: asks " + what);
        send(m);
    }

    private void next() {
        step++;
        String actor = "(agent-identifier :name " + seller.getName() + ")";
        switch (step) {
            case 1 -> send(new Action(seller, Shop.sell(Book.of("The Hobbit", 12.5f, 310, new Date(1234567890123L), "Tolkien"))),
                    "to sell The Hobbit");
            case 2 -> send(new Action(seller, Shop.sell(Book.of("Good Omens", 9.75f, 288, null, "Pratchett", "Gaiman"))),
                    "to sell Good Omens");
            case 3 -> send(new Action(seller, Shop.browse("Tolkien")), "for Tolkien's books");
            case 4 -> {
                if (Shop.TEXT) {
                    sendText("((action " + actor + " (Sell :book ?b)))", "with a variable");
                } else {
                    next();
                }
            }
            case 5 -> {
                if (Shop.TEXT) {
                    sendText("((action " + actor + " (Sell :book (Book :authors (sequence Ann) :pages 10 :price 3.0))))",
                            "for a book without a title");
                } else {
                    next();
                }
            }
            case 6 -> {
                if (Shop.TEXT) {
                    sendText("((action " + actor + " (Sell :book (Book :authors (sequence Ann) :pages 10 :price 3.0 :title",
                            "with a cut text");
                } else {
                    next();
                }
            }
            case 7 -> {
                ACLMessage m = request();
                m.setOntology("no-such-ontology");
                m.setContent("((Owns x y))");
                System.out.println("buyer: asks in an unknown ontology");
                send(m);
            }
            case 8 -> {
                ACLMessage m = request();
                m.setLanguage("no-such-language");
                m.setContent("((Owns x y))");
                System.out.println("buyer: asks in an unknown language");
                send(m);
            }
            case 9 -> send(new Action(seller, Shop.sell(Book.of(null, 1f, 1, null, "Nobody"))), "for a book without a title");
            case 10 -> send(new Action(seller, Shop.sell(Book.of("Nameless", 1f, 1, null))), "for a book without authors");
            case 11 -> {
                try {
                    ACLMessage m = request();
                    getContentManager().fillContent(m, new Action(seller, Shop.sell(Book.of("X", 1f, 1, null, "Y"))));
                    m.setLanguage("no-such-language");
                    getContentManager().extractContent(m);
                } catch (Codec.CodecException e) {
                    System.out.println("buyer: extract in an unknown language: CodecException");
                } catch (OntologyException e) {
                    System.out.println("buyer: extract in an unknown language: OntologyException");
                }
                System.out.println("buyer: bye");
                doDelete();
            }
            default -> {
            }
        }
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
