import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.UnreadableException;

/** Reads objects back with getContentObject; text content is not an object. */
public class Reader extends Agent {
    private int seen;

    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive();
                if (m == null) {
                    block();
                    return;
                }
                seen++;
                if (m.hasByteSequenceContent()) {
                    try {
                        Object o = m.getContentObject();
                        System.out.println("reader: object " + o.getClass().getSimpleName() + " " + o);
                    } catch (UnreadableException e) {
                        System.out.println("reader: unreadable object");
                    }
                } else {
                    System.out.println("reader: text " + m.getContent());
                    try {
                        m.getContentObject();
                        System.out.println("reader: text read as an object");
                    } catch (UnreadableException e) {
                        System.out.println("reader: text is not an object");
                    }
                }
                if (seen == 3) {
                    myAgent.doDelete();
                }
            }
        });
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
