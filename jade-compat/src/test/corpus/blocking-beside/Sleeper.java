import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.ACLMessage;

/** Blocks its thread in setup() (blockingReceive) and in an action (Thread.sleep, doWait): the other agent must not stall. */
public class Sleeper extends Agent {
    @Override
    protected void setup() {
        ACLMessage go = blockingReceive();
        System.out.println("sleeper woke on: " + go.getContent());
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                try {
                    Thread.sleep(50);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                myAgent.doWait(30);
                System.out.println("sleeper slept and waited");
                ACLMessage timedOut = myAgent.blockingReceive(40);
                System.out.println("sleeper timed receive: " + (timedOut == null ? "nothing" : timedOut.getContent()));
                ACLMessage m = new ACLMessage(ACLMessage.INFORM);
                m.addReceiver(new AID("ticker", AID.ISLOCALNAME));
                m.setContent("awake");
                myAgent.send(m);
                ACLMessage last = myAgent.blockingReceive();
                System.out.println("sleeper got: " + last.getContent());
                myAgent.doDelete();
            }
        });
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
