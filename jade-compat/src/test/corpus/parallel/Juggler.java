import jade.core.Agent;
import jade.core.behaviours.ParallelBehaviour;
import jade.core.behaviours.SimpleBehaviour;

/** Two parallel behaviours: WHEN_ALL interleaves children to the end; WHEN_ANY ends with the first child. */
public class Juggler extends Agent {
    private SimpleBehaviour counter(final String name, final int steps) {
        return new SimpleBehaviour(this) {
            private int n;

            @Override
            public void action() {
                n++;
                System.out.println(name + " step " + n);
            }

            @Override
            public boolean done() {
                return n == steps;
            }

            @Override
            public int onEnd() {
                System.out.println(name + " ended");
                return 0;
            }
        };
    }

    @Override
    protected void setup() {
        ParallelBehaviour all = new ParallelBehaviour(this, ParallelBehaviour.WHEN_ALL) {
            @Override
            public int onEnd() {
                System.out.println("all ended, terminated " + getTerminatedChildren().size());
                ParallelBehaviour any = new ParallelBehaviour(myAgent, ParallelBehaviour.WHEN_ANY) {
                    @Override
                    public int onEnd() {
                        System.out.println("any ended");
                        myAgent.doDelete();
                        return 0;
                    }
                };
                any.addSubBehaviour(counter("x", 2));
                any.addSubBehaviour(counter("y", 4));
                myAgent.addBehaviour(any);
                return 0;
            }
        };
        all.addSubBehaviour(counter("a", 2));
        all.addSubBehaviour(counter("b", 3));
        all.addSubBehaviour(counter("c", 1));
        addBehaviour(all);
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
