import jade.core.Agent;
import jade.core.behaviours.DataStore;
import jade.core.behaviours.FSMBehaviour;
import jade.core.behaviours.OneShotBehaviour;
import jade.core.behaviours.SimpleBehaviour;

/** FSM states passing a value through a shared DataStore; a state reset on the way back with toBeReset. */
public class Machine extends Agent {
    @Override
    protected void setup() {
        final DataStore ds = new DataStore();
        ds.put("count", Integer.valueOf(0));
        FSMBehaviour fsm = new FSMBehaviour(this) {
            @Override
            public int onEnd() {
                System.out.println("machine stopped with count " + getDataStore().get("count"));
                myAgent.doDelete();
                return 0;
            }
        };
        fsm.setDataStore(ds);
        OneShotBehaviour inc = new OneShotBehaviour(this) {
            @Override
            public void action() {
                int c = (Integer) getDataStore().get("count") + 1;
                getDataStore().put("count", Integer.valueOf(c));
                System.out.println("increment to " + c);
            }

            @Override
            public int onEnd() {
                return (Integer) getDataStore().get("count") < 3 ? 0 : 1;
            }
        };
        inc.setDataStore(ds);
        SimpleBehaviour twoSteps = new SimpleBehaviour(this) {
            private int steps;

            @Override
            public void onStart() {
                System.out.println("two-steps starts");
            }

            @Override
            public void action() {
                steps++;
                System.out.println("two-steps step " + steps);
            }

            @Override
            public boolean done() {
                return steps == 2;
            }

            @Override
            public void reset() {
                super.reset();
                steps = 0;
            }
        };
        OneShotBehaviour end = new OneShotBehaviour(this) {
            @Override
            public void action() {
                System.out.println("final state");
            }
        };
        fsm.registerFirstState(inc, "INC");
        fsm.registerState(twoSteps, "TWO");
        fsm.registerLastState(end, "END");
        fsm.registerTransition("INC", "TWO", 0);
        fsm.registerTransition("INC", "END", 1);
        fsm.registerDefaultTransition("TWO", "INC", new String[] {"TWO"});
        addBehaviour(fsm);
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
