import jade.core.AID;
import jade.core.Agent;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;

/** Registers a service a little after it starts, while the other agent is already looking for it. */
public class Listed extends Agent {
    @Override
    protected void setup() {
        doWait(150);
        DFAgentDescription dfd = new DFAgentDescription();
        ServiceDescription sd = new ServiceDescription();
        sd.setType("late-service");
        sd.setName("late");
        dfd.addServices(sd);
        try {
            DFService.register(this, dfd);
        } catch (FIPAException e) {
            System.out.println("register failed");
        }
        ACLMessage m = new ACLMessage(ACLMessage.INFORM);
        m.addReceiver(new AID("misc", AID.ISLOCALNAME));
        m.addReplyTo(new AID("listed", AID.ISLOCALNAME));
        m.setEncoding("plain-text");
        m.setContent("registered late");
        send(m);
    }
}
