import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;

import java.util.concurrent.CountDownLatch;

/** Takes objects from the program's main thread (O2A) in a cyclic behaviour; restarted by each new object. */
public class Worker extends Agent {
    final CountDownLatch ready = new CountDownLatch(1);
    private int done;

    @Override
    protected void setup() {
        setEnabledO2ACommunication(true, 0);
        System.out.println("worker ready, o2a object now: " + getO2AObject());
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                Object o = myAgent.getO2AObject();
                if (o == null) {
                    block();
                    return;
                }
                if ("stop".equals(o)) {
                    System.out.println("worker stops after " + done + " jobs");
                    myAgent.doDelete();
                    return;
                }
                done++;
                System.out.println("worker did " + o);
            }
        });
        ready.countDown();
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
