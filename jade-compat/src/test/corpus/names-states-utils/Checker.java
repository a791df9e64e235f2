import jade.core.Agent;
import jade.core.ServiceException;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.CyclicBehaviour;
import jade.core.behaviours.FSMBehaviour;
import jade.core.behaviours.OneShotBehaviour;
import jade.core.behaviours.SequentialBehaviour;
import jade.core.behaviours.TickerBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.proto.states.MsgReceiver;
import jade.util.ExtendedProperties;
import jade.util.Logger;
import jade.wrapper.PlatformController;

/**
 * The smaller pieces JADE projects use: behaviour names (by default and as FSM states), an FSM
 * that reads its current state's name, MsgReceiver (a message, then a timeout), the agent's
 * state, the container as a PlatformController, ExtendedProperties, jade.util.Logger, ServiceException.
 */
public class Checker extends Agent {
    private final Logger log = Logger.getMyLogger(getClass().getName());

    /** A named behaviour class, to see JADE's default name for it. */
    static class Stepper extends OneShotBehaviour {
        @Override
        public void action() {
        }
    }

    /** An FSM that says which state it is in, through JADE's protected currentName. */
    class Machine extends FSMBehaviour {
        Machine() {
            super(Checker.this);
        }

        void say(String what) {
            System.out.println("fsm: " + what + " in state " + currentName + ", named " + getState(currentName).getBehaviourName());
        }
    }

    @Override
    protected void setup() {
        System.out.println("default names: " + new Stepper().getBehaviourName() + ", " + new SequentialBehaviour().getBehaviourName()
                + ", " + new TickerBehaviour(this, 1000) {
                    @Override
                    protected void onTick() {
                    }
                }.getBehaviourName());
        System.out.println("state in setup: " + getAgentState().getName() + " " + getAgentState().getValue() + " " + getState());

        PlatformController pc = getContainerController();
        System.out.println("platform controller: " + pc.getName());

        ExtendedProperties p = new ExtendedProperties(new String[] {"port=7001", "host:localhost", "verbose=true", "url=http://${host}:${port}/x"});
        System.out.println("properties: " + p.getIntProperty("port", 0) + " " + p.getProperty("host") + " " + p.getBooleanProperty("verbose", false)
                + " " + p.getBooleanProperty("missing", false) + " " + p.getProperty("url") + " " + p.getIntProperty("host", -1));
        System.out.println("logger: " + log.getName() + " info loggable " + log.isLoggable(Logger.INFO) + ", finest " + log.isLoggable(Logger.FINEST));
        log.log(Logger.FINE, "not shown");
        try {
            throw new ServiceException("no such service", new IllegalStateException("inner"));
        } catch (ServiceException e) {
            System.out.println("service exception: " + e.getMessage().startsWith("no such service") + " nested " + e.getNested().getMessage());
        }

        Machine fsm = new Machine();
        fsm.registerFirstState(new OneShotBehaviour(this) {
            @Override
            public void action() {
                fsm.say("first");
            }
        }, "Start");
        fsm.registerState(new OneShotBehaviour(this) {
            @Override
            public void action() {
                fsm.say("second");
            }
        }, "Middle");
        fsm.registerLastState(new Stepper() {
            @Override
            public void action() {
                fsm.say("last");
                ACLMessage m = new ACLMessage(ACLMessage.INFORM);
                m.addReceiver(getAID());
                m.setConversationId("to-self");
                m.setContent("ping");
                send(m);
            }
        }, "End");
        fsm.registerDefaultTransition("Start", "Middle");
        fsm.registerDefaultTransition("Middle", "End");
        SequentialBehaviour seq = new SequentialBehaviour(this);
        seq.addSubBehaviour(fsm);
        seq.addSubBehaviour(new MsgReceiver(this, MessageTemplate.MatchConversationId("to-self"), MsgReceiver.INFINITE, null, "got") {
            @Override
            protected void handleMessage(ACLMessage msg) {
                System.out.println("receiver got: " + msg.getContent() + ", stored: " + (getDataStore().get("got") == msg));
            }

            @Override
            public int onEnd() {
                int r = super.onEnd();
                System.out.println("receiver ended with " + ACLMessage.getPerformative(r));
                return r;
            }
        });
        seq.addSubBehaviour(new MsgReceiver(this, MessageTemplate.MatchConversationId("never"), System.currentTimeMillis() + 300, null, "late") {
            @Override
            protected void handleMessage(ACLMessage msg) {
                System.out.println("second receiver got " + msg);
            }

            @Override
            public int onEnd() {
                int r = super.onEnd();
                System.out.println("second receiver ended with " + r + " (timeout " + (r == MsgReceiver.TIMEOUT_EXPIRED) + ")");
                return r;
            }
        });
        seq.addSubBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                System.out.println("state in a behaviour: " + myAgent.getAgentState());
                myAgent.doDelete();
            }
        });
        addBehaviour(seq);
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
