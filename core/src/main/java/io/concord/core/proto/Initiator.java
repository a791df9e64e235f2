package io.concord.core.proto;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Behaviour;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What the initiator side of every FIPA protocol shares: one conversation, one session per
 * responder, a {@code :reply-by} deadline for the first answers, and a single behaviour that takes
 * the conversation's replies from the mailbox. A reply is matched to its session by
 * {@code :in-reply-to} (so the AMS's FAILURE for an unknown receiver finds it, as in JADE), else
 * by its sender.
 */
abstract class Initiator extends Behaviour {
    /** A responder's progress in the conversation. */
    static final int WAITING_RESPONSE = 0;
    static final int WAITING_RESULT = 1;
    static final int ENDED = 2;

    static final class Session {
        final AID responder;
        int state = WAITING_RESPONSE;
        AclMessage lastReply;

        Session(AID responder) {
            this.responder = responder;
        }
    }

    final Map<AID, Session> sessions = new LinkedHashMap<>();
    /** The first answers (AGREE, REFUSE, PROPOSE, ...) as they came. */
    final List<AclMessage> responses = new ArrayList<>();
    /** Whether the subclass was handed every first answer. */
    boolean responsesReported;
    private final Map<String, Session> byReplyWith = new HashMap<>();
    private final AclMessage initiation;
    private String conversationId;
    private MessageTemplate template;
    private long deadlineNs = -1;
    private boolean finished;

    Initiator(Agent agent, AclMessage initiation) {
        super(agent);
        this.initiation = initiation;
    }

    /** The conversation id (set when the behaviour starts). */
    public String getConversationId() {
        return conversationId;
    }

    /** The message this conversation started from. */
    protected AclMessage getInitiation() {
        return initiation;
    }

    /** A list holding a copy of this message: what each {@code prepare...} sends by default. */
    static List<AclMessage> copyOf(AclMessage m) {
        List<AclMessage> l = new ArrayList<>(1);
        l.add(m.copy());
        return l;
    }

    /** The messages to send; the initiation by default. Override to tailor per responder. */
    abstract List<AclMessage> prepareInitiations(AclMessage initiation);

    /** The protocol name set when the message has none. */
    abstract String defaultProtocol();

    @Override
    public void onStart() {
        conversationId = initiation.getConversationId() != null ? initiation.getConversationId()
                : myAgent.newConversationId();
        template = MessageTemplate.matchConversationId(conversationId);
        sessions.clear();
        byReplyWith.clear();
        responses.clear();
        responsesReported = false;
        finished = false;
        deadlineNs = -1;
        for (AclMessage m : prepareInitiations(initiation)) {
            sendToEach(m, true);
        }
        if (sessions.isEmpty()) {
            onAllEnded();
        }
    }

    /** Sends one copy per receiver, each with its own reply-with; opens sessions if asked. */
    void sendToEach(AclMessage m, boolean openSessions) {
        m.setConversationId(conversationId);
        if (m.getProtocol() == null) {
            m.setProtocol(defaultProtocol());
        }
        if (openSessions && m.hasReplyBy()) {
            long d = Replies.replyByDeadlineNs(myAgent, m);
            deadlineNs = deadlineNs < 0 ? d : Math.max(deadlineNs, d);
        }
        for (AID r : new ArrayList<>(m.getReceivers())) {
            AclMessage copy = m.copy();
            copy.clearAllReceiver();
            copy.addReceiver(r);
            copy.setReplyWith(myAgent.newReplyWith());
            Session s = openSessions ? new Session(r) : sessions.get(r);
            if (openSessions) {
                sessions.put(r, s);
            }
            if (s != null) {
                byReplyWith.put(copy.getReplyWith(), s);
            }
            myAgent.send(copy);
        }
    }

    /** The current phase has no deadline. */
    void clearDeadline() {
        deadlineNs = -1;
    }

    /** Moves the current phase's deadline to {@code ms} from now, if it is sooner; a phase with no deadline keeps none. */
    void postponeDeadline(long ms) {
        if (deadlineNs >= 0) {
            deadlineNs = Math.max(deadlineNs, myAgent.runtime().nowNs() + ms * 1_000_000);
        }
    }

    /** Sets a new deadline for the current phase, from a message's {@code :reply-by}. */
    void deadlineFrom(AclMessage m) {
        deadlineNs = m.hasReplyBy() ? Replies.replyByDeadlineNs(myAgent, m) : -1;
    }

    @Override
    public void action() {
        if (finished) {
            return;
        }
        AclMessage m = myAgent.receive(template);
        if (m != null) {
            Session s = m.getInReplyTo() == null ? null : byReplyWith.get(m.getInReplyTo());
            if (s == null && m.getSender() != null) {
                s = sessions.get(m.getSender());
            }
            if (s == null || s.state == ENDED) {
                handleOutOfSequence(m);
            } else {
                s.lastReply = m;
                onReply(s, m);
            }
            progress();
            return;
        }
        if (deadlineNs >= 0) {
            long now = myAgent.runtime().nowNs();
            if (now >= deadlineNs) {
                deadlineNs = -1;
                onTimeout();
                progress();
                return;
            }
            block((deadlineNs - now + 999_999) / 1_000_000L);
        } else {
            block();
        }
    }

    abstract void onReply(Session s, AclMessage m);

    /** The deadline of the current phase passed. */
    abstract void onTimeout();

    /** Called after every reply and timeout: moves phases, ends the conversation when all ended. */
    abstract void progress();

    /** Every session has ended: called once. */
    void onAllEnded() {
        finished = true;
    }

    boolean all(int state) {
        for (Session s : sessions.values()) {
            if (s.state != state) {
                return false;
            }
        }
        return true;
    }

    boolean none(int state) {
        for (Session s : sessions.values()) {
            if (s.state == state) {
                return false;
            }
        }
        return true;
    }

    /** A reply that fits no session or comes out of order. */
    protected void handleOutOfSequence(AclMessage msg) {
    }

    @Override
    public boolean done() {
        return finished;
    }

    @Override
    public void reset() {
        super.reset();
        sessions.clear();
        byReplyWith.clear();
        finished = false;
    }
}
