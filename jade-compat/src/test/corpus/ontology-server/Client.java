import jade.content.ContentElement;
import jade.content.lang.sl.SLCodec;
import jade.content.onto.basic.Action;
import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.ACLMessage;

/** Sends the shop each kind of message in turn and prints each answer (or that none came). */
public class Client extends Agent {
    @Override
    protected void setup() {
        getContentManager().registerLanguage(new SLCodec());
        getContentManager().registerOntology(ShopOntology.getInstance());
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                try {
                    Sell tea = new Sell();
                    tea.setItem("tea");
                    ask(ACLMessage.REQUEST, new Action(getAID(), tea), null);
                    Owns owns = new Owns();
                    owns.setItem("tea");
                    ask(ACLMessage.QUERY_IF, owns, null);
                    ask(ACLMessage.INFORM, owns, null);
                    Buy buy = new Buy();
                    buy.setItem("salt");
                    ask(ACLMessage.REQUEST, new Action(getAID(), buy), null);
                    ask(ACLMessage.REQUEST, null, "((garbage");
                    Sell boom = new Sell();
                    boom.setItem("boom");
                    ask(ACLMessage.REQUEST, new Action(getAID(), boom), null);
                } catch (Exception e) {
                    System.out.println("client failed: " + e);
                }
                myAgent.doDelete();
            }
        });
    }

    private void ask(int performative, ContentElement ce, String raw) throws Exception {
        ACLMessage m = new ACLMessage(performative);
        m.addReceiver(new AID("shop", AID.ISLOCALNAME));
        m.setLanguage(new SLCodec().getName());
        m.setOntology(ShopOntology.getInstance().getName());
        if (ce != null) {
            getContentManager().fillContent(m, ce);
        } else {
            m.setContent(raw);
        }
        send(m);
        ACLMessage r = blockingReceive(1500);
        System.out.println("client: " + ACLMessage.getPerformative(performative) + " -> "
                + (r == null ? "no answer" : ACLMessage.getPerformative(r.getPerformative()) + " " + r.getContent()));
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
