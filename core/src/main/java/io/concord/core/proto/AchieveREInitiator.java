package io.concord.core.proto;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;

import java.util.ArrayList;
import java.util.List;

/**
 * The initiator of FIPA-Request and FIPA-Query (JADE's {@code AchieveREInitiator}): sends the
 * request to each receiver, then reports each answer (AGREE, REFUSE, NOT-UNDERSTOOD) and each
 * result (INFORM, FAILURE). {@code :reply-by} bounds the wait for answers; when it passes,
 * {@link #handleAllResponses} gets what came, and only responders that agreed are waited for.
 */
public class AchieveREInitiator extends Initiator {
    private final List<AclMessage> results = new ArrayList<>();

    public AchieveREInitiator(Agent agent, AclMessage request) {
        super(agent, request);
    }

    @Override
    List<AclMessage> prepareInitiations(AclMessage initiation) {
        return prepareRequests(initiation);
    }

    /** The requests to send; a copy of the given one by default. */
    protected List<AclMessage> prepareRequests(AclMessage request) {
        return copyOf(request);
    }

    @Override
    String defaultProtocol() {
        Performative p = getInitiation().getPerformative();
        return p == Performative.QUERY_IF || p == Performative.QUERY_REF ? FipaProtocols.QUERY : FipaProtocols.REQUEST;
    }

    @Override
    void onReply(Session s, AclMessage m) {
        switch (m.getPerformative()) {
            // A result ends the session whether or not an AGREE came first.
            case INFORM -> endWithResult(s, m, this::handleInform);
            case FAILURE -> endWithResult(s, m, this::handleFailure);
            case AGREE -> firstAnswer(s, m, WAITING_RESULT, this::handleAgree);
            case REFUSE -> firstAnswer(s, m, ENDED, this::handleRefuse);
            case NOT_UNDERSTOOD -> firstAnswer(s, m, ENDED, this::handleNotUnderstood);
            default -> handleOutOfSequence(m);
        }
    }

    private void endWithResult(Session s, AclMessage m, java.util.function.Consumer<AclMessage> handler) {
        s.state = ENDED;
        results.add(m);
        handler.accept(m);
    }

    private void firstAnswer(Session s, AclMessage m, int next, java.util.function.Consumer<AclMessage> handler) {
        if (s.state != WAITING_RESPONSE) {
            handleOutOfSequence(m);
            return;
        }
        s.state = next;
        responses.add(m);
        handler.accept(m);
    }

    @Override
    void onTimeout() {
        for (Session s : sessions.values()) {
            if (s.state == WAITING_RESPONSE) {
                s.state = ENDED;
            }
        }
    }

    @Override
    void progress() {
        if (!responsesReported && none(WAITING_RESPONSE)) {
            responsesReported = true;
            handleAllResponses(new ArrayList<>(responses));
        }
        if (responsesReported && all(ENDED)) {
            handleAllResultNotifications(new ArrayList<>(results));
            onAllEnded();
        }
    }

    @Override
    void onAllEnded() {
        if (sessions.isEmpty() && !responsesReported) {
            responsesReported = true;
            handleAllResponses(List.of());
            handleAllResultNotifications(List.of());
        }
        super.onAllEnded();
    }

    protected void handleAgree(AclMessage agree) {
    }

    protected void handleRefuse(AclMessage refuse) {
    }

    protected void handleNotUnderstood(AclMessage notUnderstood) {
    }

    protected void handleInform(AclMessage inform) {
    }

    protected void handleFailure(AclMessage failure) {
    }

    /** Every first answer has come, or {@code :reply-by} passed. */
    protected void handleAllResponses(List<AclMessage> responses) {
    }

    /** Every result has come; the conversation is over. */
    protected void handleAllResultNotifications(List<AclMessage> resultNotifications) {
    }

    @Override
    public void reset() {
        super.reset();
        results.clear();
    }
}
