package io.concord.core.proto;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;

/**
 * The responder of FIPA-Request and FIPA-Query (JADE's {@code AchieveREResponder}). For each
 * matching request: {@link #handleRequest} answers AGREE, REFUSE (throw {@link RefuseException}),
 * NOT-UNDERSTOOD, or directly the result; after AGREE or no answer,
 * {@link #prepareResultNotification} gives INFORM or FAILURE. Conversation id, in-reply-to,
 * protocol and receiver are filled in when left out.
 */
public class AchieveREResponder extends CyclicBehaviour {
    private final MessageTemplate template;

    public AchieveREResponder(Agent agent, MessageTemplate template) {
        super(agent);
        this.template = template;
    }

    /** Requests of the given protocol: REQUEST for fipa-request, QUERY-IF/QUERY-REF for fipa-query. */
    public static MessageTemplate createMessageTemplate(String protocol) {
        MessageTemplate byProtocol = MessageTemplate.matchProtocol(protocol);
        if (FipaProtocols.QUERY.equals(protocol)) {
            return byProtocol.and(MessageTemplate.matchPerformative(Performative.QUERY_IF)
                    .or(MessageTemplate.matchPerformative(Performative.QUERY_REF)));
        }
        if (FipaProtocols.REQUEST.equals(protocol)) {
            return byProtocol.and(MessageTemplate.matchPerformative(Performative.REQUEST));
        }
        return byProtocol;
    }

    @Override
    public void action() {
        AclMessage request = myAgent.receive(template);
        if (request == null) {
            block();
            return;
        }
        AclMessage response;
        try {
            response = handleRequest(request);
        } catch (FipaException e) {
            response = e.toReply(request);
        }
        if (response != null) {
            Replies.complete(response, request);
            myAgent.send(response);
        }
        if (response == null || response.getPerformative() == Performative.AGREE) {
            AclMessage result;
            try {
                result = prepareResultNotification(request, response);
            } catch (FailureException e) {
                result = e.toReply(request);
            }
            if (result != null) {
                Replies.complete(result, request);
                myAgent.send(result);
            }
        }
    }

    /**
     * The first answer to a request: AGREE, an INFORM that is already the result, or {@code null}
     * to go straight to the result. Throw {@link RefuseException} or {@link NotUnderstoodException}
     * to answer so; a {@link FailureException} here becomes an immediate FAILURE.
     */
    protected AclMessage handleRequest(AclMessage request) throws FipaException {
        return null;
    }

    /** The result: INFORM, or throw {@link FailureException}. */
    protected AclMessage prepareResultNotification(AclMessage request, AclMessage response) throws FailureException {
        return null;
    }
}
