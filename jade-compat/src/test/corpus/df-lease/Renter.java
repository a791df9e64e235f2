import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;

/** Registers with a lease of one second, sees the registration, and sees it gone once the lease has run out. */
public class Renter extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                try {
                    DFAgentDescription dfd = new DFAgentDescription();
                    dfd.setName(getAID());
                    ServiceDescription sd = new ServiceDescription();
                    sd.setType("short-stay");
                    sd.setName("room");
                    dfd.addServices(sd);
                    dfd.setRelativeLeaseTime(1000);
                    DFService.register(myAgent, dfd);
                    System.out.println("registered for " + ((dfd.getLeaseTime().getTime() - System.currentTimeMillis() + 500) / 1000) + " s");
                    System.out.println("found at once: " + DFService.search(myAgent, template()).length);
                    Thread.sleep(2500);
                    System.out.println("found after the lease: " + DFService.search(myAgent, template()).length);
                    DFAgentDescription again = new DFAgentDescription();
                    again.setName(getAID());
                    again.addServices(sd);
                    DFService.register(myAgent, again);
                    System.out.println("registered again, without a lease: " + DFService.search(myAgent, template()).length);
                    DFService.deregister(myAgent);
                    System.out.println("deregistered: " + DFService.search(myAgent, template()).length);
                } catch (FIPAException | InterruptedException e) {
                    System.out.println("renter failed: " + e);
                }
                myAgent.doDelete();
            }
        });
    }

    private static DFAgentDescription template() {
        DFAgentDescription t = new DFAgentDescription();
        ServiceDescription sd = new ServiceDescription();
        sd.setType("short-stay");
        t.addServices(sd);
        return t;
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
