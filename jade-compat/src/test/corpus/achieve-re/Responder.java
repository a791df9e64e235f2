import jade.core.Agent;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.proto.AchieveREResponder;

/** A FIPA-request responder whose answer depends on its role (its argument). */
public class Responder extends Agent {
    @Override
    protected void setup() {
        final String role = (String) getArguments()[0];
        MessageTemplate t = AchieveREResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_REQUEST);
        addBehaviour(new AchieveREResponder(this, t) {
            @Override
            protected ACLMessage prepareResponse(ACLMessage request) throws NotUnderstoodException, RefuseException {
                if (role.equals("refusing")) {
                    throw new RefuseException("busy");
                }
                if (role.equals("puzzled")) {
                    throw new NotUnderstoodException("what is " + request.getContent());
                }
                if (role.equals("direct")) {
                    return null;
                }
                ACLMessage agree = request.createReply();
                agree.setPerformative(ACLMessage.AGREE);
                return agree;
            }

            @Override
            protected ACLMessage prepareResultNotification(ACLMessage request, ACLMessage response) throws FailureException {
                if (role.equals("failing")) {
                    throw new FailureException("broke down");
                }
                ACLMessage inform = request.createReply();
                inform.setPerformative(ACLMessage.INFORM);
                inform.setContent("done " + request.getContent() + (response == null ? " without agree" : " after agree"));
                return inform;
            }
        });
    }
}
