package io.concord.core.proto;

import io.concord.core.acl.AclMessage;

/**
 * How a conversation failed, for the {@link Conversations} futures: the responder refused, did not
 * understand, failed, or did not answer in time.
 */
public final class ProtocolException extends Exception {
    /** Why the conversation did not succeed. */
    public enum Reason { REFUSED, NOT_UNDERSTOOD, FAILED, TIMEOUT, NO_PROPOSAL }

    private final Reason reason;
    private final transient AclMessage reply;

    public ProtocolException(Reason reason, AclMessage reply, String detail) {
        super(reason + ": " + detail);
        this.reason = reason;
        this.reply = reply;
    }

    public Reason reason() {
        return reason;
    }

    /** The reply that ended the conversation, or {@code null} on timeout. */
    public AclMessage reply() {
        return reply;
    }
}
