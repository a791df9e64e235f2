package io.concord.jade;

import io.concord.core.acl.AID;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The bridge's non-blocking client against a JADE-like ACC on real sockets: JADE's answers (a page
 * with no length, blank lines after it), order kept over one kept-alive connection, a kept-alive
 * connection the peer closed meanwhile, an ACC that never answers (the clock is injected and
 * moved), and one that cannot be reached.
 */
class MtpClientTest {
    private final AtomicLong clock = new AtomicLong(1_000_000_000L);
    private final BridgeLoop loop = new BridgeLoop.Own("mtp-client-test", io.concord.core.time.Clock.system());
    private final List<AutoCloseable> open = new ArrayList<>();
    private MtpClient client;

    @AfterEach
    void close() throws Exception {
        for (AutoCloseable c : open) {
            c.close();
        }
        loop.close();
    }

    private MtpClient client() throws Exception {
        CompletableFuture<MtpClient> c = new CompletableFuture<>();
        loop.execute(() -> c.complete(new MtpClient(loop, clock::get)));
        client = c.get(10, TimeUnit.SECONDS);
        return client;
    }

    /** Posts a numbered message to the ACC; completes with null on 200, else why not. */
    private CompletableFuture<String> post(int port, int i) {
        CompletableFuture<String> done = new CompletableFuture<>();
        String url = "http://127.0.0.1:" + port + "/acc";
        byte[] request = MtpClient.request(url, new AID("buyer@10.200.0.2:1099/JADE", url), AID.local("seller", "ourplat"),
                "(INFORM :content \"" + i + "\")", io.concord.core.time.ManualClock.DEFAULT_EPOCH_MS);
        loop.execute(() -> client.post(new MtpClient.Post(url, request, done::complete)));
        return done;
    }

    /**
     * An ACC answering as JADE does: {@code answer} for each request (or nothing when null); it
     * records the contents in the order they came, and counts its connections.
     */
    private final class Acc implements AutoCloseable {
        final ServerSocket server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        final List<String> contents = new CopyOnWriteArrayList<>();
        final AtomicInteger connections = new AtomicInteger();
        final java.util.concurrent.Semaphore requests = new java.util.concurrent.Semaphore(0);
        final String answer;
        final int closeAfter;

        /** @param closeAfter requests after which the ACC closes the connection itself (0: never) */
        Acc(String answer, int closeAfter) throws IOException {
            this.answer = answer;
            this.closeAfter = closeAfter;
            open.add(this);
            Thread t = new Thread(this::accept, "fake-acc");
            t.setDaemon(true);
            t.start();
        }

        int port() {
            return server.getLocalPort();
        }

        private void accept() {
            try {
                while (true) {
                    Socket s = server.accept();
                    connections.incrementAndGet();
                    open.add(s);
                    Thread t = new Thread(() -> serve(s), "fake-acc-conn");
                    t.setDaemon(true);
                    t.start();
                }
            } catch (IOException closed) {
                // done
            }
        }

        private void serve(Socket s) {
            try (s) {
                InputStream in = s.getInputStream();
                OutputStream o = s.getOutputStream();
                for (int n = 1; ; n++) {
                    String head = head(in);
                    if (head == null) {
                        return;
                    }
                    int at = head.toLowerCase().indexOf("content-length: ");
                    int len = Integer.parseInt(head.substring(at + 16, head.indexOf('\r', at)).trim());
                    String body = new String(in.readNBytes(len), StandardCharsets.UTF_8);
                    int c = body.indexOf(":content \"");
                    contents.add(body.substring(c + 10, body.indexOf('"', c + 10)));
                    requests.release();
                    if (answer == null) {
                        continue;
                    }
                    o.write(answer.getBytes(StandardCharsets.US_ASCII));
                    o.flush();
                    if (n == closeAfter) {
                        return;
                    }
                }
            } catch (IOException e) {
                // the client went
            }
        }

        private static String head(InputStream in) throws IOException {
            StringBuilder b = new StringBuilder();
            int c;
            while ((c = in.read()) >= 0) {
                b.append((char) c);
                if (b.length() > 4 && b.substring(b.length() - 4).equals("\r\n\r\n")) {
                    return b.toString();
                }
            }
            return null;
        }

        @Override
        public void close() throws IOException {
            server.close();
        }
    }

    /** JADE's answer: keep-alive, no length, its page, and the two blank lines it writes after. */
    private static final String JADE_OK = "HTTP/1.1 200 OK\r\nContent-Type: text/html\r\nCache-Control: no-cache\r\n"
            + "Connection: Keep-Alive\r\n\r\n<html><body><h1>200 OK</h1></body></html>\r\n\r\n";

    @Test
    void messagesToOneAccGoInOrderOverOneKeptAliveConnection() throws Exception {
        Acc acc = new Acc(JADE_OK, 0);
        client();
        List<CompletableFuture<String>> done = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            done.add(post(acc.port(), i));
        }
        for (CompletableFuture<String> d : done) {
            assertNull(d.get(10, TimeUnit.SECONDS), "each answered 200");
        }
        List<String> expected = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            expected.add(Integer.toString(i));
        }
        assertEquals(expected, acc.contents, "in the order given");
        assertEquals(1, acc.connections.get(), "over one connection, JADE's page without a length read whole each time");
    }

    @Test
    void aKeptAliveConnectionThePeerClosedIsReplacedAndTheMessageGoesAgain() throws Exception {
        Acc acc = new Acc(JADE_OK, 1); // closes after each answer, without saying so
        client();
        for (int i = 0; i < 5; i++) {
            assertNull(post(acc.port(), i).get(10, TimeUnit.SECONDS), "message " + i);
        }
        assertEquals(List.of("0", "1", "2", "3", "4"), acc.contents, "each once, in order");
        assertEquals(5, acc.connections.get());
    }

    @Test
    void anAccThatNeverAnswersFailsItsMessagesAfterTheResponseTimeout() throws Exception {
        Acc acc = new Acc(null, 0);
        client();
        CompletableFuture<String> first = post(acc.port(), 0);
        CompletableFuture<String> second = post(acc.port(), 1);
        assertTrue(acc.requests.tryAcquire(10, TimeUnit.SECONDS), "the first request arrives");
        CompletableFuture<Void> swept = new CompletableFuture<>();
        loop.execute(() -> {
            client.expire();
            swept.complete(null);
        });
        swept.get(10, TimeUnit.SECONDS);
        assertTrue(!first.isDone() && !second.isDone(), "nothing is given up before its time");
        clock.addAndGet(MtpClient.RESPONSE_TIMEOUT_NS + 1);
        loop.execute(client::expire);
        String why = first.get(10, TimeUnit.SECONDS);
        assertTrue(why != null && why.contains("did not answer within 10000 ms"), why);
        assertTrue(acc.requests.tryAcquire(10, TimeUnit.SECONDS), "the second request arrives, on a new connection");
        clock.addAndGet(MtpClient.RESPONSE_TIMEOUT_NS + 1);
        loop.execute(client::expire);
        assertTrue(second.get(10, TimeUnit.SECONDS).contains("did not answer"), "the next one is tried, and given up too");
        assertEquals(2, acc.connections.get(), "the connection of a request given up is not used again");
    }

    @Test
    void anAccThatCannotBeReachedFailsEverythingWaitingForItAtOnce() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        client();
        List<CompletableFuture<String>> done = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            done.add(post(port, i));
        }
        for (CompletableFuture<String> d : done) {
            String why = d.get(10, TimeUnit.SECONDS);
            assertTrue(why != null && why.contains("cannot connect to 127.0.0.1:" + port), why);
        }
    }
}
