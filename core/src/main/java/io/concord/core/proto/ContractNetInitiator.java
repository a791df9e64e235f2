package io.concord.core.proto;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;

import java.util.ArrayList;
import java.util.List;

/**
 * The initiator of FIPA Contract Net (JADE's {@code ContractNetInitiator}): sends the CFP to every
 * receiver, collects PROPOSE / REFUSE / NOT-UNDERSTOOD until all have answered or the CFP's
 * {@code :reply-by} passes, lets {@link #handleAllResponses} choose (by adding ACCEPT-PROPOSAL and
 * REJECT-PROPOSAL replies to the acceptances), sends those, and collects the winners' INFORM or
 * FAILURE. Proposers that get no acceptance are simply not waited for.
 */
public class ContractNetInitiator extends Initiator {
    private static final int PROPOSED = 3;

    private final List<AclMessage> results = new ArrayList<>();
    private final List<AclMessage> earlyAcceptances = new ArrayList<>();

    public ContractNetInitiator(Agent agent, AclMessage cfp) {
        super(agent, cfp);
    }

    @Override
    List<AclMessage> prepareInitiations(AclMessage initiation) {
        return prepareCfps(initiation);
    }

    /** The CFPs to send; a copy of the given one by default. */
    protected List<AclMessage> prepareCfps(AclMessage cfp) {
        return copyOf(cfp);
    }

    @Override
    String defaultProtocol() {
        return FipaProtocols.CONTRACT_NET;
    }

    @Override
    void onReply(Session s, AclMessage m) {
        Performative p = m.getPerformative();
        if (s.state == WAITING_RESPONSE && p != Performative.INFORM) {
            responses.add(m);
            switch (p) {
                case PROPOSE -> {
                    s.state = PROPOSED;
                    handlePropose(m, earlyAcceptances);
                }
                case REFUSE -> endWith(s, m, this::handleRefuse);
                case NOT_UNDERSTOOD -> endWith(s, m, this::handleNotUnderstood);
                case FAILURE -> endWith(s, m, this::handleFailure);
                default -> {
                    responses.remove(responses.size() - 1);
                    handleOutOfSequence(m);
                }
            }
        } else if (s.state == WAITING_RESULT && (p == Performative.INFORM || p == Performative.FAILURE)) {
            results.add(m);
            endWith(s, m, p == Performative.INFORM ? this::handleInform : this::handleFailure);
        } else {
            handleOutOfSequence(m);
        }
    }

    private static void endWith(Session s, AclMessage m, java.util.function.Consumer<AclMessage> handler) {
        s.state = ENDED;
        handler.accept(m);
    }

    @Override
    void onTimeout() {
        int from = responsesReported ? WAITING_RESULT : WAITING_RESPONSE;
        for (Session s : sessions.values()) {
            if (s.state == from) {
                s.state = ENDED;
            }
        }
    }

    @Override
    void progress() {
        if (!responsesReported && none(WAITING_RESPONSE)) {
            responsesReported = true;
            List<AclMessage> acceptances = new ArrayList<>(earlyAcceptances);
            handleAllResponses(new ArrayList<>(responses), acceptances);
            sendAcceptances(acceptances);
        }
        if (responsesReported && all(ENDED)) {
            handleAllResultNotifications(new ArrayList<>(results));
            onAllEnded();
        }
    }

    private void sendAcceptances(List<AclMessage> acceptances) {
        AclMessage withDeadline = null;
        for (AclMessage a : acceptances) {
            for (AID r : a.getReceivers()) {
                Session s = sessions.get(r);
                if (s != null && s.state == PROPOSED) {
                    s.state = a.getPerformative() == Performative.ACCEPT_PROPOSAL ? WAITING_RESULT : ENDED;
                }
            }
            if (a.getPerformative() == Performative.ACCEPT_PROPOSAL && a.hasReplyBy()) {
                withDeadline = a;
            }
            sendToEach(a, false);
        }
        for (Session s : sessions.values()) {
            if (s.state == PROPOSED) {
                s.state = ENDED;
            }
        }
        if (withDeadline != null) {
            deadlineFrom(withDeadline);
        } else {
            clearDeadline();
        }
    }

    @Override
    void onAllEnded() {
        if (sessions.isEmpty() && !responsesReported) {
            responsesReported = true;
            handleAllResponses(List.of(), new ArrayList<>());
            handleAllResultNotifications(List.of());
        }
        super.onAllEnded();
    }

    /**
     * Gives the accepted responders at least {@code ms} more for their results (one said it is
     * held up: a paused task). Has no effect before the acceptances are sent, or without a deadline.
     * Call on the agent's loop.
     */
    public final void postponeResultDeadline(long ms) {
        if (responsesReported) {
            postponeDeadline(ms);
        }
    }

    /** A proposal; an acceptance or rejection may be added to {@code acceptances} at once. */
    protected void handlePropose(AclMessage propose, List<AclMessage> acceptances) {
    }

    protected void handleRefuse(AclMessage refuse) {
    }

    protected void handleNotUnderstood(AclMessage notUnderstood) {
    }

    protected void handleFailure(AclMessage failure) {
    }

    protected void handleInform(AclMessage inform) {
    }

    /**
     * Every responder answered or the deadline passed: add an ACCEPT-PROPOSAL or REJECT-PROPOSAL
     * (usually {@code propose.createReply()}) to {@code acceptances} for the proposals you choose.
     */
    protected void handleAllResponses(List<AclMessage> responses, List<AclMessage> acceptances) {
    }

    /** Every accepted proposer reported its result; the conversation is over. */
    protected void handleAllResultNotifications(List<AclMessage> resultNotifications) {
    }

    @Override
    public void reset() {
        super.reset();
        results.clear();
        earlyAcceptances.clear();
    }
}
