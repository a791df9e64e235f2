import jade.core.Agent;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;

/** Register, register again (an error), modify, search its own entry, deregister twice (the second is an error). */
public class Shop extends Agent {
    private DFAgentDescription description(String type) {
        DFAgentDescription dfd = new DFAgentDescription();
        ServiceDescription sd = new ServiceDescription();
        sd.setType(type);
        sd.setName("shop-" + type);
        dfd.addServices(sd);
        return dfd;
    }

    private void show(String when) throws FIPAException {
        DFAgentDescription t = new DFAgentDescription();
        t.setName(getAID());
        DFAgentDescription[] r = DFService.search(this, t);
        StringBuilder b = new StringBuilder();
        for (DFAgentDescription d : r) {
            ServiceDescription sd = (ServiceDescription) d.getAllServices().next();
            b.append(d.getName().getLocalName()).append(':').append(sd.getType());
        }
        System.out.println(when + ": " + r.length + " " + b);
    }

    @Override
    protected void setup() {
        try {
            DFAgentDescription d = DFService.register(this, description("fruit"));
            System.out.println("registered as " + d.getName().getLocalName());
            show("after register");
        } catch (FIPAException e) {
            System.out.println("register failed");
        }
        try {
            DFService.register(this, description("fruit"));
            System.out.println("second register accepted");
        } catch (FIPAException e) {
            System.out.println("second register refused");
        }
        try {
            DFService.modify(this, description("vegetables"));
            show("after modify");
            DFService.deregister(this);
            show("after deregister");
        } catch (FIPAException e) {
            System.out.println("modify or deregister failed");
        }
        try {
            DFService.deregister(this);
            System.out.println("second deregister accepted");
        } catch (FIPAException e) {
            System.out.println("second deregister refused");
        }
        doDelete();
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
