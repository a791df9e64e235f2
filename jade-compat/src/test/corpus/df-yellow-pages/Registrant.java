import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.Property;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;

/** Registers its service with the DF in setup(), as JADE's book-trading seller does; deregisters in takeDown(). */
public class Registrant extends Agent {
    @Override
    protected void setup() {
        Object[] a = getArguments();
        DFAgentDescription dfd = new DFAgentDescription();
        dfd.setName(getAID());
        ServiceDescription sd = new ServiceDescription();
        sd.setType((String) a[0]);
        sd.setName((String) a[1]);
        sd.addProperties(new Property("price", a[2]));
        sd.addLanguages("english");
        dfd.addServices(sd);
        try {
            DFService.register(this, dfd);
        } catch (FIPAException fe) {
            System.out.println("register failed " + fe.getMessage());
        }
        ACLMessage ready = new ACLMessage(ACLMessage.INFORM);
        ready.addReceiver(new AID("finder", AID.ISLOCALNAME));
        ready.setContent("registered");
        send(ready);
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive();
                if (m == null) {
                    block();
                } else if ("leave".equals(m.getContent())) {
                    myAgent.doDelete();
                }
            }
        });
    }

    @Override
    protected void takeDown() {
        try {
            DFService.deregister(this);
        } catch (FIPAException fe) {
            System.out.println("deregister failed");
        }
        ACLMessage gone = new ACLMessage(ACLMessage.INFORM);
        gone.addReceiver(new AID("finder", AID.ISLOCALNAME));
        gone.setContent("deregistered");
        send(gone);
    }
}
