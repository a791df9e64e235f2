import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.Property;
import jade.domain.FIPAAgentManagement.SearchConstraints;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.util.leap.Iterator;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** Waits until three agents say they registered, then searches the DF in several ways; one leaves, it searches again. */
public class Finder extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                MessageTemplate registered = MessageTemplate.MatchContent("registered");
                for (int i = 0; i < 3; i++) {
                    myAgent.blockingReceive(registered);
                }
                try {
                    print("book-selling", search("book-selling", null, null));
                    print("repair", search("repair", null, null));
                    print("nothing", search("astrology", null, null));
                    print("book-selling name Emma", search("book-selling", "Emma", null));
                    SearchConstraints one = new SearchConstraints();
                    one.setMaxResults(Long.valueOf(1));
                    System.out.println("book-selling at most 1: " + DFService.search(myAgent, template("book-selling", null), one).length);
                    SearchConstraints all = new SearchConstraints();
                    all.setMaxResults(Long.valueOf(-1));
                    print("any service", DFService.search(myAgent, new DFAgentDescription(), all));
                    DFAgentDescription byPrice = template("book-selling", null);
                    ((ServiceDescription) byPrice.getAllServices().next()).addProperties(new Property("price", "17"));
                    print("book-selling price 17", DFService.search(myAgent, byPrice));
                    ACLMessage leave = new ACLMessage(ACLMessage.REQUEST);
                    leave.addReceiver(new AID("seller1", AID.ISLOCALNAME));
                    leave.setContent("leave");
                    myAgent.send(leave);
                    myAgent.blockingReceive(MessageTemplate.MatchContent("deregistered"));
                    print("book-selling after seller1 left", search("book-selling", null, null));
                } catch (FIPAException fe) {
                    System.out.println("search failed " + fe.getMessage());
                }
                myAgent.doDelete();
            }
        });
    }

    private static DFAgentDescription template(String type, String name) {
        DFAgentDescription t = new DFAgentDescription();
        ServiceDescription sd = new ServiceDescription();
        sd.setType(type);
        if (name != null) {
            sd.setName(name);
        }
        t.addServices(sd);
        return t;
    }

    private DFAgentDescription[] search(String type, String name, SearchConstraints sc) throws FIPAException {
        return DFService.search(this, template(type, name));
    }

    private static void print(String what, DFAgentDescription[] found) {
        List<String> l = new ArrayList<>();
        for (DFAgentDescription d : found) {
            StringBuilder b = new StringBuilder(d.getName().getLocalName());
            for (Iterator it = d.getAllServices(); it.hasNext(); ) {
                ServiceDescription sd = (ServiceDescription) it.next();
                b.append(" ").append(sd.getType()).append("/").append(sd.getName());
                for (Iterator p = sd.getAllProperties(); p.hasNext(); ) {
                    Property pr = (Property) p.next();
                    b.append(" ").append(pr.getName()).append("=").append(pr.getValue());
                }
            }
            l.add(b.toString());
        }
        Collections.sort(l);
        System.out.println(what + ": " + found.length + " " + l);
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
