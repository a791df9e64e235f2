import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.SimpleBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** Sends N pings one after the other, each after the previous pong, with a SimpleBehaviour and its own done(). */
public class Pinger extends Agent {
    @Override
    protected void setup() {
        Object[] args = getArguments();
        final AID ponger = new AID((String) args[0], AID.ISLOCALNAME);
        final int n = Integer.parseInt((String) args[1]);
        addBehaviour(new SimpleBehaviour(this) {
            private int sent;
            private int received;
            private boolean waiting;

            @Override
            public void action() {
                if (!waiting) {
                    ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
                    m.addReceiver(ponger);
                    m.setContent(Integer.toString(++sent));
                    m.setConversationId("ping-" + sent);
                    m.setReplyWith("r" + sent);
                    myAgent.send(m);
                    waiting = true;
                    return;
                }
                ACLMessage reply = myAgent.receive(MessageTemplate.and(MessageTemplate.MatchPerformative(ACLMessage.INFORM),
                        MessageTemplate.MatchInReplyTo("r" + sent)));
                if (reply == null) {
                    block();
                    return;
                }
                received++;
                System.out.println(reply.getSender().getLocalName() + " said " + reply.getContent() + " in "
                        + reply.getConversationId() + " perf " + ACLMessage.getPerformative(reply.getPerformative()));
                waiting = false;
            }

            @Override
            public boolean done() {
                return received == n;
            }

            @Override
            public int onEnd() {
                System.out.println("done after " + received);
                System.exit(0);
                return 0;
            }
        });
    }
}
