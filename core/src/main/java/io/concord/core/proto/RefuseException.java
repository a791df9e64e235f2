package io.concord.core.proto;

import io.concord.core.acl.Performative;

/** Answers a request with REFUSE; the message is the reply's content. */
public class RefuseException extends FipaException {
    public RefuseException(String content) {
        super(Performative.REFUSE, content);
    }
}
