package jade.domain;

import io.concord.jadecompat.internal.Engine;
import jade.core.Agent;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/** JADE's base of the FIPA services' helpers: a synchronous FIPA-request to the AMS, the DF or any agent. */
public class FIPAService {
    public FIPAService() {
    }

    /** As {@link #doFipaRequestClient(Agent, ACLMessage, long)} with no time limit. */
    public static ACLMessage doFipaRequestClient(Agent a, ACLMessage request) throws FIPAException {
        return doFipaRequestClient(a, request, 0);
    }

    /**
     * Sends the request (a conversation id and reply-with are set if missing) and waits, on the
     * calling agent's thread, for its result: returns the INFORM (an AGREE before it is passed
     * over); a REFUSE, FAILURE or NOT_UNDERSTOOD is thrown as a {@link RefuseException},
     * {@link FailureException} or {@link NotUnderstoodException} carrying it; null if
     * {@code timeout} ms (0: no limit) pass first.
     */
    public static ACLMessage doFipaRequestClient(Agent a, ACLMessage request, long timeout) throws FIPAException {
        ACLMessage req = (ACLMessage) request.clone();
        String stamp = a.getLocalName() + Engine.nowMs() + "_" + System.identityHashCode(req);
        if (req.getConversationId() == null) {
            req.setConversationId("conv" + stamp);
        }
        if (req.getReplyWith() == null) {
            req.setReplyWith("rw" + stamp);
        }
        if (req.getProtocol() == null) {
            req.setProtocol(FIPANames.InteractionProtocol.FIPA_REQUEST);
        }
        MessageTemplate answers = MessageTemplate.and(MessageTemplate.MatchConversationId(req.getConversationId()),
                MessageTemplate.MatchInReplyTo(req.getReplyWith()));
        a.send(req);
        long deadline = timeout > 0 ? Engine.nowMs() + timeout : Long.MAX_VALUE;
        while (true) {
            long left = deadline - Engine.nowMs();
            if (timeout > 0 && left <= 0) {
                return null;
            }
            ACLMessage reply = a.blockingReceive(answers, timeout > 0 ? left : 0);
            if (reply == null) {
                return null;
            }
            switch (reply.getPerformative()) {
                case ACLMessage.AGREE:
                    continue;
                case ACLMessage.INFORM:
                    return reply;
                case ACLMessage.REFUSE:
                    throw new RefuseException(reply);
                case ACLMessage.FAILURE:
                    throw new FailureException(reply);
                case ACLMessage.NOT_UNDERSTOOD:
                    throw new NotUnderstoodException(reply);
                default:
                    throw new FIPAException(reply);
            }
        }
    }
}
