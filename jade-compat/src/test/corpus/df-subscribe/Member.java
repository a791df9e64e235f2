import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;

/** Registers with the DF, deregisters or leaves when told (REQUEST "register TYPE NAME", "deregister"), and says when it has. */
public class Member extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive();
                if (m == null) {
                    block();
                    return;
                }
                String[] words = m.getContent().split(" ");
                ACLMessage reply = m.createReply();
                reply.setPerformative(ACLMessage.INFORM);
                try {
                    if (words[0].equals("register")) {
                        DFAgentDescription dfd = new DFAgentDescription();
                        dfd.setName(getAID());
                        ServiceDescription sd = new ServiceDescription();
                        sd.setType(words[1]);
                        sd.setName(words[2]);
                        dfd.addServices(sd);
                        DFService.register(myAgent, dfd);
                        reply.setContent("registered");
                    } else if (words[0].equals("deregister")) {
                        DFService.deregister(myAgent);
                        reply.setContent("deregistered");
                    }
                } catch (FIPAException fe) {
                    reply.setContent("failed " + fe.getMessage());
                }
                myAgent.send(reply);
            }
        });
    }
}
