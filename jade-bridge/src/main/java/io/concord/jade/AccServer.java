package io.concord.jade;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.function.LongSupplier;

/**
 * The ACC's HTTP/1.1 server: non-blocking, one loop for every connection, with every resource a
 * client can make it hold bounded. A request costs the memory of the bytes that actually arrived
 * (an announced length allocates nothing), at most {@link Limits#maxHead} of head and
 * {@link Limits#maxBody} of body; it must arrive whole within {@link Limits#requestTimeoutNs} of its
 * first byte; at most {@link Limits#maxConnections} are open, and a new one closes the one that has
 * held the server longest without finishing a request (or, failing that, the one idle longest). Every
 * connection closed for a limit is counted in the drop counters with its reason.
 *
 * <p>It runs on a {@link BridgeLoop}: the platform's own, or a thread of the bridge's. The handler
 * runs on that loop and must not block. Leading blank lines before a
 * request are skipped (JADE writes two after each). Bodies need a {@code Content-Length}: chunked
 * requests are refused with 411, as JADE never sends them.
 */
final class AccServer implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(AccServer.class);

    /** What one client may make the server hold. */
    record Limits(int maxConnections, int maxHead, int maxBody, long requestTimeoutNs, long idleTimeoutNs) {
        static final Limits DEFAULT = new Limits(256, 16 * 1024, HttpMtp.MAX_BODY, 10_000_000_000L, 120_000_000_000L);

        Limits {
            if (maxConnections < 1 || maxHead < 64 || maxBody < 0 || requestTimeoutNs <= 0 || idleTimeoutNs <= 0) {
                throw new IllegalArgumentException("HTTP limits must be positive: " + maxConnections + " connections, "
                        + maxHead + " bytes of head, " + maxBody + " bytes of body");
            }
        }
    }

    /** A request read whole. Header names are in lower case. */
    record Request(String method, String target, Map<String, String> headers, byte[] body, InetAddress remote) {
        String header(String name) {
            return headers.get(name);
        }
    }

    /** What to answer: a status, a line of text saying why (or null), and whether the connection stays open. */
    record Response(int status, String text, boolean keepAlive) {
    }

    interface Handler {
        /** On the server's loop; must not block. */
        Response handle(Request request);

        /**
         * The server refused a request itself ({@code answered}: with a 4xx) or closed a
         * connection for a limit: to be counted with its reason. On the server's loop.
         */
        void dropped(String reason, InetAddress from, String why, boolean answered);
    }

    private final Limits limits;
    private final Handler handler;
    private final LongSupplier nanos;
    private final BridgeLoop loop;
    private final ServerSocketChannel server;
    private final ByteBuffer readBuffer = ByteBuffer.allocateDirect(64 * 1024);
    private final List<Conn> conns = new ArrayList<>();
    private boolean closed;
    private volatile int open;
    private volatile int underWay;
    private volatile long buffered;

    /** One client connection and what it has sent that is not answered yet. */
    private static final class Conn {
        final SocketChannel ch;
        final InetAddress remote;
        byte[] buf = new byte[512];
        int len;
        long lastActivityNs;
        /** When the request under way began, or -1 if none is (idle between requests). */
        long requestStartNs = -1;
        ByteBuffer pendingOut;
        boolean closeAfterWrite;
        boolean closed;
        /** Answered and closing: what the client still sends is read and thrown away, so that it reads the answer. */
        long drainUntilNs = -1;
        long drained;

        Conn(SocketChannel ch, InetAddress remote, long now) {
            this.ch = ch;
            this.remote = remote;
            this.lastActivityNs = now;
        }
    }

    /**
     * Binds and serves on the loop given (the platform's, or the bridge's own thread). Call on
     * that loop.
     *
     * @throws UncheckedIOException if the address cannot be bound, saying which
     */
    AccServer(String host, int port, Limits limits, Handler handler, LongSupplier nanos, BridgeLoop loop) {
        this.limits = limits;
        this.handler = handler;
        this.nanos = nanos;
        this.loop = loop;
        try {
            server = ServerSocketChannel.open();
            server.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            server.bind(new InetSocketAddress(host, port), 128);
            server.configureBlocking(false);
            loop.register(server, SelectionKey.OP_ACCEPT, (k, now) -> onAccept(nanos.getAsLong()));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot listen on " + host + ":" + port + " (" + e.getMessage() + ")", e);
        }
        loop.after(1_000, this::everySecond);
    }

    /** The port bound. */
    int port() {
        return server.socket().getLocalPort();
    }

    /** Connections open at the last sweep (see {@link #sweep()}). Any thread. */
    int open() {
        return open;
    }

    /** Connections with a request begun and not yet whole at the last sweep. Any thread. */
    int underWay() {
        return underWay;
    }

    /** Bytes held for unanswered requests at the last sweep, all connections together. Any thread. */
    long buffered() {
        return buffered;
    }

    /** Closes connections past their time now (by the injected clock); completes when done. Any thread. */
    CompletableFuture<Void> sweep() {
        CompletableFuture<Void> done = new CompletableFuture<>();
        loop.execute(() -> {
            expire(nanos.getAsLong());
            done.complete(null);
        });
        return done;
    }

    /** Closes the server and every connection. On the loop. */
    @Override
    public void close() {
        closed = true;
        for (Conn c : new ArrayList<>(conns)) {
            closeConn(c);
        }
        try {
            server.close();
        } catch (IOException ignored) {
            // closing anyway
        }
        open = 0;
        underWay = 0;
        buffered = 0;
    }

    private void everySecond() {
        if (!closed) {
            expire(nanos.getAsLong());
            loop.after(1_000, this::everySecond);
        }
    }

    private void onAccept(long now) {
        try {
            accept(now);
        } catch (IOException e) {
            LOG.debug("the HTTP MTP could not accept a connection: {}", e.toString());
        }
    }

    private void onConn(Conn c, SelectionKey k, long now) {
        try {
            if (k.isWritable() && flush(c, k) && c.len > 0) {
                process(c, k, now); // requests that came in behind the one answered
            }
            if (k.isValid() && k.isReadable()) {
                read(c, k, now);
            }
        } catch (IOException e) {
            closeConn(c);
        } catch (RuntimeException e) {
            LOG.warn("the HTTP MTP closed a connection from {} after a failure: {}", c.remote.getHostAddress(), e.toString(), e);
            closeConn(c);
        }
    }

    private void updateStats() {
        long b = 0;
        int u = 0;
        for (Conn c : conns) {
            b += c.buf.length;
            if (c.requestStartNs >= 0) {
                u++;
            }
        }
        buffered = b;
        underWay = u;
        open = conns.size();
    }

    private void accept(long now) throws IOException {
        SocketChannel ch;
        while ((ch = server.accept()) != null) {
            if (conns.size() >= limits.maxConnections()) {
                Conn victim = victim();
                handler.dropped("http-connections", victim.remote, "more than " + limits.maxConnections()
                        + " connections to the ACC; closed the one " + (victim.requestStartNs >= 0
                        ? "whose request has taken longest" : "idle longest"), false);
                closeConn(victim);
            }
            ch.configureBlocking(false);
            ch.setOption(StandardSocketOptions.TCP_NODELAY, true);
            InetSocketAddress remote = (InetSocketAddress) ch.getRemoteAddress();
            Conn c = new Conn(ch, remote.getAddress(), now);
            loop.register(ch, SelectionKey.OP_READ, (k, at) -> onConn(c, k, nanos.getAsLong())); // the server's clock, injected
            conns.add(c);
        }
    }

    /** The connection to give up for a new one: the oldest unfinished request, else the longest idle. */
    private Conn victim() {
        Conn slow = null;
        Conn idle = null;
        for (Conn c : conns) {
            if (c.requestStartNs >= 0) {
                if (slow == null || c.requestStartNs < slow.requestStartNs) {
                    slow = c;
                }
            } else if (idle == null || c.drainUntilNs >= 0 || c.lastActivityNs < idle.lastActivityNs) {
                idle = c;
            }
        }
        return slow != null ? slow : idle;
    }

    private void expire(long now) {
        for (Conn c : new ArrayList<>(conns)) {
            if (c.drainUntilNs >= 0) {
                if (now >= c.drainUntilNs) {
                    closeConn(c);
                }
            } else if (c.requestStartNs >= 0 && now - c.requestStartNs > limits.requestTimeoutNs()) {
                handler.dropped("http-slow", c.remote, "a request did not arrive whole within "
                        + limits.requestTimeoutNs() / 1_000_000 + " ms of its first byte; connection closed", false);
                closeConn(c);
            } else if (c.requestStartNs < 0 && c.pendingOut == null && now - c.lastActivityNs > limits.idleTimeoutNs()) {
                closeConn(c); // idle keep-alive: housekeeping, nothing lost
            }
        }
        updateStats();
    }

    private void closeConn(Conn c) {
        c.closed = true;
        conns.remove(c);
        try {
            c.ch.close();
        } catch (IOException ignored) {
            // closed anyway
        }
    }

    private void read(Conn c, SelectionKey k, long now) throws IOException {
        readBuffer.clear();
        int n = c.ch.read(readBuffer);
        if (n < 0) {
            closeConn(c);
            return;
        }
        if (n == 0) {
            return;
        }
        if (c.drainUntilNs >= 0) {
            c.drained += n;
            if (c.drained > limits.maxHead() + limits.maxBody()) {
                closeConn(c);
            }
            return;
        }
        readBuffer.flip();
        int cap = limits.maxHead() + limits.maxBody();
        if (c.len + n > c.buf.length) {
            // Grow by what arrived, never by what a header announces.
            int size = Math.min(Math.max(c.buf.length * 2, c.len + n), Math.max(cap, c.len + n));
            c.buf = java.util.Arrays.copyOf(c.buf, size);
        }
        readBuffer.get(c.buf, c.len, n);
        c.len += n;
        c.lastActivityNs = now;
        process(c, k, now);
    }

    /** Answers every request the buffer holds whole; stops while a response is still being written. */
    private void process(Conn c, SelectionKey k, long now) throws IOException {
        while (c.pendingOut == null && !c.closed) {
            int start = 0;
            while (start < c.len && (c.buf[start] == '\r' || c.buf[start] == '\n')) {
                start++;
            }
            if (start > 0) {
                consume(c, start);
            }
            if (c.len == 0) {
                c.requestStartNs = -1;
                shrink(c);
                return;
            }
            if (c.requestStartNs < 0) {
                c.requestStartNs = now;
            }
            int headEnd = headEnd(c.buf, Math.min(c.len, limits.maxHead()));
            if (headEnd < 0) {
                if (c.len >= limits.maxHead()) {
                    refuse(c, k, 431, "http-too-large", "the request's head is longer than " + limits.maxHead() + " bytes");
                }
                return;
            }
            Head head;
            try {
                head = Head.parse(new String(c.buf, 0, headEnd, StandardCharsets.ISO_8859_1));
            } catch (IllegalArgumentException e) {
                refuse(c, k, 400, "http-malformed", e.getMessage());
                return;
            }
            if (head.headers.containsKey("transfer-encoding")) {
                refuse(c, k, 411, "http-malformed", "a chunked request is not accepted; send its Content-Length");
                return;
            }
            long length = 0;
            String cl = head.headers.get("content-length");
            if (cl != null) {
                try {
                    length = Long.parseLong(cl.trim());
                } catch (NumberFormatException e) {
                    length = -1;
                }
                if (length < 0) {
                    refuse(c, k, 400, "http-malformed", "the Content-Length " + cl + " is not a length");
                    return;
                }
            } else if (head.method.equals("POST")) {
                refuse(c, k, 411, "http-malformed", "a POST needs a Content-Length");
                return;
            }
            if (length > limits.maxBody()) {
                refuse(c, k, 413, "http-too-large", "the request announces " + length + " bytes; the ACC takes at most "
                        + limits.maxBody());
                return;
            }
            if (c.len < headEnd + length) {
                return; // the body is still arriving
            }
            byte[] body = java.util.Arrays.copyOfRange(c.buf, headEnd, headEnd + (int) length);
            consume(c, headEnd + (int) length);
            c.requestStartNs = -1;
            Response r;
            try {
                r = handler.handle(new Request(head.method, head.target, head.headers, body, c.remote));
            } catch (RuntimeException e) {
                LOG.warn("the HTTP MTP failed on a request from {}: {}", c.remote.getHostAddress(), e.toString());
                r = new Response(500, "the ACC failed: " + e, false);
            }
            boolean keep = r.keepAlive() && head.keepAlive();
            write(c, k, r, keep);
        }
    }

    private void refuse(Conn c, SelectionKey k, int status, String reason, String why) throws IOException {
        handler.dropped(reason, c.remote, why, true);
        c.len = 0;
        shrink(c);
        c.requestStartNs = -1;
        write(c, k, new Response(status, why, false), false);
    }

    private void write(Conn c, SelectionKey k, Response r, boolean keepAlive) throws IOException {
        byte[] text = r.text() == null ? new byte[0] : (r.text() + "\n").getBytes(StandardCharsets.UTF_8);
        String head = "HTTP/1.1 " + r.status() + " " + reason(r.status()) + "\r\nContent-Type: text/plain; charset=utf-8\r\n"
                + "Cache-Control: no-cache\r\nContent-Length: " + text.length + "\r\nConnection: "
                + (keepAlive ? "Keep-Alive" : "close") + "\r\n\r\n";
        ByteBuffer out = ByteBuffer.allocate(head.length() + text.length);
        out.put(head.getBytes(StandardCharsets.US_ASCII)).put(text).flip();
        c.pendingOut = out;
        c.closeAfterWrite = !keepAlive;
        flush(c, k);
    }

    /** Writes what waits; true if the connection is open for the next request. */
    private boolean flush(Conn c, SelectionKey k) throws IOException {
        if (c.pendingOut == null) {
            k.interestOps(SelectionKey.OP_READ);
            return true;
        }
        c.ch.write(c.pendingOut);
        if (c.pendingOut.hasRemaining()) {
            k.interestOps(SelectionKey.OP_WRITE);
            return false;
        }
        c.pendingOut = null;
        if (c.closeAfterWrite) {
            // Half-close and read on until the client closes (or a second passes, or as much as a
            // request could hold): closing with its bytes unread would reset the connection, and
            // the client could lose the answer that says what was wrong.
            c.ch.shutdownOutput();
            c.drainUntilNs = nanos.getAsLong() + 1_000_000_000L;
            c.len = 0;
            shrink(c);
            k.interestOps(SelectionKey.OP_READ);
            return false;
        }
        k.interestOps(SelectionKey.OP_READ);
        return true;
    }

    private static void consume(Conn c, int n) {
        System.arraycopy(c.buf, n, c.buf, 0, c.len - n);
        c.len -= n;
    }

    /** Gives back a large buffer once the request it held is answered. */
    private static void shrink(Conn c) {
        if (c.buf.length > 4096 && c.len <= 512) {
            c.buf = java.util.Arrays.copyOf(c.buf, 512);
        }
    }

    /** The offset just past the blank line that ends the head, or -1. */
    static int headEnd(byte[] b, int len) {
        return headEnd(b, 0, len);
    }

    /** The offset just past the blank line that ends a head starting at {@code from}, or -1. */
    static int headEnd(byte[] b, int from, int len) {
        for (int i = from; i + 1 < len; i++) {
            if (b[i] == '\n') {
                if (b[i + 1] == '\n') {
                    return i + 2;
                }
                if (b[i + 1] == '\r' && i + 2 < len && b[i + 2] == '\n') {
                    return i + 3;
                }
            }
        }
        return -1;
    }

    /** A request line and its headers. */
    private record Head(String method, String target, boolean http11, Map<String, String> headers) {
        static Head parse(String text) {
            String[] lines = text.split("\r?\n");
            String[] start = lines[0].split(" ");
            if (start.length != 3 || !start[2].startsWith("HTTP/1.")) {
                throw new IllegalArgumentException("not an HTTP/1.x request line: "
                        + lines[0].substring(0, Math.min(lines[0].length(), 80)));
            }
            Map<String, String> headers = new HashMap<>();
            for (int i = 1; i < lines.length; i++) {
                if (lines[i].isEmpty()) {
                    continue;
                }
                int colon = lines[i].indexOf(':');
                if (colon <= 0) {
                    throw new IllegalArgumentException("a header line without a name: "
                            + lines[i].substring(0, Math.min(lines[i].length(), 80)));
                }
                headers.merge(lines[i].substring(0, colon).trim().toLowerCase(Locale.ROOT), lines[i].substring(colon + 1).trim(),
                        (a, b) -> a + ", " + b);
            }
            return new Head(start[0].toUpperCase(Locale.ROOT), start[1], start[2].equals("HTTP/1.1"), headers);
        }

        boolean keepAlive() {
            String c = headers.getOrDefault("connection", "").toLowerCase(Locale.ROOT);
            return http11 ? !c.contains("close") : c.contains("keep-alive");
        }
    }

    private static String reason(int status) {
        return switch (status) {
            case 200 -> "OK";
            case 400 -> "Bad Request";
            case 403 -> "Forbidden";
            case 404 -> "Not Found";
            case 405 -> "Method Not Allowed";
            case 406 -> "Not Acceptable";
            case 411 -> "Length Required";
            case 413 -> "Payload Too Large";
            case 431 -> "Request Header Fields Too Large";
            case 503 -> "Service Unavailable";
            default -> "Error";
        };
    }
}
