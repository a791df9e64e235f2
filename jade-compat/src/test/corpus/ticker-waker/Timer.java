import jade.core.Agent;
import jade.core.behaviours.TickerBehaviour;
import jade.core.behaviours.WakerBehaviour;

/** A ticker that stops itself after three ticks, then a waker (onWake) and one with handleElapsedTimeout. */
public class Timer extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new TickerBehaviour(this, 40) {
            @Override
            protected void onTick() {
                System.out.println("tick " + getTickCount() + " period " + getPeriod());
                if (getTickCount() == 3) {
                    stop();
                    myAgent.addBehaviour(new WakerBehaviour(myAgent, 60) {
                        @Override
                        protected void onWake() {
                            System.out.println("woke after the ticker");
                            myAgent.addBehaviour(new WakerBehaviour(myAgent, 30) {
                                @Override
                                protected void handleElapsedTimeout() {
                                    System.out.println("elapsed timeout handled");
                                    myAgent.doDelete();
                                }
                            });
                        }

                        @Override
                        public int onEnd() {
                            System.out.println("waker ended, done " + done());
                            return 0;
                        }
                    });
                }
            }

            @Override
            public int onEnd() {
                System.out.println("ticker ended after " + getTickCount());
                return 0;
            }
        });
    }

    @Override
    protected void takeDown() {
        System.out.println("bye");
        System.exit(0);
    }
}
