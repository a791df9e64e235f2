import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;

/** An agent whose name has a space, as JADE's examples name some ("timetable agent"): answers each question. */
public class Timetable extends Agent {
    @Override
    protected void setup() {
        System.out.println("up: [" + getLocalName() + "] " + getName().startsWith("timetable agent@"));
        addBehaviour(new CyclicBehaviour(this) {
            @Override
            public void action() {
                ACLMessage m = myAgent.receive();
                if (m == null) {
                    block();
                    return;
                }
                System.out.println("[" + myAgent.getLocalName() + "] asked by [" + m.getSender().getLocalName() + "]: " + m.getContent());
                ACLMessage r = m.createReply();
                r.setPerformative(ACLMessage.INFORM);
                r.setContent("the 8:15 to " + m.getContent());
                myAgent.send(r);
            }
        });
    }
}
