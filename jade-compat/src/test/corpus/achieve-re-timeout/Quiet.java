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
