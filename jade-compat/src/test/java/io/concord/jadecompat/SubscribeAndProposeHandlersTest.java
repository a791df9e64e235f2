package io.concord.jadecompat;

import jade.core.AID;
import jade.core.Agent;
import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.core.behaviours.OneShotBehaviour;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.ProposeInitiator;
import jade.proto.ProposeResponder;
import jade.proto.SubscriptionInitiator;
import jade.proto.SubscriptionResponder;
import jade.wrapper.AgentContainer;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.util.Vector;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import static io.concord.jadecompat.ProtocolHandlersTest.assertAllCalled;
import static io.concord.jadecompat.ProtocolHandlersTest.called;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@link ProtocolHandlersTest}'s check for FIPA-subscribe and FIPA-propose: every documented
 * handler of {@code SubscriptionInitiator}/{@code Responder} and {@code ProposeInitiator}/{@code Responder}
 * is called in a run built to reach each of them.
 */
class SubscribeAndProposeHandlersTest {
    private static AgentContainer container;

    @BeforeAll
    static void platform() {
        Profile p = new ProfileImpl();
        p.setParameter(Profile.LOCAL_HOST, "127.0.0.1");
        p.setParameter(Profile.LOCAL_PORT, Integer.toString(CorpusPorts.freeBase()));
        p.setParameter(Profile.PLATFORM_ID, "hooks");
        container = jade.core.Runtime.instance().createMainContainer(p);
    }

    @Test
    void everySubscriptionHandlerIsCalledByTheEngine() throws Exception {
        CountDownLatch over = new CountDownLatch(1);
        // All three partners' first answers handled: the refusal may come after the other partner's
        // whole subscription has been cancelled (each agent has a thread of its own; CI saw it).
        CountDownLatch answered = new CountDownLatch(1);
        String[] roles = {"agree", "refuse", "puzzled"};
        for (String role : roles) {
            container.acceptNewAgent("sub-" + role, new Publisher(role)).start();
        }
        container.acceptNewAgent("sub-initiator", new Agent() {
            @Override
            protected void setup() {
                ACLMessage sub = new ACLMessage(ACLMessage.SUBSCRIBE);
                for (String role : roles) {
                    sub.addReceiver(new AID("sub-" + role, AID.ISLOCALNAME));
                }
                sub.setProtocol(FIPANames.InteractionProtocol.FIPA_SUBSCRIBE);
                addBehaviour(new SubscriptionInitiator(this, sub) {
                    @Override
                    protected Vector prepareSubscriptions(ACLMessage s) {
                        called(SubscriptionInitiator.class, "prepareSubscriptions");
                        return super.prepareSubscriptions(s);
                    }

                    @Override
                    protected void handleAgree(ACLMessage m) {
                        called(SubscriptionInitiator.class, "handleAgree");
                    }

                    @Override
                    protected void handleRefuse(ACLMessage m) {
                        called(SubscriptionInitiator.class, "handleRefuse");
                    }

                    @Override
                    protected void handleNotUnderstood(ACLMessage m) {
                        called(SubscriptionInitiator.class, "handleNotUnderstood");
                    }

                    @Override
                    protected void handleAllResponses(Vector v) {
                        called(SubscriptionInitiator.class, "handleAllResponses");
                        answered.countDown();
                    }

                    @Override
                    protected void handleOutOfSequence(ACLMessage m) {
                        called(SubscriptionInitiator.class, "handleOutOfSequence");
                    }

                    @Override
                    protected void handleInform(ACLMessage m) {
                        called(SubscriptionInitiator.class, "handleInform");
                        cancel(m.getSender(), false);
                    }

                    @Override
                    protected void handleFailure(ACLMessage m) {
                        called(SubscriptionInitiator.class, "handleFailure");
                    }

                    @Override
                    public void cancellationCompleted(AID receiver) {
                        over.countDown();
                    }
                });
            }
        }).start();
        assertTrue(over.await(30, TimeUnit.SECONDS), "the subscription was not cancelled");
        assertTrue(answered.await(30, TimeUnit.SECONDS), "handleAllResponses was not called");
        assertAllCalled(SubscriptionInitiator.class);
        assertAllCalled(SubscriptionResponder.class);
    }

    /**
     * Agrees (then sends one message out of sequence and one notification, and answers the
     * cancel with a failure), refuses, or does not understand, by its role.
     */
    static final class Publisher extends Agent {
        private final String role;

        Publisher(String role) {
            this.role = role;
        }

        @Override
        protected void setup() {
            SubscriptionResponder.SubscriptionManager manager = new SubscriptionResponder.SubscriptionManager() {
                @Override
                public boolean register(SubscriptionResponder.Subscription s) throws RefuseException, NotUnderstoodException {
                    if (role.equals("refuse")) {
                        throw new RefuseException("no");
                    }
                    if (role.equals("puzzled")) {
                        throw new NotUnderstoodException("what");
                    }
                    return true;
                }

                @Override
                public boolean deregister(SubscriptionResponder.Subscription s) throws FailureException {
                    throw new FailureException("cannot let go");
                }
            };
            addBehaviour(new SubscriptionResponder(this, SubscriptionResponder.createMessageTemplate(ACLMessage.SUBSCRIBE), manager) {
                @Override
                protected ACLMessage handleSubscription(ACLMessage s) throws NotUnderstoodException, RefuseException {
                    called(SubscriptionResponder.class, "handleSubscription");
                    super.handleSubscription(s);
                    SubscriptionResponder.Subscription sub = getSubscription(s);
                    myAgent.addBehaviour(new OneShotBehaviour(myAgent) {
                        @Override
                        public void action() {
                            ACLMessage odd = new ACLMessage(ACLMessage.PROPOSE);
                            sub.notify(odd);
                            sub.notify(new ACLMessage(ACLMessage.INFORM));
                        }
                    });
                    ACLMessage agree = s.createReply();
                    agree.setPerformative(ACLMessage.AGREE);
                    return agree;
                }

                @Override
                protected ACLMessage prepareResponse(ACLMessage s) throws NotUnderstoodException, RefuseException {
                    called(SubscriptionResponder.class, "prepareResponse");
                    return super.prepareResponse(s);
                }

                @Override
                protected ACLMessage handleCancel(ACLMessage cancel) throws FailureException {
                    called(SubscriptionResponder.class, "handleCancel");
                    return super.handleCancel(cancel);
                }
            });
        }
    }

    @Test
    void everyProposeHandlerIsCalledByTheEngine() throws Exception {
        CountDownLatch over = new CountDownLatch(1);
        String[] roles = {"accept", "reject", "puzzled", "chatty"};
        for (String role : roles) {
            container.acceptNewAgent("pr-" + role, new Partner(role)).start();
        }
        container.acceptNewAgent("pr-initiator", new Agent() {
            @Override
            protected void setup() {
                ACLMessage propose = new ACLMessage(ACLMessage.PROPOSE);
                for (String role : roles) {
                    propose.addReceiver(new AID("pr-" + role, AID.ISLOCALNAME));
                }
                propose.setProtocol(FIPANames.InteractionProtocol.FIPA_PROPOSE);
                addBehaviour(new ProposeInitiator(this, propose) {
                    @Override
                    protected Vector prepareInitiations(ACLMessage p) {
                        called(ProposeInitiator.class, "prepareInitiations");
                        return super.prepareInitiations(p);
                    }

                    @Override
                    protected void handleAcceptProposal(ACLMessage m) {
                        called(ProposeInitiator.class, "handleAcceptProposal");
                    }

                    @Override
                    protected void handleRejectProposal(ACLMessage m) {
                        called(ProposeInitiator.class, "handleRejectProposal");
                    }

                    @Override
                    protected void handleNotUnderstood(ACLMessage m) {
                        called(ProposeInitiator.class, "handleNotUnderstood");
                    }

                    @Override
                    protected void handleOutOfSequence(ACLMessage m) {
                        called(ProposeInitiator.class, "handleOutOfSequence");
                    }

                    @Override
                    protected void handleAllResponses(Vector v) {
                        called(ProposeInitiator.class, "handleAllResponses");
                        over.countDown();
                    }
                });
            }
        }).start();
        assertTrue(over.await(30, TimeUnit.SECONDS), "the propose protocol did not end");
        assertAllCalled(ProposeInitiator.class);
        assertAllCalled(ProposeResponder.class);
    }

    /** Accepts, rejects, does not understand, or (chatty) sends an INFORM before it accepts. */
    static final class Partner extends Agent {
        private final String role;

        Partner(String role) {
            this.role = role;
        }

        @Override
        protected void setup() {
            addBehaviour(new ProposeResponder(this, ProposeResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_PROPOSE)) {
                @Override
                protected ACLMessage prepareResponse(ACLMessage p) throws NotUnderstoodException, RefuseException {
                    called(ProposeResponder.class, "prepareResponse");
                    if (role.equals("puzzled")) {
                        throw new NotUnderstoodException("what");
                    }
                    if (role.equals("chatty")) {
                        ACLMessage odd = p.createReply();
                        odd.setPerformative(ACLMessage.INFORM);
                        myAgent.send(odd);
                    }
                    ACLMessage r = p.createReply();
                    r.setPerformative(role.equals("reject") ? ACLMessage.REJECT_PROPOSAL : ACLMessage.ACCEPT_PROPOSAL);
                    return r;
                }
            });
        }
    }
}
