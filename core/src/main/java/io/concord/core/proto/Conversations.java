package io.concord.core.proto;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.MessageTemplate;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.Behaviour;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.function.Function;

/**
 * The FIPA protocols in a modern form: futures and lambdas instead of handler classes. Built on
 * the JADE-style behaviours of this package, so the messages on the wire are the same. Futures
 * complete on the agent's loop; chain on them without blocking it.
 *
 * <pre>{@code
 * Conversations.serve(seller, AchieveREResponder.createMessageTemplate(FipaProtocols.QUERY),
 *         q -> q.createReply().setPerformative(Performative.INFORM).setContent("42"));
 * Conversations.request(buyer, query).thenAccept(inform -> System.out.println(inform.getContent()));
 * }</pre>
 */
public final class Conversations {
    private Conversations() {
    }

    /** Answers a request: return the reply, or throw to REFUSE / NOT-UNDERSTOOD / FAILURE. */
    @FunctionalInterface
    public interface RequestHandler {
        AclMessage handle(AclMessage request) throws FipaException;
    }

    /** Answers a CFP with a PROPOSE (or throws {@link RefuseException}). */
    @FunctionalInterface
    public interface CfpHandler {
        AclMessage propose(AclMessage cfp) throws FipaException;
    }

    /** Does the accepted work and returns the INFORM (or throws {@link FailureException}). */
    @FunctionalInterface
    public interface AcceptHandler {
        AclMessage perform(AclMessage cfp, AclMessage propose, AclMessage accept) throws FailureException;
    }

    /** The winning proposal of a contract net and the winner's result. */
    public record ContractNetOutcome(AclMessage proposal, AclMessage result) {
    }

    /**
     * Sends a REQUEST, QUERY-IF or QUERY-REF to its one receiver.
     *
     * @return completes with the INFORM; fails with a {@link ProtocolException} on REFUSE,
     *         NOT-UNDERSTOOD, FAILURE, or no answer by {@code :reply-by}
     */
    public static CompletableFuture<AclMessage> request(Agent agent, AclMessage request) {
        if (request.getReceivers().size() != 1) {
            throw new IllegalArgumentException("request() takes a message with exactly one receiver, got "
                    + request.getReceivers().size() + "; use AchieveREInitiator for several");
        }
        CompletableFuture<AclMessage> f = new CompletableFuture<>();
        agent.addBehaviour(new AchieveREInitiator(agent, request) {
            @Override
            protected void handleRefuse(AclMessage refuse) {
                f.completeExceptionally(new ProtocolException(ProtocolException.Reason.REFUSED, refuse, refuse.getContent()));
            }

            @Override
            protected void handleNotUnderstood(AclMessage nu) {
                f.completeExceptionally(new ProtocolException(ProtocolException.Reason.NOT_UNDERSTOOD, nu, nu.getContent()));
            }

            @Override
            protected void handleFailure(AclMessage failure) {
                f.completeExceptionally(new ProtocolException(ProtocolException.Reason.FAILED, failure, failure.getContent()));
            }

            @Override
            protected void handleInform(AclMessage inform) {
                f.complete(inform);
            }

            @Override
            protected void handleAllResultNotifications(List<AclMessage> results) {
                if (!f.isDone()) {
                    f.completeExceptionally(new ProtocolException(ProtocolException.Reason.TIMEOUT, null,
                            "no answer from " + request.getReceivers().get(0).name() + " by :reply-by"));
                }
            }
        });
        return f;
    }

    /**
     * Serves requests that the template matches: the handler's reply (INFORM, AGREE, ...) is sent
     * back with conversation id, in-reply-to and protocol filled in; a {@link FipaException} it
     * throws becomes the REFUSE, NOT-UNDERSTOOD or FAILURE reply. A {@code null} reply sends nothing.
     *
     * @return the behaviour, already added to the agent
     */
    public static Behaviour serve(Agent agent, MessageTemplate template, RequestHandler handler) {
        Behaviour b = new AchieveREResponder(agent, template) {
            @Override
            protected AclMessage handleRequest(AclMessage request) throws FipaException {
                return handler.handle(request);
            }
        };
        agent.addBehaviour(b);
        return b;
    }

    /**
     * Runs a contract net: sends the CFP, gives the proposals to {@code chooseWinner} (return one,
     * or {@code null} for none), accepts it and rejects the others.
     *
     * @return completes with the winner's proposal and INFORM; fails with a
     *         {@link ProtocolException} if there was no proposal, none was chosen, or the winner failed
     */
    public static CompletableFuture<ContractNetOutcome> contractNet(Agent agent, AclMessage cfp,
                                                                    Function<List<AclMessage>, AclMessage> chooseWinner) {
        CompletableFuture<ContractNetOutcome> f = new CompletableFuture<>();
        agent.addBehaviour(new ContractNetInitiator(agent, cfp) {
            private AclMessage winner;

            @Override
            protected void handleAllResponses(List<AclMessage> responses, List<AclMessage> acceptances) {
                List<AclMessage> proposals = responses.stream()
                        .filter(r -> r.getPerformative() == Performative.PROPOSE).toList();
                winner = proposals.isEmpty() ? null : chooseWinner.apply(proposals);
                for (AclMessage p : proposals) {
                    AclMessage reply = p.createReply();
                    reply.setPerformative(p == winner ? Performative.ACCEPT_PROPOSAL : Performative.REJECT_PROPOSAL);
                    acceptances.add(reply);
                }
                if (winner == null) {
                    f.completeExceptionally(new ProtocolException(ProtocolException.Reason.NO_PROPOSAL, null,
                            proposals.size() + " proposals, none chosen, from " + responses.size() + " responses"));
                }
            }

            @Override
            protected void handleInform(AclMessage inform) {
                f.complete(new ContractNetOutcome(winner, inform));
            }

            @Override
            protected void handleFailure(AclMessage failure) {
                if (winner != null && failure.getSender().equals(winner.getSender())) {
                    f.completeExceptionally(new ProtocolException(ProtocolException.Reason.FAILED, failure,
                            failure.getContent()));
                }
            }

            @Override
            protected void handleAllResultNotifications(List<AclMessage> results) {
                if (!f.isDone()) {
                    f.completeExceptionally(new ProtocolException(ProtocolException.Reason.TIMEOUT, null,
                            "the winner sent no result in time"));
                }
            }
        });
        return f;
    }

    /** Takes part in contract nets: proposes with one lambda, performs with another. */
    public static ContractNetResponder offer(Agent agent, MessageTemplate cfpTemplate, CfpHandler onCfp,
                                             AcceptHandler onAccept) {
        ContractNetResponder r = new ContractNetResponder(agent, cfpTemplate) {
            @Override
            protected AclMessage handleCfp(AclMessage cfp) throws RefuseException, FailureException,
                    NotUnderstoodException {
                try {
                    return onCfp.propose(cfp);
                } catch (RefuseException | FailureException | NotUnderstoodException e) {
                    throw e;
                } catch (FipaException e) {
                    throw new FailureException(e.getMessage());
                }
            }

            @Override
            protected AclMessage handleAcceptProposal(AclMessage cfp, AclMessage propose, AclMessage accept)
                    throws FailureException {
                return onAccept.perform(cfp, propose, accept);
            }
        };
        agent.addBehaviour(r);
        return r;
    }

    /** A running subscription. */
    public static final class SubscriptionHandle {
        private final CompletableFuture<AclMessage> agreed = new CompletableFuture<>();
        private SubscriptionInitiator initiator;
        private Agent agent;

        /** Completes on AGREE (or the first INFORM); fails on REFUSE or timeout. */
        public CompletableFuture<AclMessage> agreed() {
            return agreed;
        }

        /** Sends CANCEL and stops listening. Thread-safe. */
        public void cancel() {
            if (agent.runtime().inLoop()) {
                initiator.cancelAll();
            } else {
                agent.runtime().execute(initiator::cancelAll);
            }
        }
    }

    /** Subscribes; every notification goes to {@code onNotification}, on the agent's loop. */
    public static SubscriptionHandle subscribe(Agent agent, AclMessage subscribe, Consumer<AclMessage> onNotification) {
        SubscriptionHandle h = new SubscriptionHandle();
        h.agent = agent;
        h.initiator = new SubscriptionInitiator(agent, subscribe) {
            @Override
            protected void handleAgree(AclMessage agree) {
                h.agreed.complete(agree);
            }

            @Override
            protected void handleRefuse(AclMessage refuse) {
                h.agreed.completeExceptionally(new ProtocolException(ProtocolException.Reason.REFUSED, refuse,
                        refuse.getContent()));
            }

            @Override
            protected void handleInform(AclMessage inform) {
                h.agreed.complete(inform);
                onNotification.accept(inform);
            }

            @Override
            protected void handleFailure(AclMessage failure) {
                h.agreed.completeExceptionally(new ProtocolException(ProtocolException.Reason.FAILED, failure,
                        failure.getContent()));
            }

            @Override
            protected void handleAllResponses(List<AclMessage> responses) {
                if (responses.isEmpty()) {
                    h.agreed.completeExceptionally(new ProtocolException(ProtocolException.Reason.TIMEOUT, null,
                            "no answer to SUBSCRIBE by :reply-by"));
                }
            }
        };
        agent.addBehaviour(h.initiator);
        return h;
    }
}
