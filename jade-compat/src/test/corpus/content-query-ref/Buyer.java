import jade.content.abs.AbsAggregate;
import jade.content.abs.AbsConcept;
import jade.content.abs.AbsContentElement;
import jade.content.abs.AbsIRE;
import jade.content.abs.AbsPredicate;
import jade.content.abs.AbsVariable;
import jade.content.lang.Codec;
import jade.content.lang.sl.SLCodec;
import jade.content.lang.sl.SLVocabulary;
import jade.content.onto.Ontology;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

/** Asks, with QUERY-REF and abstract descriptors, which item Alice owns (iota) and which items Bob owns (all). */
public class Buyer extends Agent {
    private final Codec codec = new SLCodec();
    private final Ontology ontology = MusicShopOntology.getInstance();
    private int step;

    @Override
    protected void setup() {
        getContentManager().registerLanguage(codec);
        getContentManager().registerOntology(ontology);
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
        try {
            AbsPredicate eq = (AbsPredicate) getContentManager().extractAbsContent(m);
            AbsIRE ire = (AbsIRE) eq.getAbsObject(SLVocabulary.EQUALS_LEFT);
            System.out.println("buyer: " + eq.getTypeName() + " of " + ire.getTypeName() + " ?" + ire.getVariable().getName());
            Object right = eq.getAbsObject(SLVocabulary.EQUALS_RIGHT);
            if (right instanceof AbsAggregate agg) {
                for (int i = 0; i < agg.size(); i++) {
                    System.out.println("buyer:   " + Seller.describe((Item) ontology.toObject(agg.get(i))));
                }
            } else {
                System.out.println("buyer:   " + Seller.describe((Item) ontology.toObject((AbsConcept) right)));
            }
        } catch (Exception e) {
            System.out.println("buyer: cannot read the answer: " + e.getClass().getSimpleName());
        }
    }

    private void ask(String kind, String owner) {
        AbsConcept person = new AbsConcept(MusicShopOntology.PERSON);
        person.set(MusicShopOntology.PERSON_NAME, owner);
        AbsVariable x = new AbsVariable("x", MusicShopOntology.ITEM);
        AbsPredicate owns = new AbsPredicate(MusicShopOntology.OWNS);
        owns.set(MusicShopOntology.OWNS_OWNER, person);
        owns.set(MusicShopOntology.OWNS_THING, x);
        AbsIRE ire = new AbsIRE(kind);
        ire.setVariable(x);
        ire.setProposition(owns);
        ACLMessage m = new ACLMessage(ACLMessage.QUERY_REF);
        m.addReceiver(new AID("seller", AID.ISLOCALNAME));
        m.setLanguage(codec.getName());
        m.setOntology(ontology.getName());
        try {
            getContentManager().fillContent(m, (AbsContentElement) ire);
            System.out.println("buyer: asks " + m.getContent());
            send(m);
        } catch (Exception e) {
            System.out.println("buyer: cannot fill: " + e.getClass().getSimpleName());
        }
    }

    private void next() {
        step++;
        switch (step) {
            case 1 -> ask(SLVocabulary.IOTA, "Alice");
            case 2 -> ask(SLVocabulary.ALL, "Bob");
            default -> {
                System.out.println("buyer: bye");
                doDelete();
            }
        }
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
