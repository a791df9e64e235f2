import jade.content.abs.AbsAggregate;
import jade.content.abs.AbsConcept;
import jade.content.abs.AbsIRE;
import jade.content.abs.AbsPredicate;
import jade.content.abs.AbsTerm;
import jade.content.lang.sl.SLCodec;
import jade.content.lang.sl.SLVocabulary;
import jade.content.onto.Ontology;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.util.leap.ArrayList;
import jade.util.leap.List;

/** Answers QUERY-REF about who owns what with (= query answer), in abstract descriptors. */
public class Seller extends Agent {
    private final Ontology ontology = MusicShopOntology.getInstance();

    @Override
    protected void setup() {
        getContentManager().registerLanguage(new SLCodec());
        getContentManager().registerOntology(ontology);
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

    static String describe(Item item) {
        StringBuilder b = new StringBuilder(item.getClass().getSimpleName()).append(" #").append(item.getSerialNumber());
        if (item instanceof CD cd) {
            b.append(" ").append(cd.getTitle()).append(" tracks:");
            for (int i = 0; i < cd.getTracks().size(); i++) {
                Track t = (Track) cd.getTracks().get(i);
                b.append(" ").append(t.getName()).append("/").append(t.getDuration());
            }
        } else if (item instanceof Book book) {
            b.append(" ").append(book.getTitle()).append(" by ").append(book.getAuthor());
        }
        return b.toString();
    }

    private static CD cd() {
        CD cd = new CD();
        cd.setSerialNumber(123);
        cd.setTitle("Abbey Road");
        List tracks = new ArrayList();
        Track t = new Track();
        t.setName("Come Together");
        t.setDuration(259);
        tracks.add(t);
        cd.setTracks(tracks);
        return cd;
    }

    private static Book book() {
        Book b = new Book();
        b.setSerialNumber(7);
        b.setTitle("Dune");
        b.setAuthor("Herbert");
        return b;
    }

    private void serve(ACLMessage m) {
        ACLMessage reply = m.createReply();
        try {
            AbsIRE ire = (AbsIRE) getContentManager().extractAbsContent(m);
            AbsPredicate p = ire.getProposition();
            String owner = ((AbsConcept) p.getAbsObject(MusicShopOntology.OWNS_OWNER)).getString(MusicShopOntology.PERSON_NAME);
            System.out.println("seller: " + ire.getTypeName() + " ?" + ire.getVariable().getName() + " such that "
                    + p.getTypeName() + " " + owner + " ?" + ire.getVariable().getName() + ", grounded " + ire.isGrounded());
            AbsPredicate eq = new AbsPredicate(SLVocabulary.EQUALS);
            eq.set(SLVocabulary.EQUALS_LEFT, ire);
            if (ire.getTypeName().equals(SLVocabulary.IOTA)) {
                eq.set(SLVocabulary.EQUALS_RIGHT, ontology.fromObject(cd()));
            } else {
                AbsAggregate all = new AbsAggregate(SLVocabulary.SEQUENCE);
                all.add((AbsTerm) ontology.fromObject(cd()));
                all.add((AbsTerm) ontology.fromObject(book()));
                eq.set(SLVocabulary.EQUALS_RIGHT, all);
            }
            reply.setPerformative(ACLMessage.INFORM);
            getContentManager().fillContent(reply, eq);
            System.out.println("seller: answers " + reply.getContent());
        } catch (Exception e) {
            System.out.println("seller: cannot answer: " + e.getClass().getSimpleName());
            reply.setPerformative(ACLMessage.NOT_UNDERSTOOD);
        }
        send(reply);
    }
}
