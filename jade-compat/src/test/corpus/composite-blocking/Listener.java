import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.FSMBehaviour;
import jade.core.behaviours.ParallelBehaviour;
import jade.core.behaviours.SequentialBehaviour;
import jade.core.behaviours.SimpleBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** Children that block (each acknowledges what it heard) inside a sequence inside a parallel inside an FSM: a message restarts them where they are. */
public class Listener extends Agent {
    private Behaviour waitFor(final String word) {
        return new SimpleBehaviour(this) {
            private boolean heard;

            @Override
            public void action() {
                ACLMessage m = myAgent.receive(MessageTemplate.MatchContent(word));
                if (m == null) {
                    block();
                    return;
                }
                heard = true;
                System.out.println("heard " + word);
                ACLMessage ack = m.createReply();
                ack.setContent("ack " + word);
                myAgent.send(ack);
            }

            @Override
            public boolean done() {
                return heard;
            }
        };
    }

    @Override
    protected void setup() {
        SequentialBehaviour seq = new SequentialBehaviour(this);
        seq.addSubBehaviour(waitFor("one"));
        seq.addSubBehaviour(waitFor("two"));
        ParallelBehaviour par = new ParallelBehaviour(this, ParallelBehaviour.WHEN_ALL) {
            @Override
            public int onEnd() {
                System.out.println("parallel over");
                return 4;
            }
        };
        par.addSubBehaviour(seq);
        par.addSubBehaviour(waitFor("three"));
        FSMBehaviour fsm = new FSMBehaviour(this) {
            @Override
            public int onEnd() {
                System.out.println("fsm over");
                myAgent.doDelete();
                return 0;
            }
        };
        fsm.registerFirstState(par, "LISTEN");
        fsm.registerLastState(new SimpleBehaviour(this) {
            @Override
            public void action() {
                System.out.println("last state, runnable " + isRunnable());
            }

            @Override
            public boolean done() {
                return true;
            }
        }, "END");
        fsm.registerTransition("LISTEN", "END", 4);
        addBehaviour(fsm);
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
