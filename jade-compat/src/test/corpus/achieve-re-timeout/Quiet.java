import jade.core.Agent;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.AchieveREResponder;

/** Answers a request with an INFORM, or (argument "silent") never answers. */
public class Quiet extends Agent {
    @Override
    protected void setup() {
        final boolean silent = "silent".equals(getArguments()[0]);
        addBehaviour(new AchieveREResponder(this, AchieveREResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_REQUEST)) {
            @Override
            protected ACLMessage prepareResponse(ACLMessage request) throws jade.domain.FIPAAgentManagement.NotUnderstoodException,
                    jade.domain.FIPAAgentManagement.RefuseException {
                // The silent one says nothing at all, so that what is printed does not depend on which
                // responder runs first; the quick one keeps the default, which prints before it answers.
                return silent ? null : super.prepareResponse(request);
            }

            @Override
            protected ACLMessage prepareResultNotification(ACLMessage request, ACLMessage response) {
                if (silent) {
                    return null;
                }
                ACLMessage r = request.createReply();
                r.setPerformative(ACLMessage.INFORM);
                r.setContent("here");
                return r;
            }
        });
    }
}
