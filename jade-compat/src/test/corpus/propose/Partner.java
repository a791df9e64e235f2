import jade.core.Agent;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.ProposeResponder;

/** Answers proposals by its role: accept, reject, puzzled (not understood), silent (no answer), chatty (an INFORM). */
public class Partner extends Agent {
    @Override
    protected void setup() {
        String role = (String) getArguments()[0];
        addBehaviour(new ProposeResponder(this, ProposeResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_PROPOSE)) {
            @Override
            protected ACLMessage prepareResponse(ACLMessage propose) throws NotUnderstoodException, RefuseException {
                ACLMessage r = propose.createReply();
                switch (role) {
                    case "accept":
                        r.setPerformative(ACLMessage.ACCEPT_PROPOSAL);
                        r.setContent("deal at " + propose.getContent());
                        return r;
                    case "reject":
                        r.setPerformative(ACLMessage.REJECT_PROPOSAL);
                        r.setContent("too dear");
                        return r;
                    case "puzzled":
                        throw new NotUnderstoodException("what is " + propose.getContent());
                    case "chatty":
                        r.setPerformative(ACLMessage.INFORM);
                        r.setContent("nice weather");
                        return r;
                    default:
                        return null;
                }
            }
        });
    }
}
