import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.ACLMessage;

/** Asks the agent its first argument names (with a space) and prints the answer. */
public class Traveller extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new OneShotBehaviour(this) {
            @Override
            public void action() {
                AID timetable = new AID((String) getArguments()[0], AID.ISLOCALNAME);
                ACLMessage q = new ACLMessage(ACLMessage.QUERY_REF);
                q.addReceiver(timetable);
                q.setContent("Lyon");
                myAgent.send(q);
                ACLMessage a = myAgent.blockingReceive();
                System.out.println("[" + myAgent.getLocalName() + "] heard from [" + a.getSender().getLocalName() + "]: " + a.getContent()
                        + ", same AID: " + a.getSender().equals(timetable));
                myAgent.doDelete();
            }
        });
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
