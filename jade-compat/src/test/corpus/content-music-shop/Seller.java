import jade.content.lang.Codec;
import jade.content.lang.sl.SLCodec;
import jade.content.onto.OntologyException;
import jade.content.onto.basic.Action;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

/** Reads each purchase, prints it, and answers what it costs (a CD) or who owns it now (a book). */
public class Seller extends Agent {
    private boolean printed;

    @Override
    protected void setup() {
        getContentManager().registerLanguage(new SLCodec());
        getContentManager().registerOntology(MusicShopOntology.getInstance());
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

    private void serve(ACLMessage m) {
        ACLMessage reply = m.createReply();
        try {
            Action a = (Action) getContentManager().extractContent(m);
            if (!printed) {
                printed = true;
                System.out.println("seller: as written: " + m.getContent().replace(a.getActor().getName(), "SELLER"));
            }
            Sell s = (Sell) a.getAction();
            Person p = s.getBuyer();
            Address ad = p.getAddress();
            System.out.println("seller: " + p.getName() + (ad == null ? "" : " of " + ad.getNumber() + " " + ad.getStreet() + ", " + ad.getCity())
                    + " buys " + describe(s.getItem()) + " paying with " + s.getCreditCard());
            reply.setPerformative(ACLMessage.INFORM);
            if (s.getItem() instanceof CD) {
                Costs c = new Costs();
                c.setItem(s.getItem());
                c.setPrice(15.5f);
                getContentManager().fillContent(reply, c);
            } else {
                Owns o = new Owns();
                o.setOwner(p);
                o.setThing(s.getItem());
                getContentManager().fillContent(reply, o);
            }
        } catch (OntologyException e) {
            System.out.println("seller: refused (" + e.getClass().getSimpleName() + ")");
            reply.setPerformative(ACLMessage.NOT_UNDERSTOOD);
            reply.setContent("not in the music shop's ontology");
        } catch (Codec.CodecException e) {
            System.out.println("seller: unreadable (" + e.getClass().getSimpleName() + ")");
            reply.setPerformative(ACLMessage.NOT_UNDERSTOOD);
            reply.setContent("unreadable");
        }
        send(reply);
    }
}
