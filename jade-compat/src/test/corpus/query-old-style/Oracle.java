import jade.core.Agent;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.AchieveREResponder;

/** A fipa-query responder written the older way: handleRequest answers at once with the INFORM. */
public class Oracle extends Agent {
    @Override
    protected void setup() {
        addBehaviour(new AchieveREResponder(this, AchieveREResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_QUERY)) {
            @Override
            protected ACLMessage handleRequest(ACLMessage request) throws NotUnderstoodException, RefuseException {
                ACLMessage reply = request.createReply();
                if (request.getPerformative() == ACLMessage.QUERY_IF) {
                    reply.setPerformative(ACLMessage.INFORM);
                    reply.setContent("yes: " + request.getContent());
                } else {
                    reply.setPerformative(ACLMessage.REFUSE);
                    reply.setContent("no refs");
                }
                return reply;
            }
        });
    }
}
