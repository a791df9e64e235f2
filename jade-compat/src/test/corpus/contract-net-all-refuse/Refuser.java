import jade.core.Agent;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.ContractNetResponder;

/** Refuses every CFP, written with the older prepareResponse name; reports each session's end. */
public class Refuser extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new ContractNetResponder(this, ContractNetResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET)) {
            @Override
            protected ACLMessage prepareResponse(ACLMessage cfp) {
                ACLMessage r = cfp.createReply();
                r.setPerformative(ACLMessage.REFUSE);
                r.setContent("no thanks");
                return r;
            }
        });
    }
}
