import jade.core.Agent;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.ContractNetResponder;

/** A contract-net responder: proposes its price, or refuses; says "rejected" back to the buyer when rejected. */
public class Seller extends Agent {
    @Override
    protected void setup() {
        final String price = (String) getArguments()[0];
        addBehaviour(new ContractNetResponder(this, ContractNetResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET)) {
            @Override
            protected ACLMessage handleCfp(ACLMessage cfp) throws RefuseException, FailureException, NotUnderstoodException {
                if (price.equals("none")) {
                    throw new RefuseException("sold out");
                }
                ACLMessage propose = cfp.createReply();
                propose.setPerformative(ACLMessage.PROPOSE);
                propose.setContent(price);
                return propose;
            }

            @Override
            protected ACLMessage handleAcceptProposal(ACLMessage cfp, ACLMessage propose, ACLMessage accept) throws FailureException {
                ACLMessage inform = accept.createReply();
                inform.setPerformative(ACLMessage.INFORM);
                inform.setContent("sold " + cfp.getContent() + " at " + propose.getContent());
                return inform;
            }

            @Override
            protected void handleRejectProposal(ACLMessage cfp, ACLMessage propose, ACLMessage reject) {
                ACLMessage note = reject.createReply();
                note.setPerformative(ACLMessage.CONFIRM);
                note.setConversationId("rejections");
                note.setContent("rejected at " + propose.getContent());
                myAgent.send(note);
            }
        });
    }
}
