package io.concord.core.proto;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;

import java.util.ArrayList;
import java.util.List;

/**
 * The initiator of FIPA-Subscribe (JADE's {@code SubscriptionInitiator}): sends SUBSCRIBE, reports
 * AGREE or REFUSE, then every INFORM the responder sends, until the subscription is cancelled
 * ({@link #cancel}), refused or failed. {@code :reply-by} bounds the wait for the first answer.
 */
public class SubscriptionInitiator extends Initiator {

    public SubscriptionInitiator(Agent agent, AclMessage subscribe) {
        super(agent, subscribe);
    }

    @Override
    List<AclMessage> prepareInitiations(AclMessage initiation) {
        return prepareSubscriptions(initiation);
    }

    /** The subscriptions to send; a copy of the given one by default. */
    protected List<AclMessage> prepareSubscriptions(AclMessage subscribe) {
        return copyOf(subscribe);
    }

    @Override
    String defaultProtocol() {
        return FipaProtocols.SUBSCRIBE;
    }

    @Override
    void onReply(Session s, AclMessage m) {
        switch (m.getPerformative()) {
            case AGREE -> {
                if (s.state == WAITING_RESPONSE) {
                    s.state = WAITING_RESULT;
                    responses.add(m);
                    handleAgree(m);
                } else {
                    handleOutOfSequence(m);
                }
            }
            case REFUSE, NOT_UNDERSTOOD -> {
                if (s.state == WAITING_RESPONSE) {
                    s.state = ENDED;
                    responses.add(m);
                    if (m.getPerformative() == Performative.REFUSE) {
                        handleRefuse(m);
                    } else {
                        handleNotUnderstood(m);
                    }
                } else {
                    handleOutOfSequence(m);
                }
            }
            case INFORM -> {
                if (s.state == WAITING_RESPONSE) {
                    s.state = WAITING_RESULT;
                    responses.add(m);
                }
                handleInform(m);
            }
            case FAILURE -> {
                s.state = ENDED;
                handleFailure(m);
            }
            default -> handleOutOfSequence(m);
        }
    }

    /**
     * Cancels the subscription with one responder: sends CANCEL and stops listening to it.
     * Call from the agent's behaviours.
     */
    public void cancel(AID responder, boolean ignoreResponse) {
        Session s = sessions.get(responder);
        if (s == null || s.state == ENDED) {
            return;
        }
        AclMessage cancel = new AclMessage(Performative.CANCEL);
        cancel.addReceiver(responder);
        cancel.setContent(getInitiation().getContent());
        cancel.setLanguage(getInitiation().getLanguage());
        cancel.setOntology(getInitiation().getOntology());
        sendToEach(cancel, false);
        s.state = ENDED;
        progress();
        restart();
    }

    /** Cancels every subscription of this conversation. */
    public void cancelAll() {
        for (AID r : new ArrayList<>(sessions.keySet())) {
            cancel(r, true);
        }
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
        if (all(ENDED) && !done()) {
            onAllEnded();
        }
    }

    protected void handleAgree(AclMessage agree) {
    }

    protected void handleRefuse(AclMessage refuse) {
    }

    protected void handleNotUnderstood(AclMessage notUnderstood) {
    }

    /** A notification; called for every INFORM while the subscription lasts. */
    protected void handleInform(AclMessage inform) {
    }

    protected void handleFailure(AclMessage failure) {
    }

    /** Every responder answered the SUBSCRIBE (or the deadline passed). */
    protected void handleAllResponses(List<AclMessage> responses) {
    }

    @Override
    public void reset() {
        super.reset();
    }
}
