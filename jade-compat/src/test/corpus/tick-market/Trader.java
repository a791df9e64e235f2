import jade.core.Agent;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.ContractNetResponder;

/** A seller of the market: proposes its base price plus the round (the CFP's content); sells when accepted. */
public class Trader extends Agent {
    @Override
    protected void setup() {
        final int base = Integer.parseInt((String) getArguments()[0]);
        addBehaviour(new ContractNetResponder(this, ContractNetResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET)) {
            @Override
            protected ACLMessage handleCfp(ACLMessage cfp) throws RefuseException, FailureException, NotUnderstoodException {
                int round = Integer.parseInt(cfp.getContent());
                ACLMessage propose = cfp.createReply();
                propose.setPerformative(ACLMessage.PROPOSE);
                // Round 1: s1 13, s2 11, s3 16; round 2: s1 14, s2 13, s3 17.
                propose.setContent(Integer.toString(base + round * (base == 9 ? 2 : 1)));
                return propose;
            }

            @Override
            protected ACLMessage handleAcceptProposal(ACLMessage cfp, ACLMessage propose, ACLMessage accept) {
                ACLMessage inform = accept.createReply();
                inform.setPerformative(ACLMessage.INFORM);
                inform.setContent(propose.getContent());
                return inform;
            }
        });
    }
}
