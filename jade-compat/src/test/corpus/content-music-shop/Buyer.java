import jade.content.ContentElement;
import jade.content.lang.Codec;
import jade.content.lang.sl.SLCodec;
import jade.content.onto.Ontology;
import jade.content.onto.basic.Action;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.util.leap.ArrayList;
import jade.util.leap.List;

/** Buys a CD and a book, one request at a time, and prints the answers; then sends content the seller must refuse. */
public class Buyer extends Agent {
    private final Codec codec = new SLCodec();
    private final Ontology ontology = MusicShopOntology.getInstance();
    private AID seller;
    private int step;

    @Override
    protected void setup() {
        getContentManager().registerLanguage(codec);
        getContentManager().registerOntology(ontology);
        seller = new AID("seller", AID.ISLOCALNAME);
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
        if (m.getPerformative() != ACLMessage.INFORM) {
            System.out.println("buyer: " + ACLMessage.getPerformative(m.getPerformative()) + " " + m.getContent());
            return;
        }
        try {
            ContentElement ce = getContentManager().extractContent(m);
            if (ce instanceof Costs c) {
                System.out.println("buyer: " + Seller.describe(c.getItem()) + " costs " + c.getPrice());
            } else if (ce instanceof Owns o) {
                System.out.println("buyer: " + o.getOwner().getName() + " owns " + Seller.describe((Item) o.getThing()));
            }
        } catch (Exception e) {
            System.out.println("buyer: cannot read the answer: " + e.getClass().getSimpleName());
        }
    }

    private static Track track(String name, Integer duration) {
        Track t = new Track();
        t.setName(name);
        t.setDuration(duration);
        return t;
    }

    private ACLMessage request() {
        ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
        m.addReceiver(seller);
        m.setLanguage(codec.getName());
        m.setOntology(ontology.getName());
        return m;
    }

    private void ask(Sell sell, String what) {
        ACLMessage m = request();
        try {
            getContentManager().fillContent(m, new Action(seller, sell));
            System.out.println("buyer: asks to buy " + what);
            send(m);
        } catch (Exception e) {
            System.out.println("buyer: cannot fill: " + e.getClass().getSimpleName());
        }
    }

    private void askText(String content, String what) {
        ACLMessage m = request();
        m.setContent("((action (agent-identifier :name " + seller.getName() + ") " + content + "))");
        System.out.println("buyer: asks " + what);
        send(m);
    }

    private void next() {
        step++;
        switch (step) {
            case 1 -> {
                Address a = new Address();
                a.setStreet("Main Street");
                a.setNumber(7);
                a.setCity("Springfield");
                Person alice = new Person();
                alice.setName("Alice");
                alice.setAddress(a);
                CD cd = new CD();
                cd.setSerialNumber(123);
                cd.setTitle("Abbey Road");
                List tracks = new ArrayList();
                tracks.add(track("Come Together", 259));
                tracks.add(track("Something", null));
                cd.setTracks(tracks);
                Sell s = new Sell();
                s.setBuyer(alice);
                s.setItem(cd);
                s.setCreditCard("1234-5678");
                ask(s, "a CD");
            }
            case 2 -> {
                Person bob = new Person();
                bob.setName("Bob");
                Book b = new Book();
                b.setSerialNumber(7);
                b.setTitle("Dune");
                Sell s = new Sell();
                s.setBuyer(bob);
                s.setItem(b);
                ask(s, "a book");
            }
            case 3 -> askText("(sell :buyer (person :name Carol) :item (cd :title Help))", "for a CD without tracks");
            case 4 -> askText("(sell :buyer (person :name Carol :age 30) :item (book :title Emma))", "with a slot the ontology lacks");
            case 5 -> askText("(sell :buyer (person :name Carol) :item (person :name Dave))", "for a person as an item");
            case 6 -> askText("(sell :buyer (person :name Carol) :item (book :title Emma :serial-number 1.5))", "with a float for an integer");
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
