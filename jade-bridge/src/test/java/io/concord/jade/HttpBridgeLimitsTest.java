package io.concord.jade;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.GatewayContext;
import io.concord.layers.platform.ServiceDescription;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Hole 6 in the HTTP bridge: everything a client can make the ACC hold or do is bounded, each
 * limit counted with its reason, and a real request still gets through a flood. Real sockets; the
 * server's clock is injected, so time limits are shown by moving it, not by waiting.
 */
class HttpBridgeLimitsTest {
    private static final String BOUNDARY = "7b446481f5ae2c17c233efb80dd6246";
    /** A port nothing listens on: where the bridge's answers to the test's requests go. */
    private static final String DEAD = "http://127.0.0.1:9/acc";

    private final AtomicLong clock = new AtomicLong(1_000_000_000L);
    private final List<AclMessage> delivered = new CopyOnWriteArrayList<>();
    private final List<AclMessage> failures = new CopyOnWriteArrayList<>();
    private final List<Socket> sockets = new ArrayList<>();
    private HttpMtp mtp;

    /** A platform of no agents whose loop is the caller's thread. */
    private final GatewayContext context = new GatewayContext() {
        @Override
        public String platformName() {
            return "ourplat";
        }

        @Override
        public void execute(Runnable task) {
            task.run();
        }

        @Override
        public boolean deliver(AclMessage message, AID receiver) {
            if (message.getPerformative() == Performative.FAILURE) {
                failures.add(message);
            }
            if (!receiver.localName().equals("echo")) {
                return false;
            }
            delivered.add(message);
            return true;
        }

        @Override
        public List<AgentEntry> search(List<ServiceDescription> templates) {
            return List.of();
        }

        @Override
        public List<AgentEntry> agents() {
            return List.of();
        }
    };

    private HttpMtp start(int maxConnections) {
        mtp = new HttpMtp("127.0.0.1", 0, "127.0.0.1",
                new AccServer.Limits(maxConnections, 16 * 1024, HttpMtp.MAX_BODY, 10_000_000_000L, 120_000_000_000L),
                new io.concord.core.time.Clock() {
                    // The server's thread reads the time the test's thread moves: an AtomicLong, not a ManualClock.
                    @Override
                    public long nanoTime() {
                        return clock.get();
                    }

                    @Override
                    public long epochMillis() {
                        return io.concord.core.time.ManualClock.DEFAULT_EPOCH_MS + clock.get() / 1_000_000;
                    }
                });
        mtp.start(context);
        return mtp;
    }

    @AfterEach
    void stop() throws IOException {
        for (Socket s : sockets) {
            s.close();
        }
        if (mtp != null) {
            mtp.stop();
        }
    }

    private Socket connect() throws IOException {
        Socket s = new Socket();
        s.connect(new InetSocketAddress("127.0.0.1", mtp.boundPort()), 5_000);
        s.setSoTimeout(30_000);
        sockets.add(s);
        return s;
    }

    /** JADE's request to {@code receiver@testplat}, from a JADE agent whose ACC is {@link #DEAD}. */
    private static String body(String receiver) {
        return WireTest.JADE_BODY.replace("bob@foreignplat", receiver + "@ourplat").replace("http://127.0.0.1:7778/acc", DEAD);
    }

    private static byte[] request(String body) {
        byte[] b = body.getBytes(StandardCharsets.ISO_8859_1);
        String head = "POST /acc HTTP/1.1\r\nContent-Type: multipart/mixed ; boundary=\"" + BOUNDARY + "\"\r\nContent-Length: "
                + b.length + "\r\nConnection: Keep-Alive\r\n\r\n";
        byte[] all = new byte[head.length() + b.length];
        System.arraycopy(head.getBytes(StandardCharsets.US_ASCII), 0, all, 0, head.length());
        System.arraycopy(b, 0, all, head.length(), b.length);
        return all;
    }

    /** Writes the bytes and reads one response: its status line and body. */
    private static String exchange(Socket s, byte[] bytes) throws IOException {
        OutputStream o = s.getOutputStream();
        o.write(bytes);
        o.flush();
        return readResponse(s.getInputStream());
    }

    private static String readResponse(InputStream in) throws IOException {
        StringBuilder head = new StringBuilder();
        int c;
        while ((c = in.read()) >= 0) {
            head.append((char) c);
            if (head.length() >= 4 && head.substring(head.length() - 4).equals("\r\n\r\n")) {
                break;
            }
        }
        String h = head.toString();
        int at = h.toLowerCase().indexOf("content-length: ");
        int n = at < 0 ? 0 : Integer.parseInt(h.substring(at + 16, h.indexOf('\r', at)).trim());
        String body = new String(in.readNBytes(n), StandardCharsets.UTF_8);
        return h.substring(0, Math.max(0, h.indexOf('\r'))) + " " + body.trim();
    }

    private static void assertOk(String response, String... why) {
        assertTrue(response.startsWith("HTTP/1.1 200"), (why.length > 0 ? why[0] + ": " : "") + response);
    }

    private long drops(String reason) {
        return mtp.drops().getOrDefault(reason, 0L);
    }

    @Test
    void connectionsBeyondTheLimitCloseTheSlowestAndARealRequestStillGetsThrough() throws Exception {
        start(32);
        for (int i = 0; i < 100; i++) {
            Socket s = connect();
            // Half stop inside the head; half announce a 1 MiB body and send 10 bytes of it.
            String partial = i % 2 == 0 ? "POST /acc HTTP/1.1\r\nContent-Ty"
                    : "POST /acc HTTP/1.1\r\nContent-Type: multipart/mixed; boundary=b\r\nContent-Length: 1048576\r\n\r\n0123456789";
            s.getOutputStream().write(partial.getBytes(StandardCharsets.US_ASCII));
        }
        Socket real = connect();
        assertOk(exchange(real, request(body("echo"))), "the real request is answered");
        mtp.server().sweep().get(10, TimeUnit.SECONDS);
        assertEquals(1, delivered.size(), "and delivered");
        assertEquals(32, mtp.server().open(), "no more connections than the limit are held");
        assertEquals(101 - 32, drops("http-connections"), "each connection closed for the limit is counted");
        assertTrue(mtp.server().buffered() <= 32 * 1024, "an announced 1 MiB body holds only what arrived: "
                + mtp.server().buffered() + " bytes held");
        assertOk(exchange(real, request(body("echo"))), "the real client's kept-alive connection was not the one closed");
    }

    @Test
    void aRequestThatDoesNotArriveWholeInTimeIsClosedAndCounted() throws Exception {
        start(256);
        Socket kept = connect();
        assertOk(exchange(kept, request(body("echo"))));
        List<Socket> slow = new ArrayList<>();
        for (int i = 0; i < 10; i++) {
            Socket s = connect();
            s.getOutputStream().write(("POST /acc HTTP/1.1\r\nContent-Length: 100\r\n\r\n" + "x".repeat(i)).getBytes(StandardCharsets.US_ASCII));
            s.getOutputStream().flush();
            slow.add(s);
        }
        // Every slow request is under way on the server before the clock moves (the server may
        // accept a connection in one turn and read its bytes in a later one).
        for (int i = 0; i < 10_000 && mtp.server().underWay() < 10; i++) {
            mtp.server().sweep().get(10, TimeUnit.SECONDS);
        }
        assertEquals(10, mtp.server().underWay());
        assertOk(exchange(kept, request(body("echo"))));
        mtp.server().sweep().get(10, TimeUnit.SECONDS);
        assertEquals(11, mtp.server().open());
        clock.addAndGet(10_500_000_000L);
        mtp.server().sweep().get(10, TimeUnit.SECONDS);
        assertEquals(10, drops("http-slow"), "each request that took longer than 10 s is counted");
        assertEquals(1, mtp.server().open(), "the idle kept-alive connection stays: it owes nothing");
        for (Socket s : slow) {
            assertEquals(-1, s.getInputStream().read(), "the slow connection is closed");
        }
        assertOk(exchange(kept, request(body("echo"))));
    }

    @Test
    void whatTheAccCannotTakeGetsAClear4xxBeforeItIsRead() throws Exception {
        start(256);
        assertEquals("HTTP/1.1 413 Payload Too Large the request announces 2147483648 bytes; the ACC takes at most 1048576",
                exchange(connect(), "POST /acc HTTP/1.1\r\nContent-Length: 2147483648\r\n\r\n".getBytes(StandardCharsets.US_ASCII)));
        assertEquals("HTTP/1.1 431 Request Header Fields Too Large the request's head is longer than 16384 bytes",
                exchange(connect(), ("POST /acc HTTP/1.1\r\nX: " + "y".repeat(20_000)).getBytes(StandardCharsets.US_ASCII)));
        assertEquals("HTTP/1.1 411 Length Required a chunked request is not accepted; send its Content-Length",
                exchange(connect(), "POST /acc HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n".getBytes(StandardCharsets.US_ASCII)));
        assertEquals("HTTP/1.1 411 Length Required a POST needs a Content-Length",
                exchange(connect(), "POST /acc HTTP/1.1\r\n\r\n".getBytes(StandardCharsets.US_ASCII)));
        assertEquals("HTTP/1.1 400 Bad Request the Content-Length -5 is not a length",
                exchange(connect(), "POST /acc HTTP/1.1\r\nContent-Length: -5\r\n\r\n".getBytes(StandardCharsets.US_ASCII)));
        assertEquals("HTTP/1.1 400 Bad Request not an HTTP/1.x request line: hello",
                exchange(connect(), "hello\r\n\r\n".getBytes(StandardCharsets.US_ASCII)));
        assertEquals("HTTP/1.1 405 Method Not Allowed the ACC accepts POST only",
                exchange(connect(), "GET /acc HTTP/1.1\r\n\r\n".getBytes(StandardCharsets.US_ASCII)));
        assertEquals(2, drops("http-too-large"));
        assertEquals(5, drops("http-malformed"));
        assertEquals(7, mtp.rejected());
    }

    /**
     * A payload that does not parse is answered 400 with the parser's reason and counted as
     * {@code http-bad-acl}, apart from malformed HTTP; content as JADE writes it when it ends in a
     * backslash is accepted (it was answered 400 before, and JADE reported "No valid address").
     */
    @Test
    void anAclMessageThatDoesNotParseGetsItsReasonAndItsOwnCount() throws Exception {
        start(256);
        String bad = exchange(connect(), request(body("echo").replace(":content  \"ping\"", ":content  \"ping\" :bogus 1")));
        assertTrue(bad.startsWith("HTTP/1.1 400") && bad.contains("not a FIPA string ACL message")
                && bad.contains("':bogus'"), bad);
        assertEquals(1, drops("http-bad-acl"));
        assertEquals(0, drops("http-malformed"));
        assertOk(exchange(connect(), request(body("echo").replace(":content  \"ping\"", ":content  \"ends with backslash\\\""))),
                "JADE's writing of content ending in a backslash");
        assertEquals(1, drops("http-bad-acl"));
    }

    @Test
    void aBodyOfManyPartsCostsOneReadingWhateverItsShape() throws Exception {
        start(256);
        // The envelope and the payload, then 150,000 more parts closed by a bare LF: the split used
        // to look for CRLF delimiters from each part to the end of the body, 10^11 steps here.
        String two = body("echo");
        String first = two.substring(0, two.lastIndexOf("--" + BOUNDARY + "--"));
        StringBuilder b = new StringBuilder(first);
        while (b.length() + BOUNDARY.length() + 4 <= HttpMtp.MAX_BODY) {
            b.append("--").append(BOUNDARY).append("\n\n");
        }
        Socket s = connect();
        assertOk(exchange(s, request(b.toString())), "the message in the first two parts is read; the rest is never looked at");
        assertOk(exchange(s, request(body("echo"))), "and the server is free for the next");
        assertEquals(2, delivered.size());
        assertEquals(2, MtpMultipart.split(b.toString(), BOUNDARY).size());
    }

    @Test
    void theBridgeAnswersRequestsNamingOneHostAtABoundedRate() throws Exception {
        start(256);
        Socket s = connect();
        int n = ReplyLimit.BURST + 100;
        for (int i = 0; i < n; i++) {
            assertOk(exchange(s, request(body("nobody"))));
        }
        assertEquals(100, drops("http-reply-limit"), "a FAILURE for each unknown receiver, up to the burst; the rest counted");
        clock.addAndGet(1_000_000_000L);
        for (int i = 0; i < ReplyLimit.RATE + 10; i++) {
            exchange(s, request(body("nobody")));
        }
        assertEquals(110, drops("http-reply-limit"), ReplyLimit.RATE + " more a second later");
    }

    @Test
    void messagesWaitingForAForeignPlatformAreBoundedAndTheSenderIsTold() throws Exception {
        start(256);
        // A JADE platform that takes connections and never answers: the out thread waits on it.
        try (ServerSocket stuck = new ServerSocket(0, 50, java.net.InetAddress.getLoopbackAddress())) {
            AID jade = new AID("buyer@10.200.0.2:1099/JADE", "http://127.0.0.1:" + stuck.getLocalPort() + "/acc");
            AID me = AID.local("seller", "ourplat");
            int n = HttpMtp.OUT_QUEUE + 500;
            for (int i = 0; i < n; i++) {
                AclMessage m = new AclMessage(Performative.INFORM);
                m.setSender(me);
                m.addReceiver(jade);
                m.setContent("offer " + i);
                mtp.sendOut(m, jade);
            }
            assertTrue(mtp.outQueued() <= HttpMtp.OUT_QUEUE, "no more messages wait than the queue holds");
            long full = drops("http-out-full");
            assertTrue(full >= 499 && full <= 500, "each message past the queue is counted: " + full);
            long told = failures.stream().filter(m -> m.getPerformative() == Performative.FAILURE
                    && m.getContent().contains("queue to foreign platforms is full")).count();
            assertEquals(full, told, "and its sender is told FAILURE, saying why");
        }
    }

    /** An exposed sniff posts its events to an address the subscriber names: at the bridge's answer rate, not the agent's. */
    @Test
    void theObservationServicesEventsToAForeignHostAreBoundedAsTheBridgesOwnAnswers() throws Exception {
        start(8);
        AID foreign = new AID("sniffer@elsewhere", DEAD);
        for (int i = 0; i < 1_000; i++) {
            AclMessage e = new AclMessage(Performative.INFORM).setSender(new AID("echo@ourplat"));
            e.setOntology("concord-observe");
            e.setContent("{\"dir\":\"sent\"}");
            e.addReceiver(foreign);
            mtp.sendOut(e, foreign);
        }
        mtp.server().sweep().get(10, TimeUnit.SECONDS);
        assertEquals(1_000 - ReplyLimit.BURST, drops("http-out-limit"), "past the burst, with the clock standing still");
        assertEquals(1_000 - ReplyLimit.BURST, failures.stream().filter(f -> f.getContent().contains("posts at most 50 messages a second"))
                .count(), "the sender (the observed agent) is told each time");
    }
}
