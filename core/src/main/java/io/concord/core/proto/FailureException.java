package io.concord.core.proto;

import io.concord.core.acl.Performative;

/** Answers a request with FAILURE; the message is the reply's content. */
public class FailureException extends FipaException {
    public FailureException(String content) {
        super(Performative.FAILURE, content);
    }
}
