package io.concord.jade;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.PortRange;
import io.concord.core.content.Action;
import io.concord.core.content.ContentException;
import io.concord.core.content.ContentManager;
import io.concord.core.content.Done;
import io.concord.core.content.SlCodec;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.Platform;
import io.concord.layers.platform.ServiceDescription;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;
import jade.core.behaviours.OneShotBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.wrapper.ContainerController;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.io.InputStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A real JADE 4.3 platform in this JVM (main container, HTTP MTP with the parser fix) and a
 * Concord platform whose container serves the HTTP MTP: unchanged JADE code on one side, Concord
 * agents on the other.
 */
class JadeBridgeTest {
    static final long PID = ProcessHandle.current().pid();
    static final String CONCORD = "cbridge" + PID;
    static final String JADE = "jplat" + PID;
    static int jadeHttp;
    static int concordHttp;
    static ContainerController jadeMain;
    static Platform concord;
    static final Inbox INBOX = new Inbox();

    /** Keeps what a Concord agent receives. */
    static final class Inbox extends Agent {
        final BlockingQueue<AclMessage> got = new LinkedBlockingQueue<>();

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour() {
                @Override
                public void action() {
                    AclMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                    } else {
                        got.add(m);
                    }
                }
            });
        }
    }

    /** A Concord echo: REQUEST in, INFORM "echo:..." back; registered in the DF as echo-service. */
    static final class ConcordEcho extends io.concord.testkit.EchoAgent {
        @Override
        protected void setup() {
            super.setup();
            addBehaviour(new io.concord.core.agent.OneShotBehaviour(this) {
                @Override
                public void action() {
                    Platform.of(myAgent).register(ServiceDescription.of("echo-service", "concord-echo"));
                }
            });
        }
    }

    /** A JADE agent that runs one task on its own thread and completes a future with the result. */
    public static final class JadeDriver extends jade.core.Agent {
        @Override
        @SuppressWarnings("unchecked")
        protected void setup() {
            Function<jade.core.Agent, Object> task = (Function<jade.core.Agent, Object>) getArguments()[0];
            CompletableFuture<Object> result = (CompletableFuture<Object>) getArguments()[1];
            addBehaviour(new OneShotBehaviour(this) {
                @Override
                public void action() {
                    try {
                        result.complete(task.apply(myAgent));
                    } catch (Exception e) {
                        result.completeExceptionally(e);
                    }
                    myAgent.doDelete();
                }
            });
        }
    }

    /** A plain JADE echo agent. */
    public static final class JadeEcho extends jade.core.Agent {
        @Override
        protected void setup() {
            DFAgentDescription dfd = new DFAgentDescription();
            dfd.setName(getAID());
            jade.domain.FIPAAgentManagement.ServiceDescription sd = new jade.domain.FIPAAgentManagement.ServiceDescription();
            sd.setType("jade-echo-service");
            sd.setName("jecho-service");
            dfd.addServices(sd);
            try {
                DFService.register(this, dfd);
            } catch (jade.domain.FIPAException e) {
                throw new IllegalStateException(e);
            }
            addBehaviour(new jade.core.behaviours.CyclicBehaviour(this) {
                @Override
                public void action() {
                    ACLMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                    } else if (m.getPerformative() == ACLMessage.REQUEST) {
                        ACLMessage r = m.createReply();
                        r.setPerformative(ACLMessage.INFORM);
                        r.setContent("jade-echo:" + m.getContent());
                        myAgent.send(r);
                    }
                }
            });
        }
    }

    /**
     * A book seller in JADE: QUERY-REF gives its price, REQUEST gets AGREE, as the annex seller
     * ({@link io.concord.examples.BookSeller}) answers on Concord; and a contract net, through
     * jade.proto.ContractNetResponder.
     */
    public static final class JadeSeller extends jade.core.Agent {
        @Override
        protected void setup() {
            int price = Integer.parseInt(getArguments()[0].toString());
            addBehaviour(new jade.proto.ContractNetResponder(this, jade.proto.ContractNetResponder.createMessageTemplate(
                    jade.domain.FIPANames.InteractionProtocol.FIPA_CONTRACT_NET)) {
                @Override
                protected ACLMessage handleCfp(ACLMessage cfp) {
                    ACLMessage p = cfp.createReply();
                    p.setPerformative(ACLMessage.PROPOSE);
                    p.setContent(Integer.toString(price));
                    return p;
                }

                @Override
                protected ACLMessage handleAcceptProposal(ACLMessage cfp, ACLMessage propose, ACLMessage accept) {
                    ACLMessage i = accept.createReply();
                    i.setPerformative(ACLMessage.INFORM);
                    i.setContent("(sold at " + price + ")");
                    return i;
                }
            });
            addBehaviour(new jade.core.behaviours.CyclicBehaviour(this) {
                @Override
                public void action() {
                    ACLMessage m = myAgent.receive(MessageTemplate.or(MessageTemplate.MatchPerformative(ACLMessage.QUERY_REF),
                            MessageTemplate.MatchPerformative(ACLMessage.REQUEST)));
                    if (m == null) {
                        block();
                        return;
                    }
                    ACLMessage r = m.createReply();
                    r.setPerformative(m.getPerformative() == ACLMessage.QUERY_REF ? ACLMessage.INFORM : ACLMessage.AGREE);
                    r.setContent(m.getPerformative() == ACLMessage.QUERY_REF ? Integer.toString(price) : "(sold " + m.getContent() + ")");
                    myAgent.send(r);
                }
            });
        }
    }

    /**
     * A Concord book seller speaking the book-trading ontology through Concord's content manager
     * and SL codec: a CFP to sell a book gets a PROPOSE that it costs its price, an ACCEPT-PROPOSAL
     * the INFORM that the sale is done; content it cannot read gets NOT-UNDERSTOOD with the reason.
     * It keeps what it extracted.
     */
    static final class ConcordBookSeller extends Agent {
        final BlockingQueue<Object> extracted = new LinkedBlockingQueue<>();
        final ContentManager cm = new ContentManager().register(new SlCodec()).register(BookTrading.ontology());

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour() {
                @Override
                public void action() {
                    AclMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    AclMessage r = m.createReply();
                    try {
                        Object content = cm.extract(m);
                        extracted.add(content);
                        if (!(content instanceof Action a && a.action() instanceof BookTrading.Sell sell)) {
                            throw new ContentException("expected an action Sell, got " + content);
                        }
                        if (m.getPerformative() == Performative.CFP) {
                            BookTrading.Book b = sell.item();
                            r.setPerformative(Performative.PROPOSE);
                            cm.fill(r, new BookTrading.Costs(new BookTrading.Book(b.title(), List.of("Frank Herbert"), null), 17.5));
                        } else if (m.getPerformative() == Performative.ACCEPT_PROPOSAL) {
                            r.setPerformative(Performative.INFORM);
                            cm.fill(r, new Done(a));
                        } else {
                            r.setPerformative(Performative.NOT_UNDERSTOOD);
                            r.setContent("not a CFP or ACCEPT-PROPOSAL");
                        }
                    } catch (ContentException e) {
                        r.setPerformative(Performative.NOT_UNDERSTOOD);
                        r.setContent(e.reason());
                    }
                    myAgent.send(r);
                }
            });
        }
    }

    /** {@link ConcordBookSeller} in JADE, with JADE's SLCodec and BeanOntology; keeps what it extracted. */
    public static final class JadeBookSeller extends jade.core.Agent {
        static final BlockingQueue<Object> EXTRACTED = new LinkedBlockingQueue<>();

        @Override
        protected void setup() {
            getContentManager().registerLanguage(new jade.content.lang.sl.SLCodec());
            try {
                getContentManager().registerOntology(JadeBookTrading.ontology());
            } catch (jade.content.onto.BeanOntologyException e) {
                throw new IllegalStateException(e);
            }
            addBehaviour(new jade.core.behaviours.CyclicBehaviour(this) {
                @Override
                public void action() {
                    ACLMessage m = myAgent.receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    ACLMessage r = m.createReply();
                    try {
                        jade.content.ContentElement ce = myAgent.getContentManager().extractContent(m);
                        EXTRACTED.add(ce);
                        jade.content.onto.basic.Action a = (jade.content.onto.basic.Action) ce;
                        JadeBookTrading.Sell sell = (JadeBookTrading.Sell) a.getAction();
                        if (m.getPerformative() == ACLMessage.CFP) {
                            JadeBookTrading.Costs c = new JadeBookTrading.Costs();
                            c.setItem(JadeBookTrading.book(sell.getItem().getTitle(), List.of("Ursula K. Le Guin"), null));
                            c.setPrice(23.25);
                            r.setPerformative(ACLMessage.PROPOSE);
                            myAgent.getContentManager().fillContent(r, c);
                        } else {
                            r.setPerformative(ACLMessage.INFORM);
                            myAgent.getContentManager().fillContent(r, new jade.content.onto.basic.Done(a));
                        }
                    } catch (Exception e) {
                        r.setPerformative(ACLMessage.NOT_UNDERSTOOD);
                        r.setContent(String.valueOf(e));
                    }
                    myAgent.send(r);
                }
            });
        }
    }

    static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    @BeforeAll
    static void platforms() throws Exception {
        jadeHttp = freePort();
        concordHttp = freePort();
        jade.core.Runtime rt = jade.core.Runtime.instance();
        rt.setCloseVM(false);
        jade.core.Profile p = new jade.core.ProfileImpl();
        p.setParameter(jade.core.Profile.GUI, "false");
        p.setParameter(jade.core.Profile.LOCAL_HOST, "127.0.0.1");
        p.setParameter(jade.core.Profile.LOCAL_PORT, Integer.toString(freePort()));
        p.setParameter(jade.core.Profile.PLATFORM_ID, JADE);
        p.setParameter(jade.core.Profile.DETECT_MAIN, "false");
        p.setParameter(jade.core.Profile.MTPS, "jade.mtp.http.MessageTransportProtocol(http://127.0.0.1:" + jadeHttp + "/acc)");
        p.setParameter("jade_mtp_http_parser", JadeSaxParser.class.getName());
        jadeMain = rt.createMainContainer(p);
        assertNotNull(jadeMain, "JADE's main container did not start");
        jadeMain.createNewAgent("jecho", JadeEcho.class.getName(), new Object[0]).start();

        concord = Platform.builder().name(CONCORD).ports(PortRange.of(7701, 7750))
                .safetyStack(SafetyStack.builder().profile(Profile.CLASS_7).platformKey(PlatformKey.random())
                        .identities(IdentityStore.ephemeral()).build())
                .gateway(() -> new HttpMtp("127.0.0.1", concordHttp)).network(null).build();
        concord.startAgent("echo", new ConcordEcho());
        concord.startAgent("inbox", INBOX);
        awaitListed("echo", "inbox");
    }

    /**
     * Waits until the container lists these agents (as the inbox's copy of the list shows): before,
     * the bridge answers JADE's messages to them with the FIPA FAILURE for an unknown agent.
     */
    static void awaitListed(String... locals) throws Exception {
        java.util.Set<String> want = new java.util.HashSet<>();
        for (String l : locals) {
            want.add(l + "@" + CONCORD);
        }
        CompletableFuture<Void> listed = new CompletableFuture<>();
        concord.runtime().execute(() -> {
            io.concord.layers.platform.ContainerLayer l = Platform.containerLayer(concord.runtime(),
                    io.concord.core.acl.AID.local("inbox", CONCORD));
            java.util.function.Consumer<io.concord.layers.platform.ContainerLayer> check = x -> {
                java.util.Set<String> names = new java.util.HashSet<>();
                x.agents().forEach(e -> names.add(e.name()));
                if (x.containerName() != null && names.containsAll(want)) {
                    listed.complete(null);
                }
            };
            l.addListener(check);
            check.accept(l);
        });
        try {
            listed.get(20, TimeUnit.SECONDS);
        } catch (java.util.concurrent.TimeoutException e) {
            throw new AssertionError("the container did not list " + want + " within 20 s", e);
        }
    }

    @AfterAll
    static void stop() {
        if (concord != null) {
            concord.close();
        }
        if (jadeMain != null) {
            try {
                jadeMain.kill();
            } catch (Exception ignored) {
                // gone
            }
        }
    }

    static jade.core.AID concordAid(String local) {
        jade.core.AID a = new jade.core.AID(local + "@" + CONCORD, jade.core.AID.ISGUID);
        a.addAddresses("http://127.0.0.1:" + concordHttp + "/acc");
        return a;
    }

    static Object onJade(Function<jade.core.Agent, Object> task) throws Exception {
        CompletableFuture<Object> f = new CompletableFuture<>();
        jadeMain.createNewAgent("driver" + System.nanoTime(), JadeDriver.class.getName(), new Object[]{task, f}).start();
        return f.get(60, TimeUnit.SECONDS);
    }

    @Test
    void aJadeAgentRequestsAConcordAgentAndGetsItsInform() throws Exception {
        Object reply = onJade(a -> {
            ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
            req.addReceiver(concordAid("echo"));
            req.setContent("hello from jade");
            req.setConversationId("c1");
            a.send(req);
            ACLMessage r = a.blockingReceive(MessageTemplate.MatchConversationId("c1"), 30_000);
            return r == null ? "nothing" : ACLMessage.getPerformative(r.getPerformative()) + " " + r.getContent()
                    + " from " + r.getSender().getName();
        });
        assertEquals("INFORM echo:hello from jade from echo@" + CONCORD, reply);
        // Served on the agents' own loop: no thread of the bridge's stands between a socket and an agent.
        assertTrue(Thread.getAllStackTraces().keySet().stream().noneMatch(t -> t.getName().startsWith("concord-http")),
                "the HTTP MTP runs on the platform's loop, not on a thread of its own");
    }

    @Test
    void aConcordAgentRequestsAJadeAgentByNameAndGetsItsInform() throws Exception {
        AclMessage req = new AclMessage(Performative.REQUEST);
        req.addReceiver(new io.concord.core.acl.AID("jecho@" + JADE, "http://127.0.0.1:" + jadeHttp + "/acc"));
        req.setContent("hello from concord");
        req.setConversationId("c2");
        INBOX.send(req);
        AclMessage r = poll(m -> "c2".equals(m.getConversationId()));
        assertEquals(Performative.INFORM, r.getPerformative());
        assertEquals("jade-echo:hello from concord", r.getContent());
        assertEquals("jecho@" + JADE, r.getSender().name());
    }

    @Test
    void aJadeAgentFindsAConcordAgentWithDfServiceSearchOverHttp() throws Exception {
        Object found = onJade(a -> {
            DFAgentDescription template = new DFAgentDescription();
            jade.domain.FIPAAgentManagement.ServiceDescription sd = new jade.domain.FIPAAgentManagement.ServiceDescription();
            sd.setType("echo-service");
            template.addServices(sd);
            for (int i = 0; i < 50; i++) { // the registration reaches the DF in the first moments
                try {
                    DFAgentDescription[] r = DFService.search(a, concordAid("df"), template);
                    if (r.length > 0) {
                        return r[0].getName().getName() + " " + String.join(",", r[0].getName().getAddressesArray());
                    }
                    a.doWait(100);
                } catch (Exception e) {
                    return "search failed: " + e;
                }
            }
            return "not found";
        });
        assertEquals("echo@" + CONCORD + " http://127.0.0.1:" + concordHttp + "/acc", found);
    }

    /**
     * JADE writes content ending in a backslash as {@code "...\"}; before, Concord refused it with
     * HTTP 400 and JADE reported "No valid address". Both ways, with real JADE.
     */
    @Test
    void contentEndingInABackslashCrossesBothWays() throws Exception {
        Object reply = onJade(a -> {
            ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
            req.addReceiver(concordAid("echo"));
            req.setConversationId("bs1");
            req.setContent("C:\\temp\\");
            a.send(req);
            ACLMessage r = a.blockingReceive(MessageTemplate.MatchConversationId("bs1"), 30_000);
            return r == null ? "nothing" : ACLMessage.getPerformative(r.getPerformative()) + " " + r.getContent();
        });
        assertEquals("INFORM echo:C:\\temp\\", reply);
    }

    /**
     * A protocol name JADE's parser cannot read (not a word) would make JADE reject the whole
     * message; the bridge does not send it, tells the sender FAILURE with the reason, and counts it.
     */
    @Test
    void aMessageJadeCannotReadIsNotSentAndItsSenderIsTold() throws Exception {
        AclMessage req = new AclMessage(Performative.REQUEST);
        req.addReceiver(new io.concord.core.acl.AID("jecho@" + JADE, "http://127.0.0.1:" + jadeHttp + "/acc"));
        req.setConversationId("unwritable1");
        req.setProtocol("my protocol");
        req.setContent("hello");
        INBOX.send(req);
        AclMessage r = poll(m -> "unwritable1".equals(m.getConversationId()));
        assertEquals(Performative.FAILURE, r.getPerformative());
        assertTrue(r.getContent().contains("protocol 'my protocol'"), r.getContent());
    }

    @Test
    void unknownReceiversGetTheFipaFailureBothWays() throws Exception {
        Object reply = onJade(a -> {
            ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
            req.addReceiver(concordAid("nobody"));
            req.setConversationId("c3");
            req.setContent("anyone?");
            a.send(req);
            ACLMessage r = a.blockingReceive(MessageTemplate.MatchConversationId("c3"), 30_000);
            return r == null ? "nothing" : ACLMessage.getPerformative(r.getPerformative()) + " " + r.getContent();
        });
        assertTrue(reply.toString().startsWith("FAILURE") && reply.toString().contains("Agent not found: nobody@" + CONCORD),
                reply.toString());

        AclMessage req = new AclMessage(Performative.REQUEST);
        req.addReceiver(new io.concord.core.acl.AID("nobody@" + JADE, "http://127.0.0.1:" + jadeHttp + "/acc"));
        req.setConversationId("c4");
        req.setContent("anyone there?");
        INBOX.send(req);
        AclMessage r = poll(m -> "c4".equals(m.getConversationId()));
        assertEquals(Performative.FAILURE, r.getPerformative());
        assertTrue(r.getContent().contains("nobody@" + JADE), r.getContent());
    }

    @Test
    void aMalformedHttpRequestGetsA4xxDeliversNothingAndTheEndpointKeepsServing() throws Exception {
        String[][] bad = {
                {"text/plain", "hello"},
                {"multipart/mixed ; boundary=\"b1\"", "--b1\r\ngarbage here\r\n"},
                {"multipart/mixed ; boundary=\"b1\"", "--b1\r\nContent-Type: application/xml\r\n\r\n<envelope>\r\n--b1\r\n\r\n(inform)\r\n--b1--\r\n"},
                {"multipart/mixed ; boundary=\"b1\"", "--b1\r\nContent-Type: application/xml\r\n\r\n<envelope><params index=\"1\"><to><agent-identifier><name>echo@"
                        + CONCORD + "</name></agent-identifier></to><acl-representation>fipa.acl.rep.string.std</acl-representation>"
                        + "</params></envelope>\r\n--b1\r\nContent-Type: application/text\r\n\r\n(inform :content \"unclosed)\r\n--b1--\r\n"}};
        for (String[] b : bad) {
            String request = "POST /acc HTTP/1.1\r\nContent-Type: " + b[0] + "\r\nContent-Length: "
                    + b[1].getBytes(StandardCharsets.ISO_8859_1).length + "\r\nConnection: close\r\n\r\n" + b[1];
            int status = rawStatus(request);
            assertTrue(status >= 400 && status < 500, "status " + status + " for " + request);
        }
        assertTrue(INBOX.got.stream().noneMatch(m -> "inform".equalsIgnoreCase(String.valueOf(m.getContent()))));
        aJadeAgentRequestsAConcordAgentAndGetsItsInform();
    }

    @Test
    void aConcordAgentFindsAJadeAgentInJadesDf() throws Exception {
        AclMessage q = new AclMessage(Performative.REQUEST);
        io.concord.core.acl.AID df = new io.concord.core.acl.AID("df@" + JADE, "http://127.0.0.1:" + jadeHttp + "/acc");
        q.addReceiver(df);
        q.setLanguage("fipa-sl0");
        q.setOntology("FIPA-Agent-Management");
        q.setProtocol("fipa-request");
        q.setConversationId("c5");
        q.setContent("((action (agent-identifier :name df@" + JADE + ") (search (df-agent-description :services (set "
                + "(service-description :type jade-echo-service))) (search-constraints :max-results -1))))");
        INBOX.send(q);
        AclMessage r = poll(m -> "c5".equals(m.getConversationId()) && m.getPerformative() != Performative.AGREE);
        assertEquals(Performative.INFORM, r.getPerformative(), r.getContent());
        assertTrue(r.getContent().contains("jecho@" + JADE), r.getContent());
    }

    @Test
    void whenTheContainerThatHostsTheEndpointDiesTheNewOneServesIt() throws Exception {
        String name = "fo" + PID;
        int port = freePort();
        try (Platform p = Platform.builder().name(name).ports(PortRange.of(7751, 7790))
                .safetyStack(SafetyStack.builder().profile(Profile.CLASS_3).platformKey(PlatformKey.random()).build())
                .gateway(() -> new HttpMtp("127.0.0.1", port)).network(null).build()) {
            io.concord.core.acl.AID first = p.startAgent("first", new ConcordEcho());
            p.startAgent("second", new ConcordEcho());
            Function<String, Function<jade.core.Agent, Object>> ask = who -> a -> {
                for (int i = 0; i < 100; i++) {
                    ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
                    jade.core.AID to = new jade.core.AID(who + "@" + name, jade.core.AID.ISGUID);
                    to.addAddresses("http://127.0.0.1:" + port + "/acc");
                    req.addReceiver(to);
                    req.setContent("ping");
                    req.setConversationId("fo" + i);
                    a.send(req);
                    ACLMessage r = a.blockingReceive(MessageTemplate.MatchConversationId("fo" + i), 500);
                    if (r != null && r.getPerformative() == ACLMessage.INFORM) {
                        return r.getContent() + " after " + i + " tries";
                    }
                    a.doWait(100); // the FAILURE came at once: the endpoint is between containers
                }
                return "no answer";
            };
            assertTrue(onJade(ask.apply("second")).toString().startsWith("echo:ping"));
            // "first" bound the range first: it is the container, and serves the endpoint.
            p.runtime().execute(() -> p.runtime().crashAgent(first));
            Object after = onJade(ask.apply("second"));
            assertTrue(after.toString().startsWith("echo:ping"), "nobody served the endpoint after the failover: " + after);
        }
    }

    @Test
    void anUnchangedJadeAgentFindsAConcordAgentInItsOwnDfThroughTheMirror() throws Exception {
        jadeMain.createNewAgent("mirror", ConcordDfMirror.class.getName(),
                new Object[]{CONCORD, "http://127.0.0.1:" + concordHttp + "/acc", "200"}).start();
        Object found = onJade(a -> {
            DFAgentDescription template = new DFAgentDescription();
            jade.domain.FIPAAgentManagement.ServiceDescription sd = new jade.domain.FIPAAgentManagement.ServiceDescription();
            sd.setType("echo-service");
            template.addServices(sd);
            for (int i = 0; i < 100; i++) {
                try {
                    DFAgentDescription[] r = DFService.search(a, template); // JADE's own DF
                    if (r.length > 0) {
                        ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
                        req.addReceiver(r[0].getName());
                        req.setContent("found you");
                        req.setConversationId("m1");
                        a.send(req);
                        ACLMessage reply = a.blockingReceive(MessageTemplate.MatchConversationId("m1"), 30_000);
                        return r[0].getName().getName() + " said " + (reply == null ? "nothing" : reply.getContent());
                    }
                } catch (Exception e) {
                    return "search failed: " + e;
                }
                a.doWait(100);
            }
            return "not mirrored";
        });
        assertEquals("echo@" + CONCORD + " said echo:found you", found);
    }

    @Test
    void aJadeBuyerBuysFromConcordSellers() throws Exception {
        int[] prices = {42, 35, 39};
        for (int i = 0; i < prices.length; i++) {
            concord.startAgent("cseller" + i, new io.concord.examples.BookSeller(prices[i]));
        }
        awaitListed("cseller0", "cseller1", "cseller2");
        Object outcome = onJade(a -> {
            ACLMessage q = new ACLMessage(ACLMessage.QUERY_REF);
            for (int i = 0; i < prices.length; i++) {
                q.addReceiver(concordAid("cseller" + i));
            }
            q.setContent("dune");
            q.setConversationId("jb1");
            a.send(q);
            ACLMessage best = null;
            for (int i = 0; i < prices.length; i++) {
                ACLMessage r = a.blockingReceive(MessageTemplate.and(MessageTemplate.MatchConversationId("jb1"),
                        MessageTemplate.MatchPerformative(ACLMessage.INFORM)), 30_000);
                if (r == null) {
                    return "only " + i + " quotes";
                }
                if (best == null || Integer.parseInt(r.getContent()) < Integer.parseInt(best.getContent())) {
                    best = r;
                }
            }
            ACLMessage buy = best.createReply();
            buy.setPerformative(ACLMessage.REQUEST);
            buy.setContent("1"); // one book
            a.send(buy);
            ACLMessage agree = a.blockingReceive(MessageTemplate.and(MessageTemplate.MatchConversationId("jb1"),
                    MessageTemplate.MatchPerformative(ACLMessage.AGREE)), 30_000);
            return agree == null ? "no agree" : best.getSender().getLocalName() + " at " + best.getContent() + " agreed by "
                    + agree.getSender().getLocalName();
        });
        assertEquals("cseller1 at 35 agreed by cseller1", outcome);
    }

    @Test
    void aConcordBuyerBuysFromJadeSellersAndRunsAContractNetWithThem() throws Exception {
        int[] prices = {30, 25, 28};
        for (int i = 0; i < prices.length; i++) {
            jadeMain.createNewAgent("jseller" + i, JadeSeller.class.getName(), new Object[]{Integer.toString(prices[i])}).start();
        }
        java.util.function.IntFunction<io.concord.core.acl.AID> seller = i -> new io.concord.core.acl.AID("jseller" + i + "@" + JADE,
                "http://127.0.0.1:" + jadeHttp + "/acc");
        // The book buyer: QUERY-REF to all, REQUEST to the cheapest, AGREE.
        AclMessage q = new AclMessage(Performative.QUERY_REF);
        for (int i = 0; i < prices.length; i++) {
            q.addReceiver(seller.apply(i));
        }
        q.setContent("dune");
        q.setConversationId("cb1");
        INBOX.send(q);
        AclMessage best = null;
        for (int i = 0; i < prices.length; i++) {
            AclMessage r = poll(m -> "cb1".equals(m.getConversationId()) && m.getPerformative() == Performative.INFORM);
            if (best == null || Integer.parseInt(r.getContent()) < Integer.parseInt(best.getContent())) {
                best = r;
            }
        }
        AclMessage buy = best.createReply();
        buy.setPerformative(Performative.REQUEST);
        buy.setContent("dune");
        INBOX.send(buy);
        AclMessage agree = poll(m -> "cb1".equals(m.getConversationId()) && m.getPerformative() == Performative.AGREE);
        assertEquals("jseller1@" + JADE, agree.getSender().name());

        // A contract net, Concord initiator, JADE responders (jade.proto.ContractNetResponder).
        Agent cn = new Agent() { };
        concord.startAgent("cnbuyer", cn);
        CompletableFuture<io.concord.core.proto.Conversations.ContractNetOutcome> outcome = new CompletableFuture<>();
        concord.runtime().execute(() -> {
            AclMessage cfp = new AclMessage(Performative.CFP);
            for (int i = 0; i < prices.length; i++) {
                cfp.addReceiver(seller.apply(i));
            }
            cfp.setContent("dune");
            cfp.setProtocol("fipa-contract-net");
            cfp.setReplyByEpochMs(cn.currentTimeMillis() + 20_000);
            io.concord.core.proto.Conversations.contractNet(cn, cfp, ps -> ps.stream()
                    .min(java.util.Comparator.comparingInt(p -> Integer.parseInt(p.getContent()))).orElse(null))
                    .whenComplete((o, e) -> {
                        if (e != null) {
                            outcome.completeExceptionally(e);
                        } else {
                            outcome.complete(o);
                        }
                    });
        });
        var o = outcome.get(60, TimeUnit.SECONDS);
        assertEquals("jseller1@" + JADE, o.proposal().getSender().name());
        assertEquals("(sold at 25)", o.result().getContent());
    }

    /** JADE's DFService registers a JADE agent in Concord's DF, finds it there, and deregisters it. */
    @Test
    void aJadeAgentRegistersSearchesAndDeregistersInConcordsDf() throws Exception {
        Object outcome = onJade(a -> {
            try {
                DFAgentDescription dfd = new DFAgentDescription();
                dfd.setName(a.getAID());
                jade.domain.FIPAAgentManagement.ServiceDescription sd = new jade.domain.FIPAAgentManagement.ServiceDescription();
                sd.setType("foreign-service");
                sd.setName("fs");
                sd.addLanguages("fipa-sl");
                sd.addProperties(new jade.domain.FIPAAgentManagement.Property("colour", "blue"));
                dfd.addServices(sd);
                DFService.register(a, concordAid("df"), dfd);
                DFAgentDescription template = new DFAgentDescription();
                jade.domain.FIPAAgentManagement.ServiceDescription t = new jade.domain.FIPAAgentManagement.ServiceDescription();
                t.setType("foreign-service");
                template.addServices(t);
                DFAgentDescription[] found = DFService.search(a, concordAid("df"), template);
                StringBuilder b = new StringBuilder();
                for (DFAgentDescription d : found) {
                    jade.domain.FIPAAgentManagement.ServiceDescription s = (jade.domain.FIPAAgentManagement.ServiceDescription)
                            d.getAllServices().next();
                    jade.domain.FIPAAgentManagement.Property p = (jade.domain.FIPAAgentManagement.Property) s.getAllProperties().next();
                    b.append(d.getName().equals(a.getAID())).append(' ').append(s.getName()).append(' ')
                            .append(s.getAllLanguages().next()).append(' ').append(p.getName()).append('=').append(p.getValue());
                }
                DFService.deregister(a, concordAid("df"), dfd);
                b.append(" | after deregister: ").append(DFService.search(a, concordAid("df"), template).length);
                return b.toString();
            } catch (Exception e) {
                return "failed: " + e;
            }
        });
        assertEquals("true fs fipa-sl colour=blue | after deregister: 0", outcome);
    }

    @Test
    void theDfAnswersWhatItDoesNotDoWithAClearFailure() throws Exception {
        Object replies = onJade(a -> {
            StringBuilder b = new StringBuilder();
            String[] contents = {
                    "((action (agent-identifier :name df@" + CONCORD + ") (modify (df-agent-description :name (agent-identifier :name x@y)))))",
                    "((action (agent-identifier :name df@" + CONCORD + ") (search (df-agent-description"};
            for (int i = 0; i < contents.length; i++) {
                ACLMessage req = new ACLMessage(ACLMessage.REQUEST);
                req.addReceiver(concordAid("df"));
                req.setLanguage("fipa-sl0");
                req.setOntology("FIPA-Agent-Management");
                req.setContent(contents[i]);
                req.setConversationId("sl" + i);
                a.send(req);
                ACLMessage r = a.blockingReceive(MessageTemplate.MatchConversationId("sl" + i), 30_000);
                b.append(r == null ? "nothing" : ACLMessage.getPerformative(r.getPerformative()) + " " + r.getContent()).append('\n');
            }
            return b.toString();
        });
        String[] lines = replies.toString().split("\n");
        assertTrue(lines[0].startsWith("FAILURE") && lines[0].contains("(unsupported-function modify)"), lines[0]);
        assertTrue(lines[1].startsWith("NOT-UNDERSTOOD") && lines[1].contains("unexpected end of text"), lines[1]);
    }

    /**
     * The book-trading ontology both ways over the bridge, each side with its own content stack: a
     * JADE buyer (JADE's SLCodec and BeanOntology) buys from a Concord seller (Concord's
     * ContentManager, SlCodec and BeanOntology) with CFP, PROPOSE, ACCEPT-PROPOSAL, INFORM; each
     * side's extracted objects are checked.
     */
    @Test
    void aJadeBuyerWithJadesSlCodecTradesABookWithAConcordSellerUsingOurs() throws Exception {
        ConcordBookSeller seller = new ConcordBookSeller();
        concord.startAgent("bookseller", seller);
        awaitListed("bookseller");
        Object seen = onJade(a -> {
            try {
                jade.content.ContentManager cm = a.getContentManager();
                jade.content.lang.sl.SLCodec sl = new jade.content.lang.sl.SLCodec();
                cm.registerLanguage(sl);
                cm.registerOntology(JadeBookTrading.ontology());
                JadeBookTrading.Sell sell = new JadeBookTrading.Sell();
                sell.setItem(JadeBookTrading.book("Dune \"the novel\"", null, null));
                jade.content.onto.basic.Action act = new jade.content.onto.basic.Action(concordAid("bookseller"), sell);
                ACLMessage cfp = new ACLMessage(ACLMessage.CFP);
                cfp.addReceiver(concordAid("bookseller"));
                cfp.setLanguage(sl.getName());
                cfp.setOntology(BookTrading.NAME);
                cfp.setConversationId("bt1");
                cm.fillContent(cfp, act);
                a.send(cfp);
                ACLMessage propose = a.blockingReceive(MessageTemplate.MatchConversationId("bt1"), 30_000);
                if (propose == null || propose.getPerformative() != ACLMessage.PROPOSE) {
                    return "no PROPOSE: " + propose;
                }
                JadeBookTrading.Costs costs = (JadeBookTrading.Costs) cm.extractContent(propose);
                ACLMessage accept = propose.createReply();
                accept.setPerformative(ACLMessage.ACCEPT_PROPOSAL);
                cm.fillContent(accept, act);
                a.send(accept);
                ACLMessage inform = a.blockingReceive(MessageTemplate.MatchConversationId("bt1"), 30_000);
                if (inform == null || inform.getPerformative() != ACLMessage.INFORM) {
                    return "no INFORM: " + inform;
                }
                jade.content.onto.basic.Done done = (jade.content.onto.basic.Done) cm.extractContent(inform);
                jade.content.onto.basic.Action doneAct = (jade.content.onto.basic.Action) done.getAction();
                return costs + " | done " + doneAct.getActor().getName() + " " + doneAct.getAction();
            } catch (Exception e) {
                return "failed: " + e;
            }
        });
        assertEquals("Costs(Book(Dune \"the novel\", [Frank Herbert], null), 17.5) | done bookseller@" + CONCORD
                + " Sell(Book(Dune \"the novel\", null, null))", seen);
        Action cfp = (Action) seller.extracted.poll(5, TimeUnit.SECONDS);
        assertNotNull(cfp);
        assertEquals("bookseller@" + CONCORD, cfp.actor().name());
        assertEquals(new BookTrading.Sell(new BookTrading.Book("Dune \"the novel\"", null, null)), cfp.action());
        Action accepted = (Action) seller.extracted.poll(5, TimeUnit.SECONDS);
        assertNotNull(accepted);
        assertEquals(cfp.action(), accepted.action());
    }

    /** The other way: a Concord buyer with Concord's content manager, a JADE seller with JADE's. */
    @Test
    void aConcordBuyerWithOurSlCodecTradesABookWithAJadeSellerUsingJades() throws Exception {
        jadeMain.createNewAgent("jbookseller", JadeBookSeller.class.getName(), new Object[0]).start();
        io.concord.core.acl.AID seller = new io.concord.core.acl.AID("jbookseller@" + JADE, "http://127.0.0.1:" + jadeHttp + "/acc");
        ContentManager cm = new ContentManager().register(new SlCodec()).register(BookTrading.ontology());
        BookTrading.Book wanted = new BookTrading.Book("The Dispossessed", null, 30.0);
        Action act = new Action(seller, new BookTrading.Sell(wanted));
        AclMessage cfp = new AclMessage(Performative.CFP);
        cfp.addReceiver(seller);
        cfp.setConversationId("bt2");
        cm.fill(cfp, act);
        INBOX.send(cfp);
        AclMessage propose = poll(m -> "bt2".equals(m.getConversationId()));
        assertEquals(Performative.PROPOSE, propose.getPerformative(), propose.getContent());
        assertEquals(new BookTrading.Costs(new BookTrading.Book("The Dispossessed", List.of("Ursula K. Le Guin"), null), 23.25),
                cm.extract(propose));
        AclMessage accept = propose.createReply();
        accept.setPerformative(Performative.ACCEPT_PROPOSAL);
        cm.fill(accept, act);
        INBOX.send(accept);
        AclMessage inform = poll(m -> "bt2".equals(m.getConversationId()));
        assertEquals(Performative.INFORM, inform.getPerformative(), inform.getContent());
        Done done = (Done) cm.extract(inform);
        assertEquals("jbookseller@" + JADE, done.action().actor().name());
        assertEquals(new BookTrading.Sell(wanted), done.action().action());

        for (int i = 0; i < 2; i++) {
            jade.content.onto.basic.Action got = (jade.content.onto.basic.Action) JadeBookSeller.EXTRACTED.poll(5, TimeUnit.SECONDS);
            assertNotNull(got);
            assertEquals("jbookseller@" + JADE, got.getActor().getName());
            assertEquals("Sell(Book(The Dispossessed, null, 30.0))", got.getAction().toString());
        }
    }

    private static int rawStatus(String request) throws Exception {
        try (Socket s = new Socket("127.0.0.1", concordHttp)) {
            s.setSoTimeout(10_000);
            OutputStream o = s.getOutputStream();
            o.write(request.getBytes(StandardCharsets.ISO_8859_1));
            o.flush();
            InputStream in = s.getInputStream();
            String line = new String(in.readNBytes(12), StandardCharsets.ISO_8859_1);
            return Integer.parseInt(line.substring(9, 12));
        }
    }

    private static AclMessage poll(java.util.function.Predicate<AclMessage> p) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (System.nanoTime() < end) {
            AclMessage m = INBOX.got.poll(100, TimeUnit.MILLISECONDS);
            if (m != null && p.test(m)) {
                return m;
            }
        }
        throw new AssertionError("no such message within 30 s");
    }
}
