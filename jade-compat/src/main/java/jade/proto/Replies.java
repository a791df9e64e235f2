package jade.proto;

import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;

/** What the responders do to every reply they send, and how a handler's exception becomes one. */
final class Replies {
    private Replies() {
    }

    /** Fills what the handler left unset from the message it answers: receiver, conversation, protocol, in-reply-to. */
    static ACLMessage complete(ACLMessage reply, ACLMessage to) {
        if (!reply.getAllReceiver().hasNext()) {
            jade.util.leap.Iterator rt = to.getAllReplyTo();
            if (rt.hasNext()) {
                while (rt.hasNext()) {
                    reply.addReceiver((AID) rt.next());
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
        return reply;
    }

    /** The reply a handler's FIPA exception stands for: its own message if it carries one, else a reply with its text. */
    static ACLMessage fromException(FIPAException e, int performative, ACLMessage to) {
        ACLMessage carried = e.getACLMessage();
        if (carried != null && carried.getPerformative() == performative) {
            return carried;
        }
        ACLMessage r = to.createReply();
        r.setPerformative(performative);
        r.setContent(e.getMessage());
        return r;
    }

    /** A responder's handler: its reply to a message (or null), or the FIPA exception that stands for one. */
    interface Handler {
        ACLMessage reply() throws FIPAException;
    }

    /**
     * What the handler replies to {@code to}; if it throws a {@link NotUnderstoodException},
     * {@link RefuseException} or {@link FailureException} whose performative (NOT_UNDERSTOOD,
     * REFUSE, FAILURE) is one of {@code mapped}, the reply that exception stands for (see
     * {@link #fromException}). Any other exception goes on to the caller as it came.
     */
    static ACLMessage answer(ACLMessage to, Handler handler, int... mapped) {
        try {
            return handler.reply();
        } catch (FIPAException e) {
            int performative = e instanceof NotUnderstoodException ? ACLMessage.NOT_UNDERSTOOD
                    : e instanceof RefuseException ? ACLMessage.REFUSE
                    : e instanceof FailureException ? ACLMessage.FAILURE : -1;
            for (int p : mapped) {
                if (p == performative) {
                    return fromException(e, performative, to);
                }
            }
            throw Replies.<RuntimeException>rethrow(e);
        }
    }

    /** Sends the reply, completed from the message it answers (see {@link #complete}); nothing if it is null. */
    static void send(Agent agent, ACLMessage reply, ACLMessage to) {
        if (reply != null) {
            agent.send(complete(reply, to));
        }
    }

    /** Throws a checked exception the handler threw although its signature does not say so, unchanged. */
    @SuppressWarnings("unchecked")
    private static <T extends Throwable> T rethrow(Throwable t) throws T {
        throw (T) t;
    }
}
