package io.concord.jade;

import io.concord.core.acl.AID;
import io.concord.core.agent.AgentRuntime;
import io.concord.layers.Platform;
import io.concord.layers.Profile;
import io.concord.layers.defence.Defence;
import io.concord.layers.observe.ObserverLayer;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.platform.Role;
import io.concord.core.agent.PortRange;
import io.concord.testkit.EchoAgent;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The authority table's rows for an agent of another platform, over the real HTTP MTP: a JADE-style
 * POST from {@code killer@elsewhere}, whose ACC is this test's own little HTTP server, where the
 * platform's answers arrive. Each refusal is shown to be the policy's by the same attack succeeding
 * on a platform built without the {@link Defence#AUTHORITY} defence.
 */
class ForeignAuthorityTest {
    private static final String BOUNDARY = "7b446481f5ae2c17c233efb80dd6246";

    private Platform platform;
    private ServerSocket acc;
    private Thread accThread;
    private final BlockingQueue<String> answers = new LinkedBlockingQueue<>();
    private int httpPort;
    private volatile HttpMtp mtp;

    /** The foreign platform's ACC: takes every POST, keeps its body, answers 200. */
    private String foreignAcc() throws IOException {
        acc = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        accThread = new Thread(() -> {
            while (!acc.isClosed()) {
                try (Socket s = acc.accept()) {
                    s.setSoTimeout(10_000);
                    InputStream in = s.getInputStream();
                    StringBuilder head = new StringBuilder();
                    int c;
                    while ((c = in.read()) >= 0) {
                        head.append((char) c);
                        if (head.toString().endsWith("\r\n\r\n")) {
                            break;
                        }
                    }
                    String h = head.toString().toLowerCase();
                    int at = h.indexOf("content-length:");
                    int n = at < 0 ? 0 : Integer.parseInt(h.substring(at + 15, h.indexOf('\r', at)).trim());
                    answers.add(new String(in.readNBytes(n), StandardCharsets.ISO_8859_1));
                    OutputStream o = s.getOutputStream();
                    o.write("HTTP/1.1 200 OK\r\nContent-Length: 0\r\nConnection: close\r\n\r\n".getBytes(StandardCharsets.US_ASCII));
                    o.flush();
                } catch (IOException e) {
                    // closed, or a client gone: the next one
                }
            }
        }, "foreign-acc");
        accThread.setDaemon(true);
        accThread.start();
        return "http://127.0.0.1:" + acc.getLocalPort() + "/acc";
    }

    /** A platform of one echo agent (container at once) serving the ACC, built by {@code b}. */
    private void start(String name, Consumer<Platform.Builder> b) throws Exception {
        httpPort = JadeBridgeTest.freePort();
        int p = httpPort;
        Platform.Builder builder = Platform.builder().name(name).ports(PortRange.parse("7841-7859")).profile(Profile.CLOSED)
                .gateway(() -> {
                    HttpMtp m = new HttpMtp("127.0.0.1", p);
                    mtp = m;
                    return m;
                });
        b.accept(builder);
        platform = builder.build();
        platform.startAgent("echo", new EchoAgent());
        CompletableFuture<Void> container = new CompletableFuture<>();
        platform.runtime().execute(() -> {
            ContainerLayer l = Platform.containerLayer(platform.runtime(), AID.local("echo", name));
            Consumer<ContainerLayer> check = x -> {
                if (x.role() == Role.CONTAINER) {
                    container.complete(null);
                }
            };
            l.addListener(check);
            check.accept(l);
        });
        container.get(20, TimeUnit.SECONDS);
    }

    @AfterEach
    void stop() throws IOException {
        if (platform != null) {
            platform.close();
        }
        if (acc != null) {
            acc.close();
        }
    }

    /** POSTs a JADE agent's message (its ACL string) to echo, and returns the ACC's HTTP status. */
    private int post(String receiver, String performative, String ontology, String content, String replyTo) throws Exception {
        String acl = "(" + performative + "\n :sender  ( agent-identifier :name killer@elsewhere  :addresses (sequence " + replyTo + " ))\n"
                + " :receiver  (set ( agent-identifier :name " + receiver + " ) )\n :content  \"" + content + "\"\n"
                + (ontology == null ? "" : " :ontology  " + ontology + "\n") + " :conversation-id  c1 )";
        String env = "<?xml version=\"1.0\"?>\n<envelope><params index=\"1\"><to><agent-identifier><name>" + receiver + "</name>"
                + "</agent-identifier></to><from><agent-identifier><name>killer@elsewhere</name><addresses><url>" + replyTo
                + "</url></addresses></agent-identifier></from><acl-representation>fipa.acl.rep.string.std</acl-representation>"
                + "<payload-length>" + acl.length() + "</payload-length><date>20261121Z080444961</date><intended-receiver>"
                + "<agent-identifier><name>" + receiver + "</name></agent-identifier></intended-receiver></params></envelope>";
        String body = "This is not part of the MIME multipart encoded message.\r\n--" + BOUNDARY + "\r\nContent-Type: application/xml\r\n\r\n"
                + env + "\r\n--" + BOUNDARY + "\r\nContent-Type: application/text\r\n\r\n" + acl + "\r\n--" + BOUNDARY + "--\r\n";
        HttpClient c = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
        HttpRequest post = HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + httpPort + "/acc"))
                .header("Content-Type", "multipart/mixed ; boundary=\"" + BOUNDARY + "\"")
                .POST(HttpRequest.BodyPublishers.ofString(body)).build();
        return c.send(post, HttpResponse.BodyHandlers.discarding()).statusCode();
    }

    /** The next message the platform posted to the foreign ACC: its ACL payload. */
    private String answer() throws InterruptedException {
        String a = answers.poll(20, TimeUnit.SECONDS);
        assertNotNull(a, "the platform answered the foreign agent");
        return a;
    }

    private <T> T onLoop(java.util.function.Function<AgentRuntime, T> f) throws Exception {
        CompletableFuture<T> r = new CompletableFuture<>();
        platform.runtime().execute(() -> r.complete(f.apply(platform.runtime())));
        return r.get(10, TimeUnit.SECONDS);
    }

    private boolean echoRuns(String name) throws Exception {
        return onLoop(rt -> rt.agents().contains(AID.local("echo", name)));
    }

    private long notAuthorized() throws Exception {
        return onLoop(rt -> mtp.drops().getOrDefault("not-authorized", 0L) + rt.drops().getOrDefault("not-authorized", 0L));
    }

    @Test
    void aForeignAgentKillsNoAgentSniffsNoneAsksNoStatusAndSpeaksNoPlatformWords() throws Exception {
        String me = foreignAcc();
        start("authplat", b -> { });
        long before = notAuthorized();

        assertEquals(200, post("echo@authplat", "REQUEST", "concord-observe", "kill", me));
        String a = answer();
        assertTrue(a.contains("(REFUSE") && a.contains("may not use observation: REQUEST kill"), a);
        assertTrue(echoRuns("authplat"), "the agent is still on the platform");

        assertEquals(200, post("echo@authplat", "SUBSCRIBE", "concord-observe", "sniff", me));
        a = answer();
        assertTrue(a.contains("(REFUSE") && a.contains("SUBSCRIBE sniff") && a.contains("-http-expose sniff"), a);
        assertEquals(0, (int) onLoop(rt -> rt.layer(AID.local("echo", "authplat"), ObserverLayer.class).sniffers()));

        assertEquals(200, post("echo@authplat", "QUERY-REF", "concord-observe", "status", me));
        a = answer();
        assertTrue(a.contains("(REFUSE") && a.contains("QUERY-REF status"), a);

        assertEquals(200, post("echo@authplat", "INFORM", "concord-services", "(relay-in x)", me));
        a = answer();
        assertTrue(a.contains("(REFUSE") && a.contains("may not use platform messages"), a);
        assertEquals(4, notAuthorized() - before, "each refusal counted");

        // What a JADE agent needs still works: its own conversation with the agent.
        assertEquals(200, post("echo@authplat", "REQUEST", null, "ping", me));
        a = answer();
        assertTrue(a.contains("(INFORM") && a.contains("echo:ping"), a);
    }

    @Test
    void withoutTheAuthorityDefenceAForeignAgentKillsTheContainer() throws Exception {
        String me = foreignAcc();
        start("authoff", b -> b.withoutDefences(Defence.AUTHORITY));
        assertEquals(200, post("echo@authoff", "SUBSCRIBE", "concord-observe", "sniff", me));
        String agreed = answer();
        assertTrue(agreed.contains("(AGREE") && agreed.contains("lease-ms"), agreed);
        assertEquals(1, (int) onLoop(rt -> rt.layer(AID.local("echo", "authoff"), ObserverLayer.class).sniffers()),
                "the hazard: a stranger sniffs the agent");
        assertEquals(200, post("echo@authoff", "QUERY-REF", "concord-observe", "status", me));
        String status = answers.poll(20, TimeUnit.SECONDS);
        while (status != null && !(status.contains("(INFORM") && status.contains("pid") && status.contains("drops"))) {
            status = answers.poll(20, TimeUnit.SECONDS);   // sniffed events come too: the status answer is among them
        }
        assertNotNull(status, "the hazard: a stranger reads the agent's status");
        assertEquals(200, post("echo@authoff", "REQUEST", "concord-observe", "kill", me));
        // The agent leaves (the AGREE it sent may go down with its gateway): wait for that event, 20 s at most.
        long end = System.nanoTime() + 20_000_000_000L;
        while (echoRuns("authoff") && System.nanoTime() < end) {
            Thread.sleep(10);
        }
        assertTrue(!echoRuns("authoff"), "the hazard: a stranger killed the container");
    }

    @Test
    void anOperatorMayExposeTheStatusToAgentsOfOtherPlatformsAndNothingElse() throws Exception {
        String me = foreignAcc();
        start("authexp", b -> b.httpExpose("status"));
        assertEquals(200, post("echo@authexp", "QUERY-REF", "concord-observe", "status", me));
        String a = answer();
        assertTrue(a.contains("(INFORM") && a.contains("role"), a);
        assertEquals(200, post("echo@authexp", "REQUEST", "concord-observe", "kill", me));
        a = answer();
        assertTrue(a.contains("(REFUSE"), a);
        assertTrue(echoRuns("authexp"));
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> Platform.builder().httpExpose("resume"));
        assertTrue(e.getMessage().contains("resume cannot be exposed"), e.getMessage());
    }
}
