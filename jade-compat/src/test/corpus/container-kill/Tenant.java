import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;

import java.util.concurrent.CountDownLatch;

/** Registers with the DF; when its container is killed, its takeDown searches the DF, deregisters and says goodbye. */
public class Tenant extends Agent {
    static final CountDownLatch ready = new CountDownLatch(1);

    @Override
    protected void setup() {
        DFAgentDescription dfd = new DFAgentDescription();
        ServiceDescription sd = new ServiceDescription();
        sd.setType("lodging");
        sd.setName("room-1");
        dfd.addServices(sd);
        try {
            DFService.register(this, dfd);
        } catch (FIPAException e) {
            System.out.println("register failed");
        }
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                block();
            }
        });
        System.out.println("tenant moved in");
        ready.countDown();
    }

    @Override
    protected void takeDown() {
        try {
            DFAgentDescription t = new DFAgentDescription();
            ServiceDescription sd = new ServiceDescription();
            sd.setType("lodging");
            t.addServices(sd);
            System.out.println("takeDown sees " + DFService.search(this, t).length + " lodging entry");
            DFService.deregister(this);
            System.out.println("takeDown deregistered, now " + DFService.search(this, t).length);
        } catch (FIPAException e) {
            System.out.println("DF from takeDown failed: " + e.getMessage());
        }
        System.out.println("tenant moved out");
    }
}
