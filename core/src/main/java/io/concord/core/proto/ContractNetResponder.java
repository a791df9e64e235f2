package io.concord.core.proto;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The responder of FIPA Contract Net (JADE's {@code ContractNetResponder}), serving any number of
 * CFP sessions at once: {@link #handleCfp} answers PROPOSE or REFUSE; then
 * {@link #handleAcceptProposal} gives the INFORM (or throws {@link FailureException}), or
 * {@link #handleRejectProposal} is told. Open sessions are bounded; the oldest are forgotten first.
 */
public class ContractNetResponder extends CyclicBehaviour {
    /** Open proposals kept at most. */
    public static final int MAX_OPEN_SESSIONS = 10_000;

    private record Session(AclMessage cfp, AclMessage propose) {
    }

    private final MessageTemplate cfpTemplate;
    private final Map<String, Session> open = new LinkedHashMap<>(16, 0.75f, false) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Session> eldest) {
            return size() > MAX_OPEN_SESSIONS;
        }
    };
    private final MessageTemplate template;

    public ContractNetResponder(Agent agent, MessageTemplate cfpTemplate) {
        super(agent);
        this.cfpTemplate = cfpTemplate;
        this.template = m -> cfpTemplate.match(m) || ((m.getPerformative() == Performative.ACCEPT_PROPOSAL
                || m.getPerformative() == Performative.REJECT_PROPOSAL) && open.containsKey(Replies.sessionKey(m)));
    }

    /** CFPs of the given protocol. */
    public static MessageTemplate createMessageTemplate(String protocol) {
        return MessageTemplate.matchProtocol(protocol).and(MessageTemplate.matchPerformative(Performative.CFP));
    }


    @Override
    public void action() {
        AclMessage m = myAgent.receive(template);
        if (m == null) {
            block();
            return;
        }
        if (m.getPerformative() == Performative.CFP && cfpTemplate.match(m)) {
            AclMessage reply;
            try {
                reply = handleCfp(m);
            } catch (FipaException e) {
                reply = e.toReply(m);
            }
            if (reply != null) {
                Replies.complete(reply, m);
                if (reply.getPerformative() == Performative.PROPOSE) {
                    open.put(Replies.sessionKey(m), new Session(m, reply));
                }
                myAgent.send(reply);
            }
            return;
        }
        Session s = open.remove(Replies.sessionKey(m));
        if (s == null) {
            return;
        }
        if (m.getPerformative() == Performative.ACCEPT_PROPOSAL) {
            AclMessage result;
            try {
                result = handleAcceptProposal(s.cfp(), s.propose(), m);
            } catch (FailureException e) {
                result = e.toReply(m);
            }
            if (result != null) {
                Replies.complete(result, m);
                myAgent.send(result);
            }
        } else {
            handleRejectProposal(s.cfp(), s.propose(), m);
        }
    }

    /**
     * Answers a CFP later: for a responder whose {@code handleCfp} returned {@code null} because
     * it must first ask others (a planner, a stock check). Completes {@code reply} (a PROPOSE or a
     * REFUSE) as the reply to the CFP and sends it; a PROPOSE opens the session, so that the
     * ACCEPT-PROPOSAL or REJECT-PROPOSAL comes back to this responder. Call on the agent's loop.
     */
    public final void respond(AclMessage cfp, AclMessage reply) {
        Replies.complete(reply, cfp);
        if (reply.getPerformative() == Performative.PROPOSE) {
            open.put(Replies.sessionKey(cfp), new Session(cfp, reply));
        }
        myAgent.send(reply);
        restart();
    }

    /** Answers a CFP with PROPOSE, or throws {@link RefuseException}; {@code null} sends nothing (see {@link #respond}). */
    protected AclMessage handleCfp(AclMessage cfp) throws RefuseException, FailureException, NotUnderstoodException {
        throw new RefuseException("not implemented");
    }

    /** The proposal was accepted: do the work and return INFORM, or throw {@link FailureException}. */
    protected AclMessage handleAcceptProposal(AclMessage cfp, AclMessage propose, AclMessage accept)
            throws FailureException {
        return null;
    }

    /** The proposal was rejected. */
    protected void handleRejectProposal(AclMessage cfp, AclMessage propose, AclMessage reject) {
    }

    /** Proposals waiting for an answer. */
    public int openSessions() {
        return open.size();
    }
}
