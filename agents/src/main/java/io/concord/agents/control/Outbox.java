package io.concord.agents.control;

import io.concord.core.acl.AclMessage;

import java.util.concurrent.CompletableFuture;

/** How a part of the control agent speaks: through the agent's asks and its send, or a test's list. */
interface Outbox {
    /** Sends a message that needs no answer. */
    void send(AclMessage m);

    /** Sends a request and completes with the final answer, or null if none came within the time. */
    CompletableFuture<AclMessage> ask(AclMessage request, long timeoutMs);
}
