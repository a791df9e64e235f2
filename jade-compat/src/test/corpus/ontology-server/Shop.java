import jade.core.Agent;
import jade.core.behaviours.OntologyServer;
import jade.lang.acl.ACLMessage;

/** Serves the shop ontology's REQUESTs, QUERY_IFs and INFORMs with an OntologyServer; the agent is the server delegate
 * (without one, JADE looks for the serve methods on the OntologyServer itself). */
public class Shop extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new OntologyServer(this, ShopOntology.getInstance(), new int[] {ACLMessage.REQUEST, ACLMessage.QUERY_IF, ACLMessage.INFORM}, this));
    }

    public void serveSellRequest(Sell s, ACLMessage request) {
        System.out.println("shop: sell " + s.getItem());
        if (s.getItem().equals("boom")) {
            throw new IllegalStateException("boom!");
        }
        ACLMessage r = request.createReply();
        r.setPerformative(ACLMessage.INFORM);
        r.setContent("sold " + s.getItem());
        send(r);
    }

    public void serveOwnsQueryIf(Owns o, ACLMessage query) {
        System.out.println("shop: owns " + o.getItem() + "?");
        ACLMessage r = query.createReply();
        r.setPerformative(ACLMessage.INFORM);
        r.setContent(o.getItem().equals("tea") ? "yes" : "no");
        send(r);
    }
}
