package jade.proto;

import jade.core.AID;
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
}
