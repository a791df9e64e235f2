import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.OneShotBehaviour;
import jade.core.behaviours.SimpleBehaviour;
import jade.core.behaviours.WakerBehaviour;

/** block(ms) wakes a behaviour when the time passes; restart() from another behaviour wakes a blocked one at once. */
public class Waiter extends Agent {
    @Override
    protected void setup() {
        final SimpleBehaviour sleepy = new SimpleBehaviour(this) {
            private int runs;

            @Override
            public void action() {
                runs++;
                System.out.println("sleepy run " + runs + " restarts " + getRestartCounter());
                block();
            }

            @Override
            public boolean done() {
                return runs == 2;
            }

            @Override
            public int onEnd() {
                System.out.println("sleepy ended");
                myAgent.doDelete();
                return 0;
            }
        };
        addBehaviour(new SimpleBehaviour(this) {
            private int runs;

            @Override
            public void action() {
                runs++;
                System.out.println("timed run " + runs + ", runnable " + isRunnable());
                if (runs < 3) {
                    block(40);
                }
            }

            @Override
            public boolean done() {
                return runs == 3;
            }

            @Override
            public int onEnd() {
                System.out.println("timed ended; restarting sleepy");
                sleepy.restart();
                return 0;
            }
        });
        addBehaviour(sleepy);
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
