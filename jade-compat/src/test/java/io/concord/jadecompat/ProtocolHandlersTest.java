package io.concord.jadecompat;

import jade.core.AID;
import jade.core.Agent;
import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.AchieveREInitiator;
import jade.proto.AchieveREResponder;
import jade.proto.ContractNetInitiator;
import jade.proto.ContractNetResponder;
import jade.wrapper.AgentContainer;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.Set;
import java.util.TreeSet;
import java.util.Vector;
import java.util.concurrent.ConcurrentSkipListSet;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The silent-hook class of bug: a handler that compiles but that the engine never calls. Every
 * overridable {@code handle*}, {@code prepare*} and {@code sessionTerminated} method of the
 * protocol classes (found by reflection, so a new one is covered at once) must be called in a run
 * built to reach each of them; the calls are recorded by overrides and compared with that list.
 */
class ProtocolHandlersTest {
    static final Set<String> CALLED = new ConcurrentSkipListSet<>();
    private static AgentContainer container;

    @BeforeAll
    static void platform() {
        Profile p = new ProfileImpl();
        p.setParameter(Profile.LOCAL_HOST, "127.0.0.1");
        p.setParameter(Profile.LOCAL_PORT, Integer.toString(CorpusPorts.freeBase()));
        p.setParameter(Profile.PLATFORM_ID, "hooks");
        container = jade.core.Runtime.instance().createMainContainer(p);
    }

    /** The handlers a user may override in a protocol class: what this test must see called. */
    static Set<String> documentedHandlers(Class<?> type) {
        Set<String> names = new TreeSet<>();
        for (Method m : type.getDeclaredMethods()) {
            int mod = m.getModifiers();
            boolean overridable = (Modifier.isProtected(mod) || Modifier.isPublic(mod)) && !Modifier.isFinal(mod) && !Modifier.isStatic(mod);
            String n = m.getName();
            if (overridable && (n.startsWith("handle") || n.startsWith("prepare") || n.equals("sessionTerminated"))) {
                names.add(type.getSimpleName() + "." + n);
            }
        }
        return names;
    }

    static void called(Class<?> type, String method) {
        CALLED.add(type.getSimpleName() + "." + method);
    }

    @Test
    void everyAchieveREHandlerIsCalledByTheEngine() throws Exception {
        CountDownLatch over = new CountDownLatch(1);
        for (String role : new String[] {"agree", "refuse", "puzzled", "direct", "fail", "old-style"}) {
            container.acceptNewAgent("re-" + role, new RequestResponder(role)).start();
        }
        container.acceptNewAgent("re-initiator", new Agent() {
            @Override
            protected void setup() {
                ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
                for (String role : new String[] {"agree", "refuse", "puzzled", "direct", "fail", "old-style"}) {
                    req.addReceiver(new AID("re-" + role, AID.ISLOCALNAME));
                }
                req.setProtocol(FIPANames.InteractionProtocol.FIPA_REQUEST);
                addBehaviour(new AchieveREInitiator(this, req) {
                    @Override
                    protected Vector prepareRequests(ACLMessage request) {
                        called(AchieveREInitiator.class, "prepareRequests");
                        return super.prepareRequests(request);
                    }

                    @Override
                    protected void handleAgree(ACLMessage m) {
                        called(AchieveREInitiator.class, "handleAgree");
                    }

                    @Override
                    protected void handleRefuse(ACLMessage m) {
                        called(AchieveREInitiator.class, "handleRefuse");
                    }

                    @Override
                    protected void handleNotUnderstood(ACLMessage m) {
                        called(AchieveREInitiator.class, "handleNotUnderstood");
                    }

                    @Override
                    protected void handleInform(ACLMessage m) {
                        called(AchieveREInitiator.class, "handleInform");
                    }

                    @Override
                    protected void handleFailure(ACLMessage m) {
                        called(AchieveREInitiator.class, "handleFailure");
                    }

                    @Override
                    protected void handleOutOfSequence(ACLMessage m) {
                        called(AchieveREInitiator.class, "handleOutOfSequence");
                    }

                    @Override
                    protected void handleAllResponses(Vector v) {
                        called(AchieveREInitiator.class, "handleAllResponses");
                    }

                    @Override
                    protected void handleAllResultNotifications(Vector v) {
                        called(AchieveREInitiator.class, "handleAllResultNotifications");
                        over.countDown();
                    }
                });
            }
        }).start();
        assertTrue(over.await(30, TimeUnit.SECONDS), "the request protocol did not end");
        assertAllCalled(AchieveREInitiator.class);
        assertAllCalled(AchieveREResponder.class);
    }

    /** A request responder whose answer depends on its role; "agree" also sends one reply out of sequence first. */
    static final class RequestResponder extends Agent {
        private final String role;

        RequestResponder(String role) {
            this.role = role;
        }

        @Override
        protected void setup() {
            addBehaviour(new AchieveREResponder(this, AchieveREResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_REQUEST)) {
                @Override
                protected ACLMessage handleRequest(ACLMessage request) throws NotUnderstoodException, RefuseException {
                    if (role.equals("old-style")) {
                        called(AchieveREResponder.class, "handleRequest");
                        ACLMessage inform = request.createReply();
                        inform.setPerformative(ACLMessage.INFORM);
                        return inform;
                    }
                    return super.handleRequest(request);
                }

                @Override
                protected ACLMessage prepareResponse(ACLMessage request) throws NotUnderstoodException, RefuseException {
                    called(AchieveREResponder.class, "prepareResponse");
                    switch (role) {
                        case "refuse" -> throw new RefuseException("no");
                        case "puzzled" -> throw new NotUnderstoodException("what");
                        case "direct" -> {
                            return null;
                        }
                        default -> {
                            if (role.equals("agree")) {
                                ACLMessage odd = request.createReply();
                                odd.setPerformative(ACLMessage.PROPOSE);
                                myAgent.send(odd);
                            }
                            ACLMessage agree = request.createReply();
                            agree.setPerformative(ACLMessage.AGREE);
                            return agree;
                        }
                    }
                }

                @Override
                protected ACLMessage prepareResultNotification(ACLMessage request, ACLMessage response) throws FailureException {
                    called(AchieveREResponder.class, "prepareResultNotification");
                    if (role.equals("fail")) {
                        throw new FailureException("broken");
                    }
                    ACLMessage inform = request.createReply();
                    inform.setPerformative(ACLMessage.INFORM);
                    return inform;
                }
            });
        }
    }

    @Test
    void everyContractNetHandlerIsCalledByTheEngine() throws Exception {
        CountDownLatch over = new CountDownLatch(1);
        CountDownLatch rejectedSessionsOver = new CountDownLatch(2);
        String[] roles = {"best", "worse", "rejected", "refuse", "puzzled", "fail", "old-style"};
        for (String role : roles) {
            container.acceptNewAgent("cn-" + role, new CfpResponder(role, rejectedSessionsOver)).start();
        }
        container.acceptNewAgent("cn-initiator", new Agent() {
            @Override
            protected void setup() {
                ACLMessage cfp = new ACLMessage(ACLMessage.CFP);
                for (String role : roles) {
                    cfp.addReceiver(new AID("cn-" + role, AID.ISLOCALNAME));
                }
                cfp.setProtocol(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET);
                cfp.setConversationId("cn-hooks");
                addBehaviour(new ContractNetInitiator(this, cfp) {
                    @Override
                    protected Vector prepareCfps(ACLMessage c) {
                        called(ContractNetInitiator.class, "prepareCfps");
                        return super.prepareCfps(c);
                    }

                    @Override
                    protected void handlePropose(ACLMessage m, Vector acceptances) {
                        called(ContractNetInitiator.class, "handlePropose");
                    }

                    @Override
                    protected void handleRefuse(ACLMessage m) {
                        called(ContractNetInitiator.class, "handleRefuse");
                    }

                    @Override
                    protected void handleNotUnderstood(ACLMessage m) {
                        called(ContractNetInitiator.class, "handleNotUnderstood");
                    }

                    @Override
                    protected void handleFailure(ACLMessage m) {
                        called(ContractNetInitiator.class, "handleFailure");
                    }

                    @Override
                    protected void handleOutOfSequence(ACLMessage m) {
                        called(ContractNetInitiator.class, "handleOutOfSequence");
                    }

                    @Override
                    protected void handleInform(ACLMessage m) {
                        called(ContractNetInitiator.class, "handleInform");
                    }

                    @Override
                    protected void handleAllResponses(Vector responses, Vector acceptances) {
                        called(ContractNetInitiator.class, "handleAllResponses");
                        for (Object o : responses) {
                            ACLMessage r = (ACLMessage) o;
                            if (r.getPerformative() != ACLMessage.PROPOSE) {
                                continue;
                            }
                            String who = r.getSender().getLocalName();
                            ACLMessage answer = r.createReply();
                            if (who.equals("cn-worse")) {
                                // Something the responder does not expect while it waits for the decision.
                                ACLMessage odd = r.createReply();
                                odd.setPerformative(ACLMessage.INFORM);
                                myAgent.send(odd);
                                continue;
                            }
                            answer.setPerformative(who.equals("cn-old-style") || who.equals("cn-best")
                                    ? ACLMessage.ACCEPT_PROPOSAL : ACLMessage.REJECT_PROPOSAL);
                            acceptances.add(answer);
                        }
                    }

                    @Override
                    protected void handleAllResultNotifications(Vector v) {
                        called(ContractNetInitiator.class, "handleAllResultNotifications");
                        over.countDown();
                    }
                });
            }
        }).start();
        assertTrue(over.await(30, TimeUnit.SECONDS), "the contract net did not end");
        assertTrue(rejectedSessionsOver.await(30, TimeUnit.SECONDS), "the responders' sessions did not end");
        assertAllCalled(ContractNetInitiator.class);
        assertAllCalled(ContractNetResponder.class);
    }

    /** A contract-net responder by role; "old-style" uses JADE's older method names. */
    static final class CfpResponder extends Agent {
        private final String role;
        private final CountDownLatch sessionsOver;

        CfpResponder(String role, CountDownLatch sessionsOver) {
            this.role = role;
            this.sessionsOver = sessionsOver;
        }

        @Override
        protected void setup() {
            addBehaviour(new ContractNetResponder(this, ContractNetResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET)) {
                @Override
                protected ACLMessage handleCfp(ACLMessage cfp) throws RefuseException, FailureException, NotUnderstoodException {
                    if (role.equals("old-style")) {
                        return super.handleCfp(cfp);
                    }
                    called(ContractNetResponder.class, "handleCfp");
                    switch (role) {
                        case "refuse" -> throw new RefuseException("no");
                        case "puzzled" -> throw new NotUnderstoodException("what");
                        case "fail" -> throw new FailureException("broken");
                        default -> {
                            if (role.equals("best")) {
                                // Something the initiator does not expect while it collects proposals.
                                ACLMessage odd = cfp.createReply();
                                odd.setPerformative(ACLMessage.CONFIRM);
                                myAgent.send(odd);
                            }
                            ACLMessage propose = cfp.createReply();
                            propose.setPerformative(ACLMessage.PROPOSE);
                            propose.setContent(role);
                            return propose;
                        }
                    }
                }

                @Override
                protected ACLMessage prepareResponse(ACLMessage cfp) {
                    called(ContractNetResponder.class, "prepareResponse");
                    ACLMessage propose = cfp.createReply();
                    propose.setPerformative(ACLMessage.PROPOSE);
                    return propose;
                }

                @Override
                protected ACLMessage handleAcceptProposal(ACLMessage cfp, ACLMessage propose, ACLMessage accept) throws FailureException {
                    if (role.equals("old-style")) {
                        return super.handleAcceptProposal(cfp, propose, accept);
                    }
                    called(ContractNetResponder.class, "handleAcceptProposal");
                    ACLMessage inform = accept.createReply();
                    inform.setPerformative(ACLMessage.INFORM);
                    return inform;
                }

                @Override
                protected ACLMessage prepareResultNotification(ACLMessage cfp, ACLMessage propose, ACLMessage accept) {
                    called(ContractNetResponder.class, "prepareResultNotification");
                    ACLMessage failure = accept.createReply();
                    failure.setPerformative(ACLMessage.FAILURE);
                    return failure;
                }

                @Override
                protected void handleRejectProposal(ACLMessage cfp, ACLMessage propose, ACLMessage reject) {
                    called(ContractNetResponder.class, "handleRejectProposal");
                }

                @Override
                protected void handleOutOfSequence(ACLMessage cfp, ACLMessage propose, ACLMessage msg) {
                    called(ContractNetResponder.class, "handleOutOfSequence");
                }

                @Override
                protected void sessionTerminated() {
                    called(ContractNetResponder.class, "sessionTerminated");
                    if (role.equals("worse") || role.equals("rejected")) {
                        sessionsOver.countDown();
                    }
                }
            });
        }
    }

    static void assertAllCalled(Class<?> type) {
        Set<String> missing = new TreeSet<>(documentedHandlers(type));
        missing.removeAll(CALLED);
        assertTrue(!documentedHandlers(type).isEmpty(), "found no handlers of " + type.getSimpleName() + " by reflection");
        assertEquals(Set.of(), missing, "handlers of " + type.getSimpleName() + " the engine never called");
    }
}
