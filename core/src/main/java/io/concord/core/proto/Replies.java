package io.concord.core.proto;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;

/** Fills in what a protocol reply must carry when the handler left it out. */
final class Replies {
    private Replies() {
    }

    static void complete(AclMessage reply, AclMessage to) {
        if (reply.getReceivers().isEmpty()) {
            if (!to.getReplyTo().isEmpty()) {
                for (AID a : to.getReplyTo()) {
                    reply.addReceiver(a);
                }
            } else if (to.getSender() != null) {
                reply.addReceiver(to.getSender());
            }
        }
        if (reply.getConversationId() == null) {
            reply.setConversationId(to.getConversationId());
        }
        if (reply.getInReplyTo() == null) {
            reply.setInReplyTo(to.getReplyWith());
        }
        if (reply.getProtocol() == null) {
            reply.setProtocol(to.getProtocol());
        }
    }

    /** Identifies a responder-side session: the conversation and who started it. */
    static String sessionKey(AclMessage m) {
        return m.getConversationId() + "|" + (m.getSender() == null ? "" : m.getSender().name().toLowerCase(java.util.Locale.ROOT));
    }

    /** The loop time (ns) at which the message's {@code :reply-by} passes, or -1 if it has none. */
    static long replyByDeadlineNs(io.concord.core.agent.Agent agent, AclMessage msg) {
        if (!msg.hasReplyBy()) {
            return -1;
        }
        long leftMs = msg.getReplyByEpochMs() - agent.currentTimeMillis();
        return agent.runtime().nowNs() + Math.max(0, leftMs) * 1_000_000L;
    }
}
