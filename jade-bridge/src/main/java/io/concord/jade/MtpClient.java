package io.concord.jade;

import io.concord.core.acl.AID;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.net.URI;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * The HTTP MTP's client: POSTs a message to another platform's ACC as JADE sends and reads it (a
 * multipart body of the XML envelope and the ACL string), non-blocking, on the bridge's loop. One
 * connection per ACC (host and port), kept alive when the peer allows, carries that ACC's messages
 * one after the other in the order they were given: a JADE agent gets a Concord agent's messages
 * in the order it sent them. Every method runs on the loop.
 */
final class MtpClient {
    static final long CONNECT_TIMEOUT_NS = 5_000_000_000L;
    static final long RESPONSE_TIMEOUT_NS = 10_000_000_000L;
    /** JADE keeps an idle connection 60 s; a little less here, so that the peer never closes one under a request. */
    static final long IDLE_NS = 50_000_000_000L;
    /** What a response's head and JADE's bodiless page may take. */
    static final int MAX_RESPONSE = 16 * 1024;

    private final BridgeLoop loop;
    private final LongSupplier nanos;
    private final Map<String, Acc> accs = new HashMap<>();
    private boolean closed;

    MtpClient(BridgeLoop loop, LongSupplier nanos) {
        this.loop = loop;
        this.nanos = nanos;
        loop.after(1_000, this::everySecond);
    }

    /** A message to post and what to do when it is done: {@code done} gets null if the ACC answered 200, else why not. */
    record Post(String url, byte[] request, Consumer<String> done) {
    }

    /** Requests in flight or waiting, all ACCs together. */
    int queued() {
        int n = 0;
        for (Acc a : accs.values()) {
            n += a.waiting.size() + (a.conn != null && a.conn.current != null ? 1 : 0);
        }
        return n;
    }

    /** Posts, after the messages already waiting for the same ACC. */
    void post(Post p) {
        if (closed) {
            p.done().accept("the HTTP MTP is stopping");
            return;
        }
        URI u = URI.create(p.url());
        int port = u.getPort() < 0 ? 80 : u.getPort();
        String key = u.getHost() + ":" + port;
        Acc a = accs.computeIfAbsent(key, k -> new Acc(u.getHost(), port));
        a.waiting.add(p);
        a.pump();
    }

    /** Closes every connection; what waits is told {@code why}. */
    void close(String why) {
        closed = true;
        for (Acc a : new ArrayList<>(accs.values())) {
            a.failAll(why);
        }
        accs.clear();
    }

    private void everySecond() {
        if (!closed) {
            expire();
            loop.after(1_000, this::everySecond);
        }
    }

    /** Gives up what is past its time now (by the injected clock); the loop does it every second. */
    void expire() {
        long now = nanos.getAsLong();
        for (Acc a : new ArrayList<>(accs.values())) {
            a.expire(now);
        }
    }

    /** One foreign ACC: its connection and the messages waiting for it. */
    private final class Acc {
        final String host;
        final int port;
        final ArrayDeque<Post> waiting = new ArrayDeque<>();
        Conn conn;

        Acc(String host, int port) {
            this.host = host;
            this.port = port;
        }

        /** Starts the next request if the connection is free, opening one if needed. */
        void pump() {
            if (waiting.isEmpty()) {
                return;
            }
            if (conn == null) {
                try {
                    conn = new Conn(this);
                } catch (IOException e) {
                    failAll("cannot connect to " + host + ":" + port + ": " + e.getMessage());
                    return;
                }
            }
            if (conn.connected && conn.current == null) {
                conn.start(waiting.poll());
            }
        }

        void failAll(String why) {
            Conn c = conn;
            conn = null;
            if (c != null) {
                c.close();
                if (c.current != null) {
                    c.current.done().accept(why);
                }
            }
            Post p;
            while ((p = waiting.poll()) != null) {
                p.done().accept(why);
            }
        }

        /** The connection failed: the request it carried fails or, if the peer closed a kept-alive connection under it, goes again. */
        void failed(Conn c, String why) {
            c.close();
            if (conn == c) {
                conn = null;
            }
            Post p = c.current;
            c.current = null;
            if (!c.connected) {
                failAll(why); // the ACC cannot be reached: everything waiting for it would wait the same
                return;
            }
            if (p != null) {
                if (c.reused && c.in == 0 && !c.retried) {
                    waiting.addFirst(p); // once more on a new connection
                    retryNext = true;
                } else {
                    p.done().accept(why);
                }
            }
            pump();
        }

        boolean retryNext;

        void expire(long now) {
            Conn c = conn;
            if (c == null) {
                if (waiting.isEmpty()) {
                    accs.remove(host + ":" + port, this);
                }
                return;
            }
            if (!c.connected && now - c.sinceNs > CONNECT_TIMEOUT_NS) {
                failAll("no connection to " + host + ":" + port + " within " + CONNECT_TIMEOUT_NS / 1_000_000 + " ms");
            } else if (c.current != null && now - c.sinceNs > RESPONSE_TIMEOUT_NS) {
                c.reused = false; // no second try for an ACC that does not answer
                failed(c, host + ":" + port + " did not answer within " + RESPONSE_TIMEOUT_NS / 1_000_000 + " ms");
            } else if (c.connected && c.current == null && now - c.sinceNs > IDLE_NS) {
                c.close();
                conn = null;
            }
        }
    }

    /** A connection to an ACC and the one request it carries. */
    private final class Conn {
        final Acc acc;
        final SocketChannel ch;
        final SelectionKey key;
        boolean connected;
        boolean reused;
        boolean retried;
        Post current;
        ByteBuffer out;
        byte[] resp = new byte[512];
        int in;
        long sinceNs;

        Conn(Acc acc) throws IOException {
            this.acc = acc;
            sinceNs = nanos.getAsLong();
            ch = SocketChannel.open();
            try {
                ch.configureBlocking(false);
                ch.setOption(StandardSocketOptions.TCP_NODELAY, true); // one write, sent at once
                connected = ch.connect(new InetSocketAddress(acc.host, acc.port));
                key = loop.register(ch, connected ? 0 : SelectionKey.OP_CONNECT, (k, now) -> onReady(k));
            } catch (IOException | RuntimeException e) {
                ch.close();
                throw e instanceof IOException io ? io : new IOException(e.getMessage(), e);
            }
        }

        void start(Post p) {
            current = p;
            retried = acc.retryNext;
            acc.retryNext = false;
            out = ByteBuffer.wrap(p.request());
            in = 0;
            sinceNs = nanos.getAsLong();
            write();
        }

        private void write() {
            try {
                ch.write(out);
            } catch (IOException e) {
                acc.failed(this, current.url() + ": " + e.getMessage());
                return;
            }
            key.interestOps(out.hasRemaining() ? SelectionKey.OP_WRITE : SelectionKey.OP_READ);
        }

        private void onReady(SelectionKey k) {
            if (!k.isValid()) {
                return;
            }
            if (k.isConnectable()) {
                try {
                    ch.finishConnect();
                } catch (IOException e) {
                    acc.failed(this, "cannot connect to " + acc.host + ":" + acc.port + ": " + e.getMessage());
                    return;
                }
                connected = true;
                sinceNs = nanos.getAsLong();
                key.interestOps(0);
                acc.pump();
                return;
            }
            if (k.isWritable()) {
                write();
                return;
            }
            if (k.isReadable()) {
                read();
            }
        }

        private void read() {
            int n;
            try {
                if (in == resp.length) {
                    if (resp.length >= MAX_RESPONSE) {
                        acc.failed(this, current == null ? "unasked bytes" : current.url() + " answered more than "
                                + MAX_RESPONSE + " bytes");
                        return;
                    }
                    resp = java.util.Arrays.copyOf(resp, resp.length * 2);
                }
                n = ch.read(ByteBuffer.wrap(resp, in, resp.length - in));
            } catch (IOException e) {
                acc.failed(this, (current == null ? acc.host : current.url()) + ": " + e.getMessage());
                return;
            }
            if (n < 0) {
                acc.failed(this, (current == null ? acc.host : current.url()) + " closed the connection before answering");
                return;
            }
            if (current == null) {
                for (int i = in; i < in + n; i++) {
                    if (resp[i] != '\r' && resp[i] != '\n') {
                        acc.failed(this, "unasked bytes from " + acc.host); // a peer that talks unasked is dropped
                        return;
                    }
                }
                return; // the blank lines JADE writes after an answer
            }
            in += n;
            Response r = Response.parse(resp, in);
            if (r == null) {
                return; // more to come
            }
            Post p = current;
            current = null;
            in = 0;
            sinceNs = nanos.getAsLong();
            reused = true;
            if (r.keepAlive()) {
                key.interestOps(SelectionKey.OP_READ); // an idle connection the peer closes is seen at once
                if (resp.length > 4096) {
                    resp = new byte[512];
                }
            } else {
                close();
                acc.conn = null;
            }
            p.done().accept(r.status() == 200 ? null : p.url() + " answered " + r.status());
            acc.pump();
        }

        void close() {
            key.cancel();
            try {
                ch.close();
            } catch (IOException ignored) {
                // closed anyway
            }
        }
    }

    /** A whole response's status and whether its connection stays open. */
    record Response(int status, boolean keepAlive) {
        /**
         * Reads a response from the bytes that arrived: the status line (after any blank lines),
         * the headers, and, when the connection stays open, the body: by its Content-Length, or
         * JADE's fixed HTML page, which has none. {@code null} until it is whole.
         */
        static Response parse(byte[] b, int len) {
            int start = 0;
            while (start < len && (b[start] == '\r' || b[start] == '\n')) {
                start++;
            }
            int headEnd = AccServer.headEnd(b, start, len);
            if (headEnd < 0) {
                return null; // read on: nothing made of a partial head
            }
            String text = new String(b, 0, len, StandardCharsets.ISO_8859_1);
            String[] lines = text.substring(start, headEnd).split("\r?\n");
            if (!lines[0].startsWith("HTTP/1.")) {
                return new Response(-1, false);
            }
            String[] w = lines[0].split(" ");
            int status;
            try {
                status = w.length > 1 ? Integer.parseInt(w[1]) : -1;
            } catch (NumberFormatException e) {
                status = -1;
            }
            boolean keepAlive = lines[0].startsWith("HTTP/1.1");
            int length = -1;
            for (int i = 1; i < lines.length; i++) {
                String l = lines[i].toLowerCase(Locale.ROOT);
                if (l.startsWith("connection:")) {
                    keepAlive = l.substring(11).trim().equals("keep-alive");
                } else if (l.startsWith("content-length:")) {
                    try {
                        length = Integer.parseInt(l.substring(15).trim());
                    } catch (NumberFormatException e) {
                        return new Response(status, false);
                    }
                }
            }
            if (!keepAlive) {
                return new Response(status, false);
            }
            if (length >= 0) {
                return len - headEnd >= length ? new Response(status, true) : null;
            }
            // JADE's page: <html><body><h1>200 OK</h1></body></html>, without a length.
            // (what follows it, if anything, is blank lines, skipped before the next response)
            for (int i = headEnd; i + 7 <= len; i++) {
                if (text.regionMatches(true, i, "</html>", 0, 7)) {
                    return new Response(status, true);
                }
            }
            return null;
        }
    }

    /** The bytes of one POST, as JADE writes it ({@link MtpMultipart}), its envelope dated {@code epochMs}. */
    static byte[] request(String url, AID receiver, AID sender, String payload, long epochMs) {
        URI u = URI.create(url);
        int port = u.getPort() < 0 ? 80 : u.getPort();
        byte[] acl = payload.getBytes(StandardCharsets.UTF_8);
        FipaEnvelope env = FipaEnvelope.forOne(receiver, sender, acl.length, epochMs);
        String boundary = MtpMultipart.newBoundary();
        byte[] body = MtpMultipart.encode(boundary, env.toXml(), acl);
        String head = "POST " + url + " HTTP/1.1\r\nCache-Control: no-cache\r\nMime-Version: 1.0\r\nHost: " + u.getHost()
                + ":" + port + "\r\nContent-Type: " + MtpMultipart.contentType(boundary) + "\r\nContent-Length: "
                + body.length + "\r\nConnection: Keep-Alive\r\n\r\n";
        ByteArrayOutputStream all = new ByteArrayOutputStream(head.length() + body.length);
        all.writeBytes(head.getBytes(StandardCharsets.US_ASCII));
        all.writeBytes(body);
        return all.toByteArray();
    }
}
