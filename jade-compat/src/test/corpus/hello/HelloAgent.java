import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;

/** The first agent of JADE's tutorial: prints its names and arguments in setup, then ends. */
public class HelloAgent extends Agent {
    @Override
    protected void setup() {
        System.out.println("Hello! I am " + getLocalName());
        System.out.println("full name " + getName());
        System.out.println("aid local " + getAID().getLocalName() + " hap " + getAID().getHap());
        Object[] args = getArguments();
        System.out.println("arguments " + (args == null ? "none" : args.length));
        for (Object a : args) {
            System.out.println("argument " + a);
        }
        AID same = new AID("hello", AID.ISLOCALNAME);
        System.out.println("equal to local-name AID " + same.equals(getAID()));
        System.out.println("equal ignoring case " + new AID("HELLO@corpus", AID.ISGUID).equals(getAID()));
        System.out.println("compare " + Integer.signum(new AID("a@corpus", AID.ISGUID).compareTo(new AID("b@corpus", AID.ISGUID))));
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                System.out.println("one-shot ran");
                myAgent.doDelete();
            }
        });
    }

    @Override
    protected void takeDown() {
        System.out.println("takeDown of " + getLocalName());
        System.out.flush();
        System.exit(0);
    }
}
