import jade.core.Agent;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.ContractNetResponder;

/** Always proposes; its session ends when the manager rejects it. */
public class Proposer extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new ContractNetResponder(this, ContractNetResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET)) {
            @Override
            protected ACLMessage handleCfp(ACLMessage cfp) throws RefuseException, FailureException, NotUnderstoodException {
                ACLMessage r = cfp.createReply();
                r.setPerformative(ACLMessage.PROPOSE);
                r.setContent("100");
                return r;
            }
        });
    }
}
