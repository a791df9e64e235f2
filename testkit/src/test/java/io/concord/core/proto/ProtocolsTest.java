package io.concord.core.proto;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.LambdaAgent;
import io.concord.core.agent.OneShotBehaviour;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.function.Consumer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The FIPA interaction protocols, initiator and responder, on the virtual network. */
class ProtocolsTest {
    private final Simulation sim = new Simulation(3, FaultPlan.NONE);
    private final AgentRuntime rt = sim.newRuntime("h1");
    private final List<String> log = new ArrayList<>();

    @AfterEach
    void close() {
        sim.close();
    }

    private AID start(String name, Consumer<Agent> setup) {
        return rt.startAgent(name, new LambdaAgent(setup));
    }

    private long ms() {
        return sim.clock().nanoTime() / 1_000_000L;
    }

    private static AclMessage msg(Performative p, String content, AID... to) {
        AclMessage m = new AclMessage(p);
        for (AID a : to) {
            m.addReceiver(a);
        }
        m.setContent(content);
        return m;
    }

    /** A fipa-request responder whose behaviour is chosen per request content. */
    private AID requestResponder(String name) {
        return start(name, a -> a.addBehaviour(new AchieveREResponder(a,
                AchieveREResponder.createMessageTemplate(FipaProtocols.REQUEST)) {
            @Override
            protected AclMessage handleRequest(AclMessage req) throws RefuseException, NotUnderstoodException {
                log.add(name + " got " + req.getContent());
                switch (req.getContent()) {
                    case "refuse" -> throw new RefuseException("(busy)");
                    case "gibberish" -> throw new NotUnderstoodException("(unknown-action)");
                    case "direct" -> {
                        AclMessage inform = req.createReply();
                        inform.setPerformative(Performative.INFORM);
                        inform.setContent("done directly");
                        return inform;
                    }
                    default -> {
                        AclMessage agree = req.createReply();
                        agree.setPerformative(Performative.AGREE);
                        return agree;
                    }
                }
            }

            @Override
            protected AclMessage prepareResultNotification(AclMessage req, AclMessage resp) throws FailureException {
                if (req.getContent().equals("fail")) {
                    throw new FailureException("(broken)");
                }
                AclMessage inform = req.createReply();
                inform.setPerformative(Performative.INFORM);
                inform.setContent("did " + req.getContent());
                return inform;
            }
        }));
    }

    /** An initiator that logs every callback. */
    private void initiate(AclMessage request) {
        start("initiator", a -> a.addBehaviour(new AchieveREInitiator(a, request) {
            @Override
            protected void handleAgree(AclMessage m) {
                log.add("agree from " + m.getSender().localName());
            }

            @Override
            protected void handleRefuse(AclMessage m) {
                log.add("refuse " + m.getContent());
            }

            @Override
            protected void handleNotUnderstood(AclMessage m) {
                log.add("not-understood " + m.getContent());
            }

            @Override
            protected void handleInform(AclMessage m) {
                log.add("inform " + m.getContent());
            }

            @Override
            protected void handleFailure(AclMessage m) {
                log.add("failure " + m.getContent());
            }

            @Override
            protected void handleAllResponses(List<AclMessage> r) {
                log.add("all responses " + r.size() + " at " + ms());
            }

            @Override
            protected void handleAllResultNotifications(List<AclMessage> r) {
                log.add("all results " + r.size());
            }
        }));
    }

    @Nested
    class Request {
        @Test
        void agreeThenInform() {
            AID r = requestResponder("r");
            initiate(msg(Performative.REQUEST, "wash", r));
            sim.runUntilQuiet(5_000);
            assertEquals(List.of("r got wash", "agree from r", "all responses 1 at 0", "inform did wash", "all results 1"), log);
        }

        @Test
        void refusal() {
            AID r = requestResponder("r");
            initiate(msg(Performative.REQUEST, "refuse", r));
            sim.runUntilQuiet(5_000);
            assertEquals(List.of("r got refuse", "refuse (busy)", "all responses 1 at 0", "all results 0"), log);
        }

        @Test
        void notUnderstood() {
            AID r = requestResponder("r");
            initiate(msg(Performative.REQUEST, "gibberish", r));
            sim.runUntilQuiet(5_000);
            assertTrue(log.contains("not-understood (unknown-action)"), log.toString());
        }

        @Test
        void failureAfterAgreeing() {
            AID r = requestResponder("r");
            initiate(msg(Performative.REQUEST, "fail", r));
            sim.runUntilQuiet(5_000);
            assertEquals(List.of("r got fail", "agree from r", "all responses 1 at 0", "failure (broken)", "all results 1"), log);
        }

        @Test
        void anInformWithoutAgreeIsTheResult() {
            AID r = requestResponder("r");
            initiate(msg(Performative.REQUEST, "direct", r));
            sim.runUntilQuiet(5_000);
            assertEquals(List.of("r got direct", "inform done directly", "all responses 0 at 0", "all results 1"), log);
        }

        @Test
        void replyByEndsTheWaitForASilentResponder() {
            AID silent = start("silent", a -> { });
            AclMessage req = msg(Performative.REQUEST, "wash", silent);
            req.setReplyByEpochMs(sim.clock().epochMillis() + 750);
            initiate(req);
            sim.runUntilQuiet(60_000);
            assertEquals(List.of("all responses 0 at 750", "all results 0"), log);
        }

        @Test
        void severalRespondersAreTrackedOneByOne() {
            AID a = requestResponder("ra");
            AID b = requestResponder("rb");
            AID c = requestResponder("rc");
            AclMessage req = msg(Performative.REQUEST, "wash", a, b, c);
            initiate(req);
            sim.runUntilQuiet(5_000);
            assertEquals(3, log.stream().filter(s -> s.startsWith("agree")).count());
            assertEquals(3, log.stream().filter(s -> s.equals("inform did wash")).count());
            assertEquals("all results 3", log.get(log.size() - 1));
            assertEquals(1, log.stream().filter(s -> s.startsWith("all responses 3")).count());
        }

        @Test
        void anUnknownReceiverComesBackAsAFailureFromTheAms() {
            initiate(msg(Performative.REQUEST, "wash", new AID("nobody@sim")));
            sim.runUntilQuiet(5_000);
            assertTrue(log.get(0).startsWith("failure ( (action"), log.toString());
            assertTrue(log.get(0).contains("Agent not found: nobody@sim"), log.toString());
            assertEquals(1L, rt.drops().get("unknown-receiver"));
        }
    }

    @Test
    void queryRefIsAnsweredByAQueryResponder() {
        AID r = start("oracle", a -> a.addBehaviour(new AchieveREResponder(a,
                AchieveREResponder.createMessageTemplate(FipaProtocols.QUERY)) {
            @Override
            protected AclMessage handleRequest(AclMessage q) {
                AclMessage inform = q.createReply();
                inform.setPerformative(Performative.INFORM);
                inform.setContent("42");
                return inform;
            }
        }));
        AclMessage q = msg(Performative.QUERY_REF, "(answer)", r);
        initiate(q);
        sim.runUntilQuiet(5_000);
        assertEquals(List.of("inform 42", "all responses 0 at 0", "all results 1"), log);
    }

    private AID seller(String name, Integer price) {
        return start(name, a -> a.addBehaviour(new ContractNetResponder(a,
                ContractNetResponder.createMessageTemplate(FipaProtocols.CONTRACT_NET)) {
            @Override
            protected AclMessage handleCfp(AclMessage cfp) throws RefuseException {
                if (price == null) {
                    throw new RefuseException("(no-stock)");
                }
                if (price < 0) {
                    return null; // silent
                }
                AclMessage p = cfp.createReply();
                p.setPerformative(Performative.PROPOSE);
                p.setContent(price.toString());
                return p;
            }

            @Override
            protected AclMessage handleAcceptProposal(AclMessage cfp, AclMessage propose, AclMessage accept) {
                log.add(name + " accepted");
                AclMessage i = accept.createReply();
                i.setPerformative(Performative.INFORM);
                i.setContent("sold by " + name);
                return i;
            }

            @Override
            protected void handleRejectProposal(AclMessage cfp, AclMessage propose, AclMessage reject) {
                log.add(name + " rejected");
            }
        }));
    }

    private void buyCheapest(AclMessage cfp) {
        start("buyer", a -> a.addBehaviour(new ContractNetInitiator(a, cfp) {
            @Override
            protected void handleRefuse(AclMessage refuse) {
                log.add("refused by " + refuse.getSender().localName());
            }

            @Override
            protected void handleAllResponses(List<AclMessage> responses, List<AclMessage> acceptances) {
                List<AclMessage> proposals = responses.stream()
                        .filter(r -> r.getPerformative() == Performative.PROPOSE)
                        .sorted(Comparator.comparingInt(r -> Integer.parseInt(r.getContent()))).toList();
                log.add(proposals.size() + " proposals at " + ms());
                for (AclMessage p : proposals) {
                    AclMessage reply = p.createReply();
                    reply.setPerformative(p == proposals.get(0) ? Performative.ACCEPT_PROPOSAL : Performative.REJECT_PROPOSAL);
                    acceptances.add(reply);
                }
            }

            @Override
            protected void handleInform(AclMessage inform) {
                log.add("buyer: " + inform.getContent());
            }

            @Override
            protected void handleAllResultNotifications(List<AclMessage> results) {
                log.add("results " + results.size());
            }
        }));
    }

    @Nested
    class ContractNet {
        @Test
        void acceptsTheCheapestAndRejectsTheOthers() {
            AID s1 = seller("s1", 42);
            AID s2 = seller("s2", 35);
            AID s3 = seller("s3", null);
            buyCheapest(msg(Performative.CFP, "book", s1, s2, s3));
            sim.runUntilQuiet(5_000);
            assertTrue(log.contains("refused by s3"), log.toString());
            assertTrue(log.contains("2 proposals at 0"), log.toString());
            assertTrue(log.contains("s2 accepted"), log.toString());
            assertTrue(log.contains("s1 rejected"), log.toString());
            assertTrue(log.contains("buyer: sold by s2"), log.toString());
            assertEquals("results 1", log.get(log.size() - 1));
        }

        @Test
        void goesOnWithoutASilentProposerWhenReplyByPasses() {
            AID s1 = seller("s1", 42);
            AID silent = seller("s2", -1);
            AclMessage cfp = msg(Performative.CFP, "book", s1, silent);
            cfp.setReplyByEpochMs(sim.clock().epochMillis() + 300);
            buyCheapest(cfp);
            sim.runUntilQuiet(60_000);
            assertTrue(log.contains("1 proposals at 300"), log.toString());
            assertTrue(log.contains("buyer: sold by s1"), log.toString());
        }
    }

    @Nested
    class Subscribe {
        private SubscriptionResponder responder;

        private AID publisher(boolean refuse) {
            return start("pub", a -> {
                responder = new SubscriptionResponder(a, SubscriptionResponder.createMessageTemplate()) {
                    @Override
                    protected AclMessage handleSubscription(AclMessage s) throws RefuseException, NotUnderstoodException {
                        if (refuse) {
                            throw new RefuseException("(closed)");
                        }
                        return super.handleSubscription(s);
                    }

                    @Override
                    protected void handleCancel(AclMessage cancel) {
                        log.add("pub: cancelled by " + cancel.getSender().localName());
                    }
                };
                a.addBehaviour(responder);
            });
        }

        private SubscriptionInitiator subscriber(AID pub) {
            SubscriptionInitiator[] holder = new SubscriptionInitiator[1];
            start("sub", a -> {
                holder[0] = new SubscriptionInitiator(a, msg(Performative.SUBSCRIBE, "(door-position)", pub)) {
                    @Override
                    protected void handleAgree(AclMessage agree) {
                        log.add("agreed");
                    }

                    @Override
                    protected void handleRefuse(AclMessage refuse) {
                        log.add("refused " + refuse.getContent());
                    }

                    @Override
                    protected void handleInform(AclMessage inform) {
                        log.add("notified " + inform.getContent());
                    }
                };
                a.addBehaviour(holder[0]);
            });
            return holder[0];
        }

        @Test
        void deliversNotificationsUntilCancelled() {
            AID pub = publisher(false);
            SubscriptionInitiator sub = subscriber(pub);
            sim.runUntilQuiet(1_000);
            assertEquals(1, responder.getSubscriptions().size());
            for (String pos : List.of("closed", "opening", "open")) {
                AclMessage n = new AclMessage(Performative.INFORM);
                n.setContent(pos);
                responder.getSubscriptions().get(0).notify(n);
                sim.runUntilQuiet(1_000);
            }
            sub.cancel(pub, true);
            sim.runUntilQuiet(1_000);
            assertEquals(List.of("agreed", "notified closed", "notified opening", "notified open", "pub: cancelled by sub"), log);
            assertTrue(responder.getSubscriptions().isEmpty());
            assertTrue(sub.done());
        }

        @Test
        void aRefusedSubscriptionEnds() {
            AID pub = publisher(true);
            SubscriptionInitiator sub = subscriber(pub);
            sim.runUntilQuiet(1_000);
            assertEquals(List.of("refused (closed)"), log);
            assertTrue(responder.getSubscriptions().isEmpty());
            assertTrue(sub.done());
        }
    }

    @Nested
    class ModernForm {
        private <T> T result(CompletableFuture<T> f) throws Exception {
            sim.runUntil(f::isDone, 60_000);
            assertTrue(f.isDone(), "the future completed in virtual time");
            return f.get();
        }

        private ProtocolException failure(CompletableFuture<?> f) {
            sim.runUntil(f::isDone, 60_000);
            assertTrue(f.isDone(), "the future completed in virtual time; log " + log);
            ExecutionException e = assertThrows(ExecutionException.class, f::get);
            return assertInstanceOf(ProtocolException.class, e.getCause());
        }

        private CompletableFuture<AclMessage> ask(AclMessage m) {
            CompletableFuture<CompletableFuture<AclMessage>> outer = new CompletableFuture<>();
            start("asker" + log.size(), a -> a.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    outer.complete(Conversations.request(myAgent, m));
                }
            }));
            sim.runUntil(outer::isDone, 1_000);
            log.add("x");
            return outer.join();
        }

        @Test
        void aLambdaServesAndAFutureGetsTheInform() throws Exception {
            AID echo = start("echo", a -> Conversations.serve(a,
                    AchieveREResponder.createMessageTemplate(FipaProtocols.REQUEST),
                    req -> req.createReply().setPerformative(Performative.INFORM).setContent("echo " + req.getContent())));
            AclMessage inform = result(ask(msg(Performative.REQUEST, "hi", echo)));
            assertEquals("echo hi", inform.getContent());
            assertEquals(FipaProtocols.REQUEST, inform.getProtocol());
        }

        @Test
        void aRefusalFailsTheFutureWithItsReason() {
            AID no = start("no", a -> Conversations.serve(a, AchieveREResponder.createMessageTemplate(FipaProtocols.REQUEST),
                    req -> {
                        throw new RefuseException("(not-today)");
                    }));
            ProtocolException e = failure(ask(msg(Performative.REQUEST, "hi", no)));
            assertEquals(ProtocolException.Reason.REFUSED, e.reason());
            assertEquals("(not-today)", e.reply().getContent());
        }

        @Test
        void aFailureFromTheHandlerBecomesAFailureReply() {
            AID broken = start("broken", a -> Conversations.serve(a,
                    AchieveREResponder.createMessageTemplate(FipaProtocols.REQUEST),
                    req -> {
                        throw new FailureException("(motor-stalled)");
                    }));
            ProtocolException e = failure(ask(msg(Performative.REQUEST, "go", broken)));
            assertEquals(ProtocolException.Reason.FAILED, e.reason());
        }

        @Test
        void noAnswerByReplyByFailsTheFutureWithATimeout() {
            AID silent = start("silent", a -> { });
            AclMessage m = msg(Performative.REQUEST, "hi", silent);
            m.setReplyByEpochMs(sim.clock().epochMillis() + 200);
            ProtocolException e = failure(ask(m));
            assertEquals(ProtocolException.Reason.TIMEOUT, e.reason());
            assertNull(e.reply());
            assertEquals(200, ms());
        }

        @Test
        void aContractNetPicksTheWinnerWithALambda() throws Exception {
            List<AID> offers = new ArrayList<>();
            for (int price : new int[]{30, 20, 25}) {
                offers.add(start("o" + price, a -> Conversations.offer(a,
                        ContractNetResponder.createMessageTemplate(FipaProtocols.CONTRACT_NET),
                        cfp -> cfp.createReply().setPerformative(Performative.PROPOSE).setContent(Integer.toString(price)),
                        (cfp, prop, acc) -> acc.createReply().setPerformative(Performative.INFORM).setContent("done for " + price))));
            }
            CompletableFuture<CompletableFuture<Conversations.ContractNetOutcome>> outer = new CompletableFuture<>();
            start("chooser", a -> a.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    outer.complete(Conversations.contractNet(myAgent, msg(Performative.CFP, "job", offers.toArray(new AID[0])),
                            ps -> ps.stream().min(Comparator.comparingInt(p -> Integer.parseInt(p.getContent()))).orElse(null)));
                }
            }));
            sim.runUntil(outer::isDone, 1_000);
            Conversations.ContractNetOutcome out = result(outer.join());
            assertEquals("o20", out.proposal().getSender().localName());
            assertEquals("done for 20", out.result().getContent());
        }

        @Test
        void aResponderMayProposeLaterAndStillReceiveTheAcceptance() throws Exception {
            // The responder asks someone first (here: a timer) and proposes 300 ms after the CFP.
            AID slow = start("slow", a -> a.addBehaviour(new ContractNetResponder(a,
                    ContractNetResponder.createMessageTemplate(FipaProtocols.CONTRACT_NET)) {
                @Override
                protected AclMessage handleCfp(AclMessage cfp) {
                    a.addBehaviour(new io.concord.core.agent.WakerBehaviour(a, 300) {
                        @Override
                        protected void onWake() {
                            respond(cfp, cfp.createReply().setPerformative(Performative.PROPOSE).setContent("7"));
                        }
                    });
                    return null;
                }

                @Override
                protected AclMessage handleAcceptProposal(AclMessage cfp, AclMessage propose, AclMessage accept) {
                    return accept.createReply().setPerformative(Performative.INFORM).setContent("done late");
                }
            }));
            CompletableFuture<CompletableFuture<Conversations.ContractNetOutcome>> outer = new CompletableFuture<>();
            start("chooser", a -> a.addBehaviour(new OneShotBehaviour() {
                @Override
                public void action() {
                    AclMessage cfp = msg(Performative.CFP, "job", slow);
                    cfp.setReplyByEpochMs(sim.clock().epochMillis() + 1_000);
                    outer.complete(Conversations.contractNet(myAgent, cfp, ps -> ps.get(0)));
                }
            }));
            sim.runUntil(() -> outer.isDone() && outer.join().isDone(), 2_000);
            Conversations.ContractNetOutcome out = result(outer.join());
            assertEquals("7", out.proposal().getContent());
            assertEquals("done late", out.result().getContent());
        }

        @Test
        void aSubscriptionHandleDeliversNotificationsToAConsumer() throws Exception {
            SubscriptionResponder[] resp = new SubscriptionResponder[1];
            AID pub = start("pub", a -> {
                resp[0] = new SubscriptionResponder(a, SubscriptionResponder.createMessageTemplate());
                a.addBehaviour(resp[0]);
            });
            List<String> seen = new ArrayList<>();
            Conversations.SubscriptionHandle[] h = new Conversations.SubscriptionHandle[1];
            start("sub", a -> h[0] = Conversations.subscribe(a, msg(Performative.SUBSCRIBE, "(x)", pub),
                    n -> seen.add(n.getContent())));
            assertEquals(Performative.AGREE, result(h[0].agreed()).getPerformative());
            resp[0].getSubscriptions().get(0).notify(new AclMessage(Performative.INFORM).setContent("v1"));
            sim.runUntilQuiet(1_000);
            h[0].cancel();
            sim.runUntilQuiet(1_000);
            assertEquals(List.of("v1"), seen);
            assertTrue(resp[0].getSubscriptions().isEmpty());
        }
    }
}
