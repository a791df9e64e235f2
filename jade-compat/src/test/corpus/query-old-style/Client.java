import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.SequentialBehaviour;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.AchieveREInitiator;

import java.util.Vector;

/** Two queries one after the other, as AchieveREInitiators inside a SequentialBehaviour; prepareRequests overridden once. */
public class Client extends Agent {
    private ACLMessage query(int perf, String content) {
        ACLMessage q = new ACLMessage(perf);
        q.addReceiver(new AID("oracle", AID.ISLOCALNAME));
        q.setProtocol(FIPANames.InteractionProtocol.FIPA_QUERY);
        q.setContent(content);
        return q;
    }

    @Override
    protected void setup() {
        SequentialBehaviour seq = new SequentialBehaviour(this) {
            @Override
            public int onEnd() {
                System.out.println("both queries over");
                myAgent.doDelete();
                return 0;
            }
        };
        seq.addSubBehaviour(new AchieveREInitiator(this, query(ACLMessage.QUERY_IF, "(is-open shop)")) {
            @Override
            protected Vector prepareRequests(ACLMessage request) {
                System.out.println("preparing " + request.getContent());
                ACLMessage changed = (ACLMessage) request.clone();
                changed.setContent(request.getContent() + " today");
                Vector v = new Vector();
                v.add(changed);
                return v;
            }

            @Override
            protected void handleInform(ACLMessage inform) {
                System.out.println("inform: " + inform.getContent());
            }

            @Override
            protected void handleAllResponses(Vector responses) {
                System.out.println("responses before the result: " + responses.size());
            }
        });
        seq.addSubBehaviour(new AchieveREInitiator(this, query(ACLMessage.QUERY_REF, "(iota ?x (price ?x))")) {
            @Override
            protected void handleRefuse(ACLMessage refuse) {
                System.out.println("refuse: " + refuse.getContent());
            }

            @Override
            protected void handleAllResultNotifications(Vector notifications) {
                System.out.println("result notifications after a refuse: " + notifications.size());
            }
        });
        addBehaviour(seq);
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
