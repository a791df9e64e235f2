import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.FSMBehaviour;
import jade.core.behaviours.OneShotBehaviour;
import jade.core.behaviours.SequentialBehaviour;

/** A sequential behaviour of three steps, then an FSM that loops once through B back to A, as JADE's FSM example does. */
public class Steps extends Agent {
    private int visitsOfA;

    private Behaviour step(final String name, final int exit) {
        return new OneShotBehaviour(this) {
            @Override
            public void onStart() {
                System.out.println("start " + name);
            }

            @Override
            public void action() {
                System.out.println("action " + name);
            }

            @Override
            public int onEnd() {
                System.out.println("end " + name + " -> " + exit);
                return exit;
            }
        };
    }

    @Override
    protected void setup() {
        SequentialBehaviour seq = new SequentialBehaviour(this) {
            @Override
            public int onEnd() {
                System.out.println("sequence over, children " + getChildren().size());
                myAgent.addBehaviour(fsm());
                return 0;
            }
        };
        seq.addSubBehaviour(step("one", 1));
        seq.addSubBehaviour(step("two", 2));
        seq.addSubBehaviour(step("three", 3));
        addBehaviour(seq);
    }

    private FSMBehaviour fsm() {
        FSMBehaviour fsm = new FSMBehaviour(this) {
            @Override
            public int onEnd() {
                System.out.println("fsm over, last exit " + getLastExitValue());
                myAgent.doDelete();
                return super.onEnd();
            }
        };
        fsm.registerFirstState(new OneShotBehaviour(this) {
            @Override
            public void action() {
                visitsOfA++;
                System.out.println("state A, visit " + visitsOfA);
            }

            @Override
            public int onEnd() {
                return visitsOfA;
            }
        }, "A");
        fsm.registerState(step("B", 0), "B");
        fsm.registerState(step("C", 5), "C");
        fsm.registerLastState(step("D", 7), "D");
        fsm.registerTransition("A", "B", 1);
        fsm.registerTransition("A", "C", 2);
        fsm.registerDefaultTransition("B", "A");
        fsm.registerTransition("C", "D", 5);
        return fsm;
    }

    @Override
    protected void takeDown() {
        System.out.println("taken down");
        System.exit(0);
    }
}
