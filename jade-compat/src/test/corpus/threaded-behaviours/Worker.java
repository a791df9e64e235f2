import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.core.behaviours.OneShotBehaviour;
import jade.core.behaviours.ThreadedBehaviourFactory;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/**
 * Two behaviours on threads of their own (ThreadedBehaviourFactory), beside an ordinary one: the
 * first sleeps until the ordinary one has seen a ping (so it can only finish if the agent's other
 * behaviours go on while it sleeps); the second echoes messages with receive() and block(), woken
 * by each message; "stop" interrupts it.
 */
public class Worker extends Agent {
    private final ThreadedBehaviourFactory tbf = new ThreadedBehaviourFactory();
    private volatile boolean pinged;
    private volatile Thread threadOfSetup;

    @Override
    protected void setup() {
        threadOfSetup = Thread.currentThread();
        addBehaviour(tbf.wrap(new OneShotBehaviour(this) {
            @Override
            public void action() {
                try {
                    while (!pinged) {
                        Thread.sleep(20);
                    }
                } catch (InterruptedException e) {
                    return;
                }
                ACLMessage m = new ACLMessage(ACLMessage.INFORM);
                m.addReceiver(new jade.core.AID("friend", jade.core.AID.ISLOCALNAME));
                m.setContent("the sleeper saw the ping");
                myAgent.send(m);
            }
        }));
        addBehaviour(tbf.wrap(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive(MessageTemplate.MatchPerformative(ACLMessage.QUERY_REF));
                if (m == null) {
                    block();
                    return;
                }
                ACLMessage r = m.createReply();
                r.setPerformative(ACLMessage.INFORM);
                r.setContent(m.getContent() + " back, from a thread of its own: " + (Thread.currentThread() != threadOfSetup));
                myAgent.send(r);
            }
        }));
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive(MessageTemplate.MatchPerformative(ACLMessage.REQUEST));
                if (m == null) {
                    block();
                    return;
                }
                if (m.getContent().equals("ping")) {
                    pinged = true;
                    ACLMessage r = m.createReply();
                    r.setPerformative(ACLMessage.INFORM);
                    r.setContent("pong");
                    myAgent.send(r);
                } else if (m.getContent().equals("stop")) {
                    System.out.println("worker: threaded behaviours before stop: " + tbf.size());
                    tbf.interrupt();
                    System.out.println("worker: all ended after interrupt: " + tbf.waitUntilEmpty(10000));
                    myAgent.doDelete();
                }
            }
        });
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
