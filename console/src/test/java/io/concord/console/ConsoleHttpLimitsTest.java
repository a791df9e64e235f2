package io.concord.console;

import io.concord.core.agent.PortRange;
import io.concord.layers.Platform;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.opentest4j.AssertionFailedError;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The console's HTTP server under a client that tries to make it hold what it should not (issue
 * 46), on real sockets: slow requests, too many connections, a huge head, a Host that only starts
 * like loopback's, a GET of an action. The server's clock is injected: a timeout is shown by moving
 * it and sweeping, never by waiting.
 */
class ConsoleHttpLimitsTest {
    static Platform platform;
    static Console plain;
    static final AtomicInteger CONSOLES = new AtomicInteger();
    static final AtomicLong RESUMED = new AtomicLong();
    static final int SLOW = 300;

    /** The hospital's action that issue 46 lost: an operator resumes a held chair. On the agents' loop. */
    static final class Ward implements ConsoleView {
        @Override
        public String id() {
            return "hospital";
        }

        @Override
        public String title() {
            return "Hospital";
        }

        @Override
        public String snapshot() {
            return "{}";
        }

        @Override
        public List<String> actions() {
            return List.of("resume");
        }

        @Override
        public String act(String action, Map<String, String> params) {
            RESUMED.incrementAndGet();
            return params.get("chair") + " may drive again";
        }
    }

    @BeforeAll
    static void start() {
        platform = Platform.builder().name("console-limits").ports(new PortRange(7701, 40, 10)).build();
        platform.startAgent("seller1", new ConsoleHttpTest.Seller());
        plain = console(HttpLoop.Limits.DEFAULT, new AtomicLong());
    }

    @AfterAll
    static void stop() {
        plain.close();
        platform.close();
    }

    /** A console of its own on loopback, with these limits and the clock given. */
    static Console console(HttpLoop.Limits limits, AtomicLong clock) {
        Console c = Console.start(platform, Console.Config.port(0).withAgentName("console-limits-" + CONSOLES.incrementAndGet()),
                limits, clock::get);
        c.addView(new Ward());
        return c;
    }

    /** Writes, and says whether the connection took it (false: the server has closed it). */
    static boolean write(Socket s, String text) {
        try {
            OutputStream o = s.getOutputStream();
            o.write(text.getBytes(StandardCharsets.US_ASCII));
            o.flush();
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    /** The connection is closed by the server: the end of the stream, or a reset, with nothing answered. */
    static void assertClosed(Socket s) throws IOException {
        try {
            assertEquals(-1, s.getInputStream().read(), "a slow connection got an answer instead of being closed");
        } catch (SocketException reset) {
            // closed with bytes of ours unread: reset
        }
    }

    /** Sends a request as written (it should end with Connection: close) and returns the whole answer. */
    static String exchange(Console c, String request) throws IOException {
        try (Socket s = new Socket("127.0.0.1", c.port())) {
            s.setSoTimeout(20_000);   // a failing server fails the test instead of hanging it
            s.getOutputStream().write(request.getBytes(StandardCharsets.ISO_8859_1));
            return new String(s.getInputStream().readAllBytes(), StandardCharsets.ISO_8859_1);
        }
    }

    static String statusLine(String answer) {
        int end = answer.indexOf("\r\n");
        return end < 0 ? answer : answer.substring(0, end);
    }

    /** The agents' loop still turns. */
    static void loopTurns() throws Exception {
        CompletableFuture<Void> turn = new CompletableFuture<>();
        platform.runtime().execute(() -> turn.complete(null));
        turn.get(10, TimeUnit.SECONDS);
    }

    /**
     * {@value #SLOW} slow connections from 127.0.0.1 (half-sent heads, a byte now and then) while a
     * normal request and an action from 127.0.0.1 are answered; then the clock passes the request
     * timeout and a sweep closes every slow one still open. Each slow connection is closed and
     * counted once: by a newer connection at the per-client cap ({@code http-connections}) or by
     * the sweep ({@code http-slow}).
     */
    static void slowConnectionsCannotLockOutTheOperator(HttpLoop.Limits limits) throws Exception {
        AtomicLong clock = new AtomicLong(5_000_000_000L);
        long resumed = RESUMED.get();
        try (Console c = console(limits, clock)) {
            HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();
            String base = "http://127.0.0.1:" + c.port();
            List<Socket> slow = new ArrayList<>();
            try {
                for (int i = 0; i < SLOW; i++) {
                    Socket s = new Socket();
                    s.setSoTimeout(20_000);
                    s.connect(new InetSocketAddress("127.0.0.1", c.port()), 10_000);
                    slow.add(s);
                    write(s, "POST /api/views/hospital/resume HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Concord-Console: 1\r\nX-Slow: ");
                }
                for (int round = 0; round < 3; round++) {
                    for (Socket s : slow) {
                        write(s, "z");   // a byte now and then: it does not make the request any younger
                    }
                }
                loopTurns();
                HttpResponse<String> r;
                try {
                    r = http.send(HttpRequest.newBuilder(URI.create(base + "/api/platform"))
                            .timeout(Duration.ofSeconds(20)).build(), HttpResponse.BodyHandlers.ofString());
                    assertEquals(200, r.statusCode(), r.body());
                    r = http.send(HttpRequest.newBuilder(URI.create(base + "/api/views/hospital/resume")).header("X-Concord-Console", "1")
                            .timeout(Duration.ofSeconds(20)).POST(HttpRequest.BodyPublishers.ofString("chair=chair1")).build(),
                            HttpResponse.BodyHandlers.ofString());
                } catch (IOException e) {
                    throw new AssertionFailedError("the operator's request was not answered: " + e, e);
                }
                assertEquals(200, r.statusCode(), r.body());
                assertTrue(r.body().contains("\"message\":\"chair1 may drive again\""), r.body());
                assertEquals(resumed + 1, RESUMED.get(), "the action ran once, on the agents' loop");
                // The agents unaffected: the console's agent still finds seller1 in the lists and messages it.
                r = http.send(HttpRequest.newBuilder(URI.create(base + "/api/agents/send")).header("X-Concord-Console", "1")
                        .timeout(Duration.ofSeconds(20)).POST(HttpRequest.BodyPublishers.ofString("performative=INFORM&receivers=seller1&content=hi"))
                        .build(), HttpResponse.BodyHandlers.ofString());
                assertEquals(200, r.statusCode(), r.body());
                assertTrue(r.body().contains("sent INFORM to seller1"), r.body());
                loopTurns();

                clock.addAndGet(HttpLoop.Limits.DEFAULT.requestTimeoutNs() + 1_000_000_000L);
                c.server().sweep();
                Map<String, Long> d = c.drops();
                long bySweep = d.getOrDefault("http-slow", 0L);
                long byNewer = d.getOrDefault("http-connections", 0L);
                assertEquals(SLOW, bySweep + byNewer, "every slow connection is closed, by a newer one or by the sweep, and counted: " + d);
                assertTrue(bySweep > 0 && byNewer > 0, d.toString());
                for (Socket s : slow) {
                    assertClosed(s);
                }
                assertTrue(c.server().connections() < 8, "the slow connections are gone: " + c.server().connections() + " open");
                // Afterwards, as before: the console answers and the agents go on.
                r = http.send(HttpRequest.newBuilder(URI.create(base + "/api/views")).timeout(Duration.ofSeconds(20)).build(),
                        HttpResponse.BodyHandlers.ofString());
                assertEquals(200, r.statusCode());
                assertTrue(r.body().contains("\"id\":\"hospital\""), r.body());
                loopTurns();
                assertEquals(0, d.getOrDefault("http-400", 0L) + d.getOrDefault("http-431", 0L), d.toString());
            } finally {
                for (Socket s : slow) {
                    s.close();
                }
            }
        }
    }

    @Test
    void slowConnectionsAreClosedAndTheOperatorIsStillAnswered() throws Exception {
        slowConnectionsCannotLockOutTheOperator(HttpLoop.Limits.DEFAULT);
    }

    /** Without the request timeout, the sweep leaves the slow connections at the cap open: the test above fails. */
    @Test
    void withoutTheRequestTimeoutTheSlowConnectionsStay() {
        AssertionFailedError e = assertThrows(AssertionFailedError.class,
                () -> slowConnectionsCannotLockOutTheOperator(HttpLoop.Limits.DEFAULT.withoutRequestTimeout()));
        assertTrue(e.getMessage().startsWith("every slow connection is closed"), e.getMessage());
    }

    /** If a new connection at the cap were closed instead of the oldest slow one, the operator would be locked out. */
    @Test
    void withoutClosingTheOldestTheOperatorIsLockedOut() {
        AssertionFailedError e = assertThrows(AssertionFailedError.class,
                () -> slowConnectionsCannotLockOutTheOperator(HttpLoop.Limits.DEFAULT.withoutClosingTheOldest()));
        assertTrue(e.getMessage().startsWith("the operator's request was not answered"), e.getMessage());
    }

    @Test
    void theHostMustBeALoopbackNameAndAPortNothingElse() throws Exception {
        long before = plain.drops().getOrDefault("http-403", 0L);
        String[] foreign = {"127.0.0.1:7780@evil.example", "127.0.0.1:evil.example", "evil.example", "localhost.evil.example",
            "127.0.0.1.evil.example", "evil.example:7780", "user@127.0.0.1", "localhost:", "localhost:80:80", "[::1]:80@evil.example",
            "[::1", "127.0.0.1:99999", "localhost/evil", "127.0.0.1 evil.example", ""};
        for (String h : foreign) {
            assertEquals("HTTP/1.1 403 Forbidden", statusLine(exchange(plain,
                    "GET /api/platform HTTP/1.1\r\nHost: " + h + "\r\nConnection: close\r\n\r\n")), h);
        }
        assertEquals("HTTP/1.1 403 Forbidden", statusLine(exchange(plain, "GET /api/platform HTTP/1.1\r\nConnection: close\r\n\r\n")),
                "no Host at all");
        assertEquals(before + foreign.length + 1, plain.drops().get("http-403"));
        String[] loopback = {"127.0.0.1", "127.0.0.1:" + plain.port(), "localhost", "LocalHost:80", "[::1]", "[::1]:7780"};
        for (String h : loopback) {
            assertEquals("HTTP/1.1 200 OK", statusLine(exchange(plain,
                    "GET /api/platform HTTP/1.1\r\nHost: " + h + "\r\nConnection: close\r\n\r\n")), h);
        }
        // The parser alone: a name (or an address) and an optional port.
        assertEquals("example.org", ConsoleServer.hostName("Example.ORG:8080"));
        assertEquals("[2001:db8::1]", ConsoleServer.hostName("[2001:db8::1]:443"));
        assertEquals("10.0.0.7", ConsoleServer.hostName("10.0.0.7"));
        assertNull(ConsoleServer.hostName("a_b.example"));
        assertNull(ConsoleServer.hostName("-a.example"));
        assertNull(ConsoleServer.hostName("10.0.0.7:"));
    }

    /** On a network address any name may be used (the token guards), but a Host must still parse. */
    @Test
    void onANetworkAddressAMalformedHostIsABadRequest() throws Exception {
        try (Console open = Console.start(platform, Console.Config.parse("0.0.0.0:0").withAgentName("console-limits-open"))) {
            String q = "GET /api/platform?token=" + open.token() + " HTTP/1.1\r\nHost: ";
            assertEquals("HTTP/1.1 200 OK", statusLine(exchange(open, q + "console.example:80\r\nConnection: close\r\n\r\n")));
            assertEquals("HTTP/1.1 400 Bad Request", statusLine(exchange(open, q + "127.0.0.1:80@evil.example\r\nConnection: close\r\n\r\n")));
        }
    }

    @Test
    void aWrongMethodOnAKnownPathIs405WithAllow() throws Exception {
        long before = plain.drops().getOrDefault("http-405", 0L);
        int n = 0;
        for (String action : new String[] {"/api/views/hospital/resume", "/api/agents/start", "/api/agents/kill", "/api/agents/send",
            "/api/record/start", "/api/record/stop"}) {
            for (String method : new String[] {"GET", "HEAD"}) {
                String a = exchange(plain, method + " " + action + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
                assertEquals("HTTP/1.1 405 Method Not Allowed", statusLine(a), method + " " + action);
                assertTrue(a.contains("\r\nAllow: POST\r\n"), a);
                n++;
            }
        }
        for (String request : new String[] {"POST /api/platform", "PUT /api/platform", "DELETE /", "POST /api/recordings/x.jsonl"}) {
            String a = exchange(plain, request + " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\nConnection: close\r\n\r\n");
            assertEquals("HTTP/1.1 405 Method Not Allowed", statusLine(a), request);
            assertTrue(a.contains("\r\nAllow: GET, HEAD\r\n"), a);
            n++;
        }
        assertEquals(before + n, plain.drops().get("http-405"));
        // An action or a page there is not: 404, whatever the method.
        assertEquals("HTTP/1.1 404 Not Found", statusLine(exchange(plain,
                "GET /api/views/hospital/explode HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")));
        assertEquals("HTTP/1.1 404 Not Found", statusLine(exchange(plain,
                "PUT /nowhere HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\nConnection: close\r\n\r\n")));
        // HEAD of a page: its headers and its length, no body.
        String head = exchange(plain, "HEAD /api/views HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
        assertEquals("HTTP/1.1 200 OK", statusLine(head));
        assertTrue(head.endsWith("\r\n\r\n") && head.matches("(?s).*\r\nContent-Length: [1-9][0-9]*\r\n.*"), head);
    }

    @Test
    void aHugeHeadIs431AndTheConnectionIsClosed() throws Exception {
        long before = plain.drops().getOrDefault("http-431", 0L);
        try (Socket s = new Socket("127.0.0.1", plain.port())) {
            s.setSoTimeout(20_000);
            s.getOutputStream().write(("GET /api/platform HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Pad: " + "a".repeat(200 * 1024) + "\r\n\r\n")
                    .getBytes(StandardCharsets.US_ASCII));
            InputStream in = s.getInputStream();
            ByteArrayOutputStream answer = new ByteArrayOutputStream();
            int b;
            while ((b = in.read()) >= 0) {   // to the end: the server closes the connection
                answer.write(b);
            }
            String a = answer.toString(StandardCharsets.ISO_8859_1);
            assertEquals("HTTP/1.1 431 Request Header Fields Too Large", statusLine(a));
            assertTrue(a.contains("longer than 16384 bytes"), a);
            assertTrue(a.contains("\r\nConnection: close\r\n"), a);
        }
        assertEquals(before + 1, plain.drops().get("http-431"));
        // A body over 4 KiB is refused on its announced length, before it comes.
        String a = exchange(plain, "POST /api/views/hospital/resume HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Concord-Console: 1\r\n"
                + "Content-Length: 5000\r\nConnection: close\r\n\r\n");
        assertEquals("HTTP/1.1 413 Payload Too Large", statusLine(a));
        assertEquals("HTTP/1.1 200 OK", statusLine(exchange(plain, "GET /api/platform HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")));
    }

    /**
     * A browser that asks for an event stream and stops reading holds a worker only until the
     * write timeout: the sweep closes it (counted {@code http-slow-reader}) and the worker and
     * the stream's place are given back.
     */
    @Test
    void aClientThatDoesNotReadItsAnswerIsClosedAfterTheWriteTimeout() throws Exception {
        AtomicLong clock = new AtomicLong(-7_000_000_000L);   // System.nanoTime may be negative too
        try (Console c = console(HttpLoop.Limits.DEFAULT, clock); Socket stuck = new Socket()) {
            c.addView(new ConsoleHttpTest.BigView());
            stuck.setReceiveBufferSize(4096);
            stuck.connect(new InetSocketAddress("127.0.0.1", c.port()));
            write(stuck, "GET /api/events?topics=view-big HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
            while (c.drops().get("console-slow-client") == 0) {
                loopTurns();   // the stream's worker waits for the client; the events pile up for it alone
                Thread.onSpinWait();
            }
            assertEquals(1, c.browsers());
            c.server().sweep();
            assertEquals(0L, c.drops().getOrDefault("http-slow-reader", 0L), "not before its time");
            clock.addAndGet(HttpLoop.Limits.DEFAULT.writeTimeoutNs() + 1_000_000_000L);
            c.server().sweep();
            assertEquals(1L, c.drops().get("http-slow-reader"), c.drops().toString());
            while (c.browsers() > 0) {
                Thread.onSpinWait();   // the worker sees its connection closed and leaves the hub
            }
            assertEquals(0, c.server().connections());
        }
    }
    /**
     * At the total cap, a new connection from another address closes the oldest unfinished
     * request whatever its address; the rest go when their time is up.
     */
    @Test
    void atTheTotalCapANewConnectionClosesAnUnfinishedRequestOfAnyAddress() throws Exception {
        HttpLoop.Limits small = new HttpLoop.Limits(16 * 1024, 4096, 2048, 10_000_000_000L, 30_000_000_000L, 30_000_000_000L, 8, 4, true);
        AtomicLong clock = new AtomicLong();
        try (Console c = console(small, clock)) {
            List<Socket> slow = new ArrayList<>();
            try {
                for (String from : new String[] {"127.0.0.2", "127.0.0.3"}) {   // all of 127/8 is loopback
                    for (int i = 0; i < 4; i++) {
                        Socket s = new Socket();
                        s.setSoTimeout(20_000);
                        s.bind(new InetSocketAddress(from, 0));
                        s.connect(new InetSocketAddress("127.0.0.1", c.port()), 10_000);
                        slow.add(s);
                        assertTrue(write(s, "GET /api/platform HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: "));
                    }
                }
                assertEquals("HTTP/1.1 200 OK", statusLine(exchange(c, "GET /api/platform HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                        + "Connection: close\r\n\r\n")));
                assertEquals(1L, c.drops().get("http-connections"), c.drops().toString());
                clock.addAndGet(9_000_000_000L);
                c.server().sweep();
                assertEquals(0L, c.drops().getOrDefault("http-slow", 0L), "not before its time: " + c.drops());
                clock.addAndGet(2_000_000_000L);
                c.server().sweep();
                assertEquals(7L, c.drops().get("http-slow"), c.drops().toString());
                for (Socket s : slow) {
                    assertClosed(s);
                }
                assertEquals(0, c.server().connections());
            } finally {
                for (Socket s : slow) {
                    s.close();
                }
            }
        }
    }

    /** A kept-alive connection serves request after request (two sent at once too), and closes, uncounted, once idle 30 s. */
    @Test
    void aKeptAliveConnectionServesRequestsAndClosesWhenIdle() throws Exception {
        AtomicLong clock = new AtomicLong();
        try (Console c = console(HttpLoop.Limits.DEFAULT, clock); Socket s = new Socket("127.0.0.1", c.port())) {
            s.setSoTimeout(20_000);
            Map<String, Long> before = c.drops();
            assertTrue(write(s, "GET /api/views HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\nGET /api/platform HTTP/1.1\r\nHost: localhost\r\n\r\n"));
            InputStream in = s.getInputStream();
            assertEquals("HTTP/1.1 200 OK", statusLine(readAnswer(in)));
            assertEquals("HTTP/1.1 200 OK", statusLine(readAnswer(in)));
            clock.addAndGet(29_000_000_000L);
            c.server().sweep();
            assertTrue(write(s, "GET /api/views HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"));
            assertTrue(readAnswer(in).contains("\"id\":\"hospital\""));
            clock.addAndGet(31_000_000_000L);
            c.server().sweep();
            assertEquals(-1, in.read(), "closed once idle");
            assertEquals(before, c.drops(), "an idle connection closed is housekeeping, not a refusal");
        }
    }

    /** One answer with a Content-Length, read from the stream. */
    static String readAnswer(InputStream in) throws IOException {
        ByteArrayOutputStream head = new ByteArrayOutputStream();
        while (!head.toString(StandardCharsets.ISO_8859_1).endsWith("\r\n\r\n")) {
            int b = in.read();
            if (b < 0) {
                throw new AssertionFailedError("the connection closed in an answer's head: " + head);
            }
            head.write(b);
        }
        String h = head.toString(StandardCharsets.ISO_8859_1);
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\r\nContent-Length: ([0-9]+)\r\n").matcher(h);
        assertTrue(m.find(), h);
        return h + new String(in.readNBytes(Integer.parseInt(m.group(1))), StandardCharsets.UTF_8);
    }
}
