package io.concord.core.proto;

import io.concord.core.acl.Performative;

/** Answers a request with NOT-UNDERSTOOD; the message is the reply's content. */
public class NotUnderstoodException extends FipaException {
    public NotUnderstoodException(String content) {
        super(Performative.NOT_UNDERSTOOD, content);
    }
}
