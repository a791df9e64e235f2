import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.ContractNetInitiator;

import java.util.Vector;

/** Rejects every proposal: which handlers run after handleAllResponses, and whether the protocol ends. */
public class Manager extends Agent {
    @Override
    protected void setup() {
        ACLMessage cfp = new ACLMessage(ACLMessage.CFP);
        cfp.addReceiver(new AID("p1", AID.ISLOCALNAME));
        cfp.addReceiver(new AID("p2", AID.ISLOCALNAME));
        cfp.setProtocol(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET);
        cfp.setContent("task");
        addBehaviour(new ContractNetInitiator(this, cfp) {
            @Override
            protected void handleAllResponses(Vector responses, Vector acceptances) {
                for (Object o : responses) {
                    ACLMessage reject = ((ACLMessage) o).createReply();
                    reject.setPerformative(ACLMessage.REJECT_PROPOSAL);
                    acceptances.add(reject);
                }
                System.out.println("rejecting " + acceptances.size());
            }

            @Override
            protected void handleAllResultNotifications(Vector notifications) {
                System.out.println("result notifications " + notifications.size());
            }

            @Override
            public int onEnd() {
                System.out.println("contract net over");
                myAgent.doDelete();
                return 0;
            }
        });
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
