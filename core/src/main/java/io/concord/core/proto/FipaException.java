package io.concord.core.proto;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

/**
 * Thrown by a responder's handler to answer with REFUSE, NOT-UNDERSTOOD or FAILURE; the message
 * becomes the reply's content, as in JADE.
 */
public abstract class FipaException extends Exception {
    private final Performative performative;

    protected FipaException(Performative performative, String content) {
        super(content);
        this.performative = performative;
    }

    /** The reply this exception stands for, addressed back to the request's sender. */
    public AclMessage toReply(AclMessage request) {
        AclMessage reply = request.createReply();
        reply.setPerformative(performative);
        reply.setContent(getMessage());
        return reply;
    }
}
