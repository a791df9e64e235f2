import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.core.behaviours.ParallelBehaviour;
import jade.core.behaviours.SimpleBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.SearchConstraints;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** doWake from another thread, searchUntilFound, a parallel behaviour that ends after two of three children, more templates. */
public class Misc extends Agent {
    @Override
    protected void setup() {
        final Agent self = this;
        Thread waker = new Thread(() -> {
            try {
                Thread.sleep(50);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            self.doWake();
        });
        waker.start();
        doWait();
        System.out.println("woken by another thread");
        DFAgentDescription t = new DFAgentDescription();
        ServiceDescription sd = new ServiceDescription();
        sd.setType("late-service");
        t.addServices(sd);
        try {
            DFAgentDescription[] found = DFService.searchUntilFound(this, getDefaultDF(), t, new SearchConstraints(), 10_000);
            System.out.println("found late service: " + (found == null ? "none" : found.length + " " + found[0].getName().getLocalName()));
        } catch (FIPAException e) {
            System.out.println("search failed");
        }
        ACLMessage m = blockingReceive(MessageTemplate.and(MessageTemplate.MatchReceiver(new AID[] {getAID()}),
                MessageTemplate.and(MessageTemplate.MatchReplyTo(new AID[] {new AID("listed", AID.ISLOCALNAME)}),
                        MessageTemplate.MatchEncoding("plain-text"))));
        System.out.println("matched by receiver, reply-to and encoding: " + m.getContent());
        ParallelBehaviour two = new ParallelBehaviour(this, 2) {
            @Override
            public int onEnd() {
                System.out.println("two of three ended: " + getTerminatedChildren().size());
                myAgent.doDelete();
                return 0;
            }
        };
        for (final int steps : new int[] {3, 1, 2}) {
            two.addSubBehaviour(new SimpleBehaviour(this) {
                private int n;

                @Override
                public void action() {
                    n++;
                    System.out.println("child of " + steps + " step " + n);
                }

                @Override
                public boolean done() {
                    return n == steps;
                }
            });
        }
        addBehaviour(two);
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
