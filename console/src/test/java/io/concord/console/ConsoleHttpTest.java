package io.concord.console;

import io.concord.core.agent.Agent;
import io.concord.core.agent.PortRange;
import io.concord.layers.Platform;
import io.concord.layers.platform.ServiceDescription;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.io.BufferedReader;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The console's HTTP side on real sockets: what it serves, what it refuses, and that no browser can hold the agents up. */
class ConsoleHttpTest {
    static Platform platform;
    static Console console;
    static final HttpClient HTTP = HttpClient.newHttpClient();

    /** Offers a service; does nothing else. */
    static final class Seller extends Agent {
        @Override
        protected void setup() {
            Platform.of(this).register(ServiceDescription.of("book-selling", getLocalName()));
        }
    }

    @BeforeAll
    static void start() {
        platform = Platform.builder().name("console-http").ports(new PortRange(7401, 60, 10)).build();
        platform.startAgent("seller1", new Seller());
        platform.startAgent("seller2", new Seller());
        console = Console.start(platform, Console.Config.port(0).withReports(java.nio.file.Path.of("..", "bench", "report")));
    }

    @AfterAll
    static void stop() {
        platform.close();
        console.close();
    }

    static HttpResponse<String> get(String pathAndQuery) throws Exception {
        return HTTP.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + console.port() + pathAndQuery)).build(),
                HttpResponse.BodyHandlers.ofString());
    }

    /** Reads an event stream until a platform event lists every name given. */
    static String awaitPlatform(String query, String... names) throws Exception {
        HttpResponse<InputStream> r = HTTP.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + console.port()
                + "/api/events" + query)).build(), HttpResponse.BodyHandlers.ofInputStream());
        assertEquals(200, r.statusCode());
        try (BufferedReader in = new BufferedReader(new InputStreamReader(r.body(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                if (line.startsWith("data: ")) {
                    boolean all = true;
                    for (String n : names) {
                        all &= line.contains("\"name\":\"" + n + "\"");
                    }
                    if (all) {
                        return line.substring(6);
                    }
                }
            }
        }
        throw new AssertionError("the stream ended");
    }

    @Test
    void theEventStreamListsTheAgentsTheirServicesAndTheContainer() throws Exception {
        String p = awaitPlatform("?topics=platform", "seller1@console-http", "seller2@console-http", "console@console-http");
        assertTrue(p.contains("{\"type\":\"book-selling\",\"name\":\"seller1\"}"), p);
        assertTrue(p.matches(".*\"container\":\"[a-z0-9]+@console-http\",\"term\":[0-9]+.*"), p);
        assertEquals(200, get("/api/platform").statusCode());
        HttpResponse<String> page = get("/");
        assertEquals(200, page.statusCode());
        assertTrue(page.body().contains("<title>Concord console</title>"));
        assertTrue(get("/app.js").body().contains("EventSource"));
    }

    @Test
    void badRequestsGetAClear4xx() throws Exception {
        HttpResponse<String> r = get("/nowhere");
        assertEquals(404, r.statusCode());
        assertTrue(r.body().contains("no such page: /nowhere"), r.body());
        r = get("/api/events?topics=platform,gossip");
        assertEquals(400, r.statusCode());
        assertTrue(r.body().contains("no such topic 'gossip'"), r.body());
        r = get("/api/events?topics=platform&topics=safety");
        assertEquals(400, r.statusCode());
        assertTrue(r.body().contains("'topics' given twice"), r.body());
        assertEquals("HTTP/1.1 400 Bad Request", raw("GET /api/events?topics=%zz HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n"));
        assertEquals(414, get("/api/platform?x=" + "a".repeat(3_000)).statusCode());
        r = get("/api/bench/..%2Fpom.xml");
        assertTrue(r.statusCode() == 400 || r.statusCode() == 404, r.statusCode() + " " + r.body());
        assertEquals(404, get("/api/bench/nothing.md").statusCode());
        // The one write: only a view's action, with the page's header, small.
        HttpResponse<String> post = HTTP.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + console.port() + "/api/views/x/y"))
                .POST(HttpRequest.BodyPublishers.ofString("a=1")).build(), HttpResponse.BodyHandlers.ofString());
        assertEquals(403, post.statusCode());
        post = HTTP.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + console.port() + "/api/views/x/y"))
                .header("X-Concord-Console", "1").POST(HttpRequest.BodyPublishers.ofString("a=1")).build(), HttpResponse.BodyHandlers.ofString());
        assertEquals(404, post.statusCode());
        assertTrue(console.drops().get("http-404") >= 2, console.drops().toString());
        // The console's own writes: the same header; a start, kill or recording that cannot be says why.
        assertEquals(403, post("/api/agents/kill", "agent=x", false).statusCode());
        assertEquals(403, post("/api/record/start", "", false).statusCode());
        r = post("/api/agents/kill", "agent=nobody", true);
        assertEquals(400, r.statusCode());
        assertTrue(r.body().contains("no agent nobody in the platform's lists"), r.body());
        r = post("/api/agents/start", "name=x&class=java.lang.String", true);
        assertEquals(400, r.statusCode());
        assertTrue(r.body().contains("java.lang.String is not an agent"), r.body());
        // The DF and the AMS, by local or full name, as JADE's DummyAgent reaches them: answered into the mail.
        r = post("/api/agents/send", "performative=REQUEST&receivers=ams&content=agents&conversation=to-ams", true);
        assertEquals(200, r.statusCode(), r.body());
        r = post("/api/agents/send", "performative=REQUEST&receivers=df@console-http&content=search+template%3Dt%3Dnothing&conversation=to-df", true);
        assertEquals(200, r.statusCode(), r.body());
        for (int i = 0; i < 2_000 && !(answered("to-ams") && answered("to-df")); i++) {
            Thread.sleep(10);   // a poll of the mail the console shows, until both answers are in
        }
        assertTrue(answered("to-ams") && answered("to-df"), "the DF and the AMS answered: " + get("/api/mail").body());
        r = post("/api/agents/send", "performative=SHOUT&receivers=x", true);
        assertEquals(400, r.statusCode());
        assertTrue(r.body().contains("no performative 'SHOUT'"), r.body());
        r = post("/api/record/start", "name=../../etc/passwd.jsonl", true);
        assertEquals(400, r.statusCode());
        assertTrue(r.body().contains("ending in .jsonl"), r.body());
        assertEquals(400, get("/api/recordings/..%2Fpom.xml").statusCode());
        assertEquals(404, get("/api/recordings/none.jsonl").statusCode());
        assertEquals(404, post("/api/agents/explode", "", true).statusCode());
    }

    /** Whether the console's mail holds an answer received in that conversation. */
    private static boolean answered(String conversation) throws Exception {
        com.fasterxml.jackson.databind.JsonNode mail = new com.fasterxml.jackson.databind.ObjectMapper().readTree(get("/api/mail").body());
        if (mail == null || !mail.isArray()) {
            return false;
        }
        for (com.fasterxml.jackson.databind.JsonNode e : mail) {
            if (e.path("dir").asText().equals("received") && e.path("conversation").asText().equals(conversation)) {
                return true;
            }
        }
        return false;
    }

    private static HttpResponse<String> post(String path, String form, boolean header) throws Exception {
        HttpRequest.Builder b = HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + console.port() + path))
                .POST(HttpRequest.BodyPublishers.ofString(form));
        if (header) {
            b.header("X-Concord-Console", "1");
        }
        return HTTP.send(b.build(), HttpResponse.BodyHandlers.ofString());
    }

    /** Sends a request as written; returns the status line. */
    static String raw(String request) throws Exception {
        try (Socket s = new Socket("127.0.0.1", console.port())) {
            OutputStream o = s.getOutputStream();
            o.write(request.getBytes(StandardCharsets.US_ASCII));
            o.flush();
            return new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.US_ASCII)).readLine();
        }
    }

    @Test
    void onLoopbackAnotherSitesNameIsRefused() throws Exception {
        // DNS rebinding: a page of evil.example resolved to 127.0.0.1 sends Host: evil.example.
        assertEquals("HTTP/1.1 403 Forbidden", raw("GET /api/platform HTTP/1.1\r\nHost: evil.example\r\nConnection: close\r\n\r\n"));
        assertEquals("HTTP/1.1 200 OK", raw("GET /api/platform HTTP/1.1\r\nHost: localhost:1\r\nConnection: close\r\n\r\n"));
    }

    @Test
    void onANetworkAddressEveryRequestNeedsTheToken() throws Exception {
        try (Console open = Console.start(platform, Console.Config.parse("0.0.0.0:0").withAgentName("console-open"))) {
            assertNotNull(open.token());
            String base = "http://127.0.0.1:" + open.port();
            for (String path : new String[] {"/", "/api/platform", "/api/events", "/app.js"}) {
                HttpResponse<String> r = HTTP.send(HttpRequest.newBuilder(URI.create(base + path)).build(), HttpResponse.BodyHandlers.ofString());
                assertEquals(401, r.statusCode(), path);
            }
            HttpResponse<String> wrong = HTTP.send(HttpRequest.newBuilder(URI.create(base + "/api/platform?token=" + "0".repeat(32))).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertEquals(401, wrong.statusCode());
            assertEquals(200, HTTP.send(HttpRequest.newBuilder(URI.create(base + "/api/platform?token=" + open.token())).build(),
                    HttpResponse.BodyHandlers.ofString()).statusCode());
            assertEquals(200, HTTP.send(HttpRequest.newBuilder(URI.create(base + "/api/platform"))
                    .header("Authorization", "Bearer " + open.token()).build(), HttpResponse.BodyHandlers.ofString()).statusCode());
            assertTrue(open.uri().endsWith("?token=" + open.token()));
        }
    }

    /** A view whose every snapshot is a megabyte: what a browser that stopped reading would pile up. */
    static final class BigView implements ConsoleView {
        @Override
        public String id() {
            return "big";
        }

        @Override
        public String title() {
            return "Big";
        }

        @Override
        public long periodMs() {
            return 0;
        }

        @Override
        public String snapshot() {
            return "{\"pad\":\"" + "x".repeat(1 << 20) + "\"}";
        }
    }

    /**
     * A browser that never reads: its events are dropped for it alone and counted, and the agents
     * go on (the loop turns, another browser still gets its events).
     */
    @Test
    void aBrowserThatStopsReadingNeverHoldsTheAgentsUp() throws Exception {
        console.addView(new BigView());
        try (Socket stuck = new Socket()) {
            stuck.setReceiveBufferSize(4096);
            stuck.connect(new java.net.InetSocketAddress("127.0.0.1", console.port()));
            stuck.getOutputStream().write(("GET /api/events?topics=view-big HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
                    .getBytes(StandardCharsets.US_ASCII));
            while (console.drops().get("console-slow-client") == 0) {
                CompletableFuture<Void> turn = new CompletableFuture<>();
                platform.runtime().execute(() -> turn.complete(null));
                turn.get(10, TimeUnit.SECONDS);   // the loop still turns
                Thread.onSpinWait();
            }
            assertTrue(console.drops().get("console-slow-client") > 0, console.drops().toString());
            awaitPlatform("?topics=platform", "seller1@console-http");   // another browser still gets its events
        }
    }
}
