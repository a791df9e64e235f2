import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.AchieveREInitiator;

import java.util.Date;
import java.util.Vector;

/** A request with a reply-by a second ahead to one agent that answers and one that never does. */
public class Asker extends Agent {
    @Override
    protected void setup() {
        ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
        req.addReceiver(new AID("quick", AID.ISLOCALNAME));
        req.addReceiver(new AID("silent", AID.ISLOCALNAME));
        req.setProtocol(FIPANames.InteractionProtocol.FIPA_REQUEST);
        req.setReplyByDate(new Date(System.currentTimeMillis() + 1000));
        req.setContent("anyone?");
        addBehaviour(new AchieveREInitiator(this, req) {
            @Override
            protected void handleInform(ACLMessage inform) {
                System.out.println("inform from " + inform.getSender().getLocalName());
            }

            @Override
            protected void handleAllResponses(Vector responses) {
                System.out.println("all responses " + responses.size());
            }

            @Override
            protected void handleAllResultNotifications(Vector notifications) {
                System.out.println("all result notifications " + notifications.size());
                myAgent.doDelete();
            }
        });
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
