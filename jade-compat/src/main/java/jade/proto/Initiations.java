package jade.proto;

import io.concord.jadecompat.internal.Engine;
import jade.core.AID;
import jade.core.behaviours.Behaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Vector;
import java.util.function.Consumer;

/**
 * What every initiator does with its conversation, whatever the protocol: sends one copy of each
 * initiation to each of its receivers under one conversation id and a reply-with of its own (one
 * {@link Session} a copy), takes the earliest {@code :reply-by} as the deadline, finds the session
 * a reply belongs to, and receives the conversation's messages until that deadline. The initiator
 * holds one in a private field and keeps the protocol: which answer moves a session where, and
 * which handler it calls.
 */
@SuppressWarnings("rawtypes")
final class Initiations implements java.io.Serializable {
    private static final long serialVersionUID = 1L;

    private final Behaviour owner;
    private final String keyPrefix;
    /** The sessions by reply-with, in the order they were opened. */
    final Map<String, Session> sessions = new LinkedHashMap<>();
    private String conversationId;
    private MessageTemplate template;
    private long deadlineMs = -1;

    /** {@code keyPrefix} starts each reply-with this initiator sets (then its hash code and a number). */
    Initiations(Behaviour owner, String keyPrefix) {
        this.owner = owner;
        this.keyPrefix = keyPrefix;
    }

    /** The conversation's id: the first initiation's own, else one made up; null before anything was sent. */
    String conversationId() {
        return conversationId;
    }

    /**
     * Sends each initiation (null: none) to each of its receivers, one copy and one session a
     * receiver, all in one conversation, and from now on receives that conversation's messages.
     */
    void send(Vector initiations) {
        int n = 0;
        for (Object o : initiations == null ? new Vector() : initiations) {
            ACLMessage m = (ACLMessage) o;
            if (conversationId == null) {
                conversationId = m.getConversationId() != null ? m.getConversationId()
                        : "C" + owner.hashCode() + "_" + Engine.nowMs();
            }
            if (m.getReplyByDate() != null) {
                deadlineMs = deadlineMs < 0 ? m.getReplyByDate().getTime() : Math.min(deadlineMs, m.getReplyByDate().getTime());
            }
            for (jade.util.leap.Iterator it = m.getAllReceiver(); it.hasNext(); ) {
                AID r = (AID) it.next();
                ACLMessage copy = (ACLMessage) m.clone();
                copy.clearAllReceiver();
                copy.addReceiver(r);
                copy.setConversationId(conversationId);
                String key = keyPrefix + owner.hashCode() + "_" + (n++);
                copy.setReplyWith(key);
                sessions.put(key, new Session(key, r));
                owner.getAgent().send(copy);
            }
        }
        String cid = conversationId;
        template = new MessageTemplate(msg -> cid != null && cid.equals(msg.getConversationId()));
    }

    /**
     * The session a reply belongs to: the one its in-reply-to names; if none (or, with
     * {@code redirectEnded}, if that one has ended), the first open session with its sender;
     * failing that, what the in-reply-to named (possibly null).
     */
    Session sessionOf(ACLMessage reply, boolean redirectEnded) {
        Session s = reply.getInReplyTo() == null ? null : sessions.get(reply.getInReplyTo());
        if (s == null || (redirectEnded && s.state == Session.DONE)) {
            for (Session x : sessions.values()) {
                if (x.state != Session.DONE && x.receiver.equals(reply.getSender())) {
                    return x;
                }
            }
        }
        return s;
    }

    /** No session is still waiting for its first answer. */
    boolean allAnswered() {
        for (Session s : sessions.values()) {
            if (s.state == Session.SENT) {
                return false;
            }
        }
        return true;
    }

    /** Every session has ended. */
    boolean allDone() {
        for (Session s : sessions.values()) {
            if (s.state != Session.DONE) {
                return false;
            }
        }
        return true;
    }

    /**
     * One step of the owner's action: the conversation's next message is put in the data store
     * under {@code replyKey} and given to {@code onReply}; if there is none, {@code onTimeout} runs
     * when the deadline is watched and has passed, else the owner blocks until a message comes (or
     * the watched deadline).
     */
    void receive(String replyKey, boolean watchDeadline, Consumer<ACLMessage> onReply, Runnable onTimeout) {
        ACLMessage reply = owner.getAgent().receive(template);
        if (reply != null) {
            owner.getDataStore().put(replyKey, reply);
            onReply.accept(reply);
            return;
        }
        if (watchDeadline && deadlineMs >= 0) {
            long left = deadlineMs - Engine.nowMs();
            if (left <= 0) {
                onTimeout.run();
                return;
            }
            owner.block(left);
        } else {
            owner.block();
        }
    }

    /** Forgets everything, for a new start. */
    void clear() {
        sessions.clear();
        conversationId = null;
        template = null;
        deadlineMs = -1;
    }
}
