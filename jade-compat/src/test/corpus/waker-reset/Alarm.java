import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.core.behaviours.TickerBehaviour;
import jade.core.behaviours.WakerBehaviour;

import java.util.Date;

/** A waker stopped before it wakes, one woken at a date, one reset to wake again, a ticker reset to a new period. */
public class Alarm extends Agent {
    @Override
    protected void setup() {
        final WakerBehaviour never = new WakerBehaviour(this, 10_000) {
            @Override
            protected void onWake() {
                System.out.println("never should not wake");
            }

            @Override
            public int onEnd() {
                System.out.println("never ended without waking");
                return 0;
            }
        };
        addBehaviour(never);
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                never.stop();
            }
        });
        addBehaviour(new WakerBehaviour(this, new Date(System.currentTimeMillis() + 50)) {
            private int wakes;

            @Override
            protected void onWake() {
                wakes++;
                System.out.println("dated waker woke, time " + wakes);
                if (wakes == 1) {
                    reset(40);
                    myAgent.addBehaviour(this);
                } else {
                    myAgent.addBehaviour(ticker());
                }
            }
        });
    }

    private TickerBehaviour ticker() {
        return new TickerBehaviour(this, 20) {
            private boolean wasReset;

            @Override
            protected void onTick() {
                System.out.println("tick " + getTickCount() + " period " + getPeriod());
                if (getTickCount() == 2 && !wasReset) {
                    wasReset = true;
                    reset(35);
                } else if (getTickCount() == 2) {
                    myAgent.doDelete();
                }
            }
        };
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
