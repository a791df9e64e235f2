package io.concord.console;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.net.URI;
import java.net.URISyntaxException;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.LongSupplier;
import java.util.regex.Pattern;

/**
 * The console's HTTP/1.1 server: one selector thread accepts every connection and reads every
 * request's head and body without blocking; only a request that arrived whole is handed to the
 * worker pool, whose handler queues its answer for the selector thread to write. Everything a
 * client can make the server hold is bounded ({@link Limits}): the head and the body of a request
 * (the buffer grows only as bytes arrive), the time from a request's first byte to its last, the
 * time a kept-alive connection may stay idle, the time an answer may take to be written, and the
 * connections open in all and from one client address, where a new connection at the cap closes
 * the one whose unfinished request has taken longest (else one closing, else the one idle
 * longest). Every refusal and every connection closed for a limit is counted by reason
 * ({@link #refusals()}). Times are read from the clock given ({@code System::nanoTime} in
 * production), so that a test moves it and calls {@link #sweep()} instead of waiting.
 */
final class HttpLoop {
    /**
     * What one client may make the server hold.
     *
     * @param closeOldest whether a new connection at a cap closes an old one (true) or is itself closed (false: for tests only)
     */
    record Limits(int maxHead, int maxBody, int maxUri, long requestTimeoutNs, long idleTimeoutNs, long writeTimeoutNs,
                  int maxConnections, int maxPerClient, boolean closeOldest) {
        static final Limits DEFAULT = new Limits(16 * 1024, 4 * 1024, 2_048, 10_000_000_000L, 30_000_000_000L,
                30_000_000_000L, 256, 64, true);

        Limits {
            if (maxHead < 256 || maxBody < 0 || maxUri < 1 || requestTimeoutNs <= 0 || idleTimeoutNs <= 0 || writeTimeoutNs <= 0
                    || maxConnections < 1 || maxPerClient < 1) {
                throw new IllegalArgumentException("the console's HTTP limits must be positive");
            }
        }

        /** These limits without the request timeout: for the tests that show it matters. */
        Limits withoutRequestTimeout() {
            return new Limits(maxHead, maxBody, maxUri, Long.MAX_VALUE, idleTimeoutNs, writeTimeoutNs, maxConnections, maxPerClient, closeOldest);
        }

        /** These limits with a new connection at a cap closed instead of an old one: for the tests that show it matters. */
        Limits withoutClosingTheOldest() {
            return new Limits(maxHead, maxBody, maxUri, requestTimeoutNs, idleTimeoutNs, writeTimeoutNs, maxConnections, maxPerClient, false);
        }
    }

    /** Answers a request; on a worker thread, which it may hold (an event stream, an action waiting on the agents). */
    interface Handler {
        void handle(Exchange x) throws IOException;
    }

    /** Bytes of an event stream waiting for its client beyond which {@link Exchange#send} waits. */
    static final int STREAM_WINDOW = 64 * 1024;
    /** After an answer that closes the connection, what the client still sends is read and thrown away this long (and this much). */
    static final long DRAIN_NS = 1_000_000_000L;
    static final int MAX_DRAIN = 1 << 20;
    private static final long SWEEP_EVERY_NS = 1_000_000_000L;
    private static final Pattern TOKEN = Pattern.compile("[!#$%&'*+.^_`|~0-9A-Za-z-]+");
    private static final Pattern LENGTH = Pattern.compile("[0-9]{1,18}");

    private final Limits limits;
    private final LongSupplier nanos;
    private final Handler handler;
    private final ExecutorService pool;
    private final Selector selector;
    private final ServerSocketChannel server;
    private final Thread thread;
    private final List<Conn> conns = new ArrayList<>();                 // the selector thread's
    private final Map<InetAddress, Integer> perClient = new HashMap<>();  // the selector thread's
    private final ConcurrentLinkedQueue<Runnable> tasks = new ConcurrentLinkedQueue<>();
    private final Map<String, LongAdder> refusals = new ConcurrentHashMap<>();
    private final ByteBuffer readBuffer = ByteBuffer.allocate(16 * 1024);
    private volatile boolean stopping;
    private volatile boolean started;
    private volatile int open;

    private enum State {
        /** Reading a request (or idle between two). */
        READING,
        /** A request is with a worker, or its answer is being written. */
        BUSY,
        /** Answered and closing: what the client still sends is read and dropped, so that it reads the answer. */
        DRAINING
    }

    /** A piece of an answer and when it was queued (for the write timeout). */
    private record Out(ByteBuffer data, long queuedNs) {
    }

    /** One client's connection. */
    private final class Conn {
        final SocketChannel ch;
        final SelectionKey key;
        final InetSocketAddress remote;
        // The selector thread's:
        byte[] buf = new byte[1024];
        int len;
        State state = State.READING;
        long lastActivityNs;
        boolean underWay;
        long requestStartNs;
        boolean continued;
        long drainUntilNs;
        long drained;
        // Guarded by this:
        final ArrayDeque<Out> out = new ArrayDeque<>();
        long outBytes;
        boolean last;
        boolean keepAfter;
        volatile boolean closed;

        Conn(SocketChannel ch, SelectionKey key, InetSocketAddress remote, long now) {
            this.ch = ch;
            this.key = key;
            this.remote = remote;
            this.lastActivityNs = now;
        }

        /** Queues bytes to write; {@code last}: the answer ends with them. False if the connection is closed. */
        boolean queue(byte[] data, boolean last, boolean keepAlive) {
            synchronized (this) {
                if (closed) {
                    return false;
                }
                if (data.length > 0) {
                    out.add(new Out(ByteBuffer.wrap(data), nanos.getAsLong()));
                    outBytes += data.length;
                }
                if (last) {
                    this.last = true;
                    this.keepAfter = keepAlive;
                }
            }
            onLoop(() -> flush(this));
            return true;
        }

        /** Waits while more than {@code window} bytes wait for the client; false once the connection is closed. */
        boolean awaitBelow(long window) throws InterruptedException {
            synchronized (this) {
                while (!closed && outBytes > window) {
                    wait();
                }
                return !closed;
            }
        }
    }

    /** A request that arrived whole, and its answer. Header names are looked up in any case. */
    final class Exchange {
        private final Conn conn;
        private final String method;
        private final String rawPath;
        private final String rawQuery;
        private final Map<String, String> headers;
        private final byte[] body;
        private final boolean keepAlive;
        private final Map<String, List<String>> answerHeaders = new TreeMap<>(String.CASE_INSENSITIVE_ORDER);
        private boolean answered;
        private boolean streaming;

        private Exchange(Conn conn, String method, String rawPath, String rawQuery, Map<String, String> headers, byte[] body,
                         boolean keepAlive) {
            this.conn = conn;
            this.method = method;
            this.rawPath = rawPath;
            this.rawQuery = rawQuery;
            this.headers = headers;
            this.body = body;
            this.keepAlive = keepAlive;
        }

        String method() {
            return method;
        }

        String rawPath() {
            return rawPath;
        }

        /** The query as sent, or null without one. */
        String rawQuery() {
            return rawQuery;
        }

        String header(String name) {
            return headers.get(name.toLowerCase(Locale.ROOT));
        }

        byte[] body() {
            return body;
        }

        InetSocketAddress remote() {
            return conn.remote;
        }

        void setHeader(String name, String value) {
            answerHeaders.put(name, new ArrayList<>(List.of(value)));
        }

        void addHeader(String name, String value) {
            answerHeaders.computeIfAbsent(name, k -> new ArrayList<>()).add(value);
        }

        boolean answered() {
            return answered;
        }

        /** Answers with a body of known length (none sent for HEAD); the connection stays open if the request allows. */
        void respond(int status, byte[] content) {
            if (answered) {
                throw new IllegalStateException("answered already");
            }
            answered = true;
            boolean noBody = status == 204 || status == 304;
            StringBuilder h = head(status);
            if (!noBody) {
                h.append("Content-Length: ").append(content.length).append("\r\n");
            }
            h.append("Connection: ").append(keepAlive ? "keep-alive" : "close").append("\r\n\r\n");
            byte[] headBytes = h.toString().getBytes(StandardCharsets.ISO_8859_1);
            boolean withBody = !noBody && !method.equals("HEAD") && content.length > 0;
            byte[] all = withBody ? Arrays.copyOf(headBytes, headBytes.length + content.length) : headBytes;
            if (withBody) {
                System.arraycopy(content, 0, all, headBytes.length, content.length);
            }
            conn.queue(all, true, keepAlive);
        }

        /** Starts an answer of unknown length (chunked), which ends with {@link #endStream()} or when the connection closes. */
        void startStream(int status) {
            if (answered) {
                throw new IllegalStateException("answered already");
            }
            answered = true;
            streaming = true;
            StringBuilder h = head(status).append("Transfer-Encoding: chunked\r\nConnection: close\r\n\r\n");
            conn.queue(h.toString().getBytes(StandardCharsets.ISO_8859_1), false, false);
        }

        /**
         * Sends a piece of a stream; waits while more than {@value HttpLoop#STREAM_WINDOW} bytes wait for the
         * client (the write timeout closes a client that does not read). False once the connection is closed.
         */
        boolean send(byte[] data) throws InterruptedException {
            if (data.length == 0) {
                return !conn.closed;
            }
            byte[] size = (Integer.toHexString(data.length) + "\r\n").getBytes(StandardCharsets.US_ASCII);
            byte[] chunk = new byte[size.length + data.length + 2];
            System.arraycopy(size, 0, chunk, 0, size.length);
            System.arraycopy(data, 0, chunk, size.length, data.length);
            chunk[chunk.length - 2] = '\r';
            chunk[chunk.length - 1] = '\n';
            return conn.queue(chunk, false, false) && conn.awaitBelow(STREAM_WINDOW);
        }

        /** Ends a stream; the connection closes once it is written. */
        void endStream() {
            if (streaming) {
                streaming = false;
                conn.queue("0\r\n\r\n".getBytes(StandardCharsets.US_ASCII), true, false);
            }
        }

        private StringBuilder head(int status) {
            StringBuilder h = new StringBuilder(256).append("HTTP/1.1 ").append(status).append(' ').append(reason(status)).append("\r\n")
                    .append("Date: ").append(DateTimeFormatter.RFC_1123_DATE_TIME.format(ZonedDateTime.now(ZoneOffset.UTC))).append("\r\n");
            answerHeaders.forEach((name, values) -> values.forEach(v -> h.append(name).append(": ").append(v).append("\r\n")));
            return h;
        }
    }

    /**
     * Binds (at once, so that a taken port fails here) and starts the selector thread.
     *
     * @throws IOException if the address cannot be bound
     */
    HttpLoop(InetSocketAddress at, Limits limits, LongSupplier nanos, ExecutorService pool, Handler handler) throws IOException {
        this.limits = limits;
        this.nanos = nanos;
        this.pool = pool;
        this.handler = handler;
        this.selector = Selector.open();
        this.server = ServerSocketChannel.open();
        try {
            server.bind(at, 128);
            server.configureBlocking(false);
            server.register(selector, SelectionKey.OP_ACCEPT);
        } catch (IOException e) {
            server.close();
            selector.close();
            throw e;
        }
        this.thread = new Thread(this::run, "concord-console-http");
        thread.setDaemon(true);
    }

    void start() {
        started = true;
        thread.start();
    }

    /** Closes every connection and the server; returns once the port is free. */
    void stop() {
        stopping = true;
        if (!started) {
            try {
                server.close();
                selector.close();
            } catch (IOException ignored) {
                // closing anyway
            }
            pool.shutdownNow();
            return;
        }
        selector.wakeup();
        try {
            thread.join(10_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    InetSocketAddress address() {
        return (InetSocketAddress) server.socket().getLocalSocketAddress();
    }

    /** Connections open now (as the selector thread last saw). Any thread. */
    int connections() {
        return open;
    }

    /** Counts a refusal (a handler's, by its status). Any thread. */
    void count(String reason) {
        refusals.computeIfAbsent(reason, k -> new LongAdder()).increment();
    }

    /** What was refused or closed for a limit, by reason. Any thread. */
    Map<String, Long> refusals() {
        Map<String, Long> m = new TreeMap<>();
        refusals.forEach((k, v) -> m.put(k, v.sum()));
        return m;
    }

    /** Closes the connections past their time by the clock now; completes once done. Any thread. */
    CompletableFuture<Void> sweep() {
        CompletableFuture<Void> done = new CompletableFuture<>();
        onLoop(() -> {
            expire(nanos.getAsLong());
            done.complete(null);
        });
        return done;
    }

    private void onLoop(Runnable r) {
        tasks.add(r);
        selector.wakeup();
    }

    private void run() {
        long nextSweep = System.nanoTime() + SWEEP_EVERY_NS;
        try {
            while (!stopping) {
                selector.select(SWEEP_EVERY_NS / 1_000_000);
                Runnable t;
                while ((t = tasks.poll()) != null) {
                    try {
                        t.run();
                    } catch (RuntimeException e) {
                        System.err.println("the console's HTTP server failed on a task: " + e);
                    }
                }
                Iterator<SelectionKey> it = selector.selectedKeys().iterator();
                while (it.hasNext()) {
                    SelectionKey k = it.next();
                    it.remove();
                    if (!k.isValid()) {
                        continue;
                    }
                    if (k.channel() == server) {
                        try {
                            accept(nanos.getAsLong());
                        } catch (IOException e) {
                            // out of descriptors, say: the connection waits in the backlog for the next turn
                        }
                    } else {
                        ready((Conn) k.attachment(), k);
                    }
                }
                if (System.nanoTime() - nextSweep >= 0) {
                    expire(nanos.getAsLong());
                    nextSweep = System.nanoTime() + SWEEP_EVERY_NS;
                }
            }
        } catch (IOException | RuntimeException e) {
            if (!stopping) {
                System.err.println("the console's HTTP server stopped: " + e);
            }
        } finally {
            for (Conn c : new ArrayList<>(conns)) {
                close(c);
            }
            try {
                server.close();
                selector.close();
            } catch (IOException ignored) {
                // closing anyway
            }
            pool.shutdownNow();
            tasks.clear();
        }
    }

    private void ready(Conn c, SelectionKey k) {
        try {
            if (k.isWritable()) {
                flush(c);
            }
            if (k.isValid() && k.isReadable()) {
                read(c);
            }
        } catch (IOException e) {
            close(c);
        } catch (RuntimeException e) {
            System.err.println("the console closed a connection from " + c.remote + " after a failure: " + e);
            close(c);
        }
    }

    private void accept(long now) throws IOException {
        SocketChannel ch;
        while ((ch = server.accept()) != null) {
            InetSocketAddress remote;
            try {
                remote = (InetSocketAddress) ch.getRemoteAddress();
            } catch (IOException e) {
                ch.close();   // reset before it was accepted
                continue;
            }
            if (remote == null) {
                ch.close();
                continue;
            }
            InetAddress from = remote.getAddress();
            boolean mine = perClient.getOrDefault(from, 0) >= limits.maxPerClient();
            if (mine || conns.size() >= limits.maxConnections()) {
                count("http-connections");
                Conn victim = limits.closeOldest() ? victim(mine ? from : null) : null;
                if (victim == null) {
                    ch.close();   // every connection is busy with an answer: the new one waits its turn
                    continue;
                }
                close(victim);
            }
            SelectionKey k;
            try {
                ch.configureBlocking(false);
                ch.setOption(StandardSocketOptions.TCP_NODELAY, true);
                k = ch.register(selector, SelectionKey.OP_READ);
            } catch (IOException e) {
                ch.close();   // gone already
                continue;
            }
            Conn c = new Conn(ch, k, remote, now);
            k.attach(c);
            conns.add(c);
            perClient.merge(from, 1, Integer::sum);
            open = conns.size();
        }
    }

    /** The connection to give up for a new one (of {@code from}'s, or of all): the oldest unfinished request, else one closing, else the longest idle. */
    private Conn victim(InetAddress from) {
        Conn slow = null;
        Conn closing = null;
        Conn idle = null;
        for (Conn c : conns) {
            if (from != null && !from.equals(c.remote.getAddress())) {
                continue;
            }
            if (c.state == State.DRAINING) {
                closing = c;
            } else if (c.state == State.READING && c.underWay) {
                if (slow == null || c.requestStartNs - slow.requestStartNs < 0) {
                    slow = c;
                }
            } else if (c.state == State.READING && (idle == null || c.lastActivityNs - idle.lastActivityNs < 0)) {
                idle = c;
            }
        }
        return slow != null ? slow : closing != null ? closing : idle;
    }

    private void expire(long now) {
        for (Conn c : new ArrayList<>(conns)) {
            if (c.state == State.DRAINING) {
                if (now - c.drainUntilNs >= 0) {
                    close(c);
                }
            } else if (c.state == State.READING && c.underWay && now - c.requestStartNs > limits.requestTimeoutNs()) {
                count("http-slow");   // a request not whole within the time: closed, no answer
                close(c);
            } else if (c.state == State.READING && !c.underWay && now - c.lastActivityNs > limits.idleTimeoutNs()) {
                close(c);             // idle keep-alive: housekeeping, nothing lost
            } else if (c.state == State.BUSY) {
                Out first;
                synchronized (c) {
                    first = c.out.peek();
                }
                if (first != null && now - first.queuedNs() > limits.writeTimeoutNs()) {
                    count("http-slow-reader");   // a client that does not read its answer
                    close(c);
                }
            }
        }
    }

    private void close(Conn c) {
        synchronized (c) {
            c.closed = true;
            c.out.clear();
            c.outBytes = 0;
            c.notifyAll();
        }
        c.key.cancel();
        try {
            c.ch.close();
        } catch (IOException ignored) {
            // closed anyway
        }
        if (conns.remove(c)) {
            perClient.computeIfPresent(c.remote.getAddress(), (a, n) -> n > 1 ? n - 1 : null);
        }
        open = conns.size();
    }

    /** Writes what waits; once an answer is written whole, reads the next request or closes. */
    private void flush(Conn c) {
        if (c.closed) {
            return;
        }
        long now = nanos.getAsLong();   // before the client can have the answer: idle from then on
        boolean empty;
        boolean done;
        boolean keep;
        try {
            synchronized (c) {
                while (!c.out.isEmpty()) {
                    Out o = c.out.peek();
                    c.outBytes -= c.ch.write(o.data());
                    if (o.data().hasRemaining()) {
                        break;
                    }
                    c.out.poll();
                }
                c.notifyAll();
                empty = c.out.isEmpty();
                done = empty && c.last;
                keep = c.keepAfter;
                if (done) {
                    c.last = false;
                }
            }
        } catch (IOException e) {
            close(c);
            return;
        }
        if (!empty) {
            c.key.interestOps(SelectionKey.OP_WRITE);
        } else if (!done) {
            c.key.interestOps(0);   // a stream between two pieces
        } else if (keep && !stopping) {
            c.state = State.READING;
            c.lastActivityNs = now;
            c.key.interestOps(SelectionKey.OP_READ);
            try {
                process(c, now);   // a request that came behind the one answered
            } catch (IOException e) {
                close(c);
            }
        } else {
            closeAfterAnswer(c);
        }
    }

    /**
     * Half-closes and reads on until the client closes (or {@link #DRAIN_NS} passes, or
     * {@link #MAX_DRAIN} bytes came): closing with its bytes unread would reset the connection, and
     * the client could lose the answer that says what was wrong.
     */
    private void closeAfterAnswer(Conn c) {
        try {
            c.ch.shutdownOutput();
        } catch (IOException e) {
            close(c);
            return;
        }
        c.state = State.DRAINING;
        c.drainUntilNs = nanos.getAsLong() + DRAIN_NS;
        c.len = 0;
        c.buf = new byte[0];
        c.key.interestOps(SelectionKey.OP_READ);
    }

    private void read(Conn c) throws IOException {
        long now = nanos.getAsLong();   // the bytes were there before: a request is no younger than this
        readBuffer.clear();
        int n = c.ch.read(readBuffer);
        if (n < 0) {
            close(c);
            return;
        }
        if (n == 0) {
            return;
        }
        if (c.state == State.DRAINING) {
            c.drained += n;
            if (c.drained > MAX_DRAIN) {
                close(c);
            }
            return;
        }
        if (c.state != State.READING) {
            return;   // not asked for: reads are off while busy
        }
        readBuffer.flip();
        if (c.len + n > c.buf.length) {
            // Grows by what arrived, never by what a header announces.
            c.buf = Arrays.copyOf(c.buf, Math.max(c.buf.length * 2, c.len + n));
        }
        readBuffer.get(c.buf, c.len, n);
        c.len += n;
        c.lastActivityNs = now;
        process(c, now);
    }

    /** Hands the request the buffer holds whole to the pool, refuses a bad one, or waits for more. */
    private void process(Conn c, long now) throws IOException {
        int start = 0;
        while (start < c.len && (c.buf[start] == '\r' || c.buf[start] == '\n')) {
            start++;
        }
        consume(c, start);
        if (c.len == 0) {
            c.underWay = false;
            if (c.buf.length > 4096) {
                c.buf = new byte[1024];
            }
            return;
        }
        if (!c.underWay) {
            c.underWay = true;
            c.continued = false;
            c.requestStartNs = now;
        }
        int headEnd = headEnd(c.buf, Math.min(c.len, limits.maxHead()));
        if (headEnd < 0) {
            if (c.len >= limits.maxHead()) {
                refuse(c, 431, "the request's head is longer than " + limits.maxHead() + " bytes");
            }
            return;
        }
        Head head;
        try {
            head = Head.parse(new String(c.buf, 0, headEnd, StandardCharsets.ISO_8859_1));
        } catch (IllegalArgumentException e) {
            refuse(c, 400, e.getMessage());
            return;
        }
        if (head.target.length() > limits.maxUri()) {
            refuse(c, 414, "the address is longer than " + limits.maxUri() + " characters");
            return;
        }
        URI uri;
        try {
            uri = new URI(head.target);
        } catch (URISyntaxException e) {
            refuse(c, 400, "a malformed address: " + e.getMessage());
            return;
        }
        if (head.headers.containsKey("transfer-encoding")) {
            refuse(c, 411, "a request's body is sent with its Content-Length, not chunked");
            return;
        }
        String cl = head.headers.get("content-length");
        long length = 0;
        if (cl != null) {
            if (!LENGTH.matcher(cl).matches()) {
                refuse(c, 400, "the Content-Length " + cl + " is not a length");
                return;
            }
            length = Long.parseLong(cl);
        }
        if (length > limits.maxBody()) {
            refuse(c, 413, "a request's body (an action's form parameters) takes at most " + limits.maxBody() + " bytes");
            return;
        }
        if (c.len < headEnd + length) {
            if (!c.continued && "100-continue".equalsIgnoreCase(head.headers.get("expect"))) {
                c.continued = true;
                c.ch.write(ByteBuffer.wrap("HTTP/1.1 100 Continue\r\n\r\n".getBytes(StandardCharsets.US_ASCII)));
            }
            return;   // the body is still arriving
        }
        byte[] body = Arrays.copyOfRange(c.buf, headEnd, headEnd + (int) length);
        consume(c, headEnd + (int) length);
        c.underWay = false;
        c.state = State.BUSY;
        c.key.interestOps(0);
        Exchange x = new Exchange(c, head.method, uri.getRawPath(), uri.getRawQuery(), head.headers, body, head.keepAlive());
        try {
            pool.execute(() -> work(x));
        } catch (RejectedExecutionException e) {
            close(c);   // stopping
        }
    }

    private void work(Exchange x) {
        try {
            handler.handle(x);
        } catch (Exception | Error e) {
            if (!x.answered()) {
                x.setHeader("Content-Type", "text/plain; charset=utf-8");
                x.respond(500, ("the console failed on this request: " + e + "\n").getBytes(StandardCharsets.UTF_8));
            }
        } finally {
            if (!x.answered()) {
                x.setHeader("Content-Type", "text/plain; charset=utf-8");
                x.respond(500, "the console gave no answer\n".getBytes(StandardCharsets.UTF_8));
            }
            x.endStream();
        }
    }

    /** Answers the server's own refusal (400, 411, 413, 414, 431), counted, and closes the connection. */
    private void refuse(Conn c, int status, String why) {
        count("http-" + status);
        c.underWay = false;
        c.len = 0;
        c.state = State.BUSY;
        c.key.interestOps(0);
        byte[] text = (why + "\n").getBytes(StandardCharsets.UTF_8);
        String head = "HTTP/1.1 " + status + " " + reason(status) + "\r\nContent-Type: text/plain; charset=utf-8\r\n"
                + "X-Content-Type-Options: nosniff\r\nContent-Length: " + text.length + "\r\nConnection: close\r\n\r\n";
        byte[] h = head.getBytes(StandardCharsets.ISO_8859_1);
        byte[] all = Arrays.copyOf(h, h.length + text.length);
        System.arraycopy(text, 0, all, h.length, text.length);
        c.queue(all, true, false);
    }

    private static void consume(Conn c, int n) {
        if (n > 0) {
            System.arraycopy(c.buf, n, c.buf, 0, c.len - n);
            c.len -= n;
        }
    }

    /** The offset just past the blank line that ends the head, or -1. */
    static int headEnd(byte[] b, int len) {
        for (int i = 0; i + 1 < len; i++) {
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

    /** A request line and its headers (names in lower case). */
    private record Head(String method, String target, boolean http11, Map<String, String> headers) {
        static Head parse(String text) {
            String[] lines = text.split("\r?\n");
            String[] start = lines[0].split(" ", -1);
            if (start.length != 3 || !TOKEN.matcher(start[0]).matches() || !start[1].startsWith("/")
                    || !(start[2].equals("HTTP/1.1") || start[2].equals("HTTP/1.0"))) {
                throw new IllegalArgumentException("not an HTTP/1.x request line: " + cut(lines[0]));
            }
            Map<String, String> headers = new HashMap<>();
            for (int i = 1; i < lines.length; i++) {
                String line = lines[i];
                if (line.isEmpty()) {
                    continue;
                }
                int colon = line.indexOf(':');
                if (colon <= 0 || !TOKEN.matcher(line.substring(0, colon)).matches()) {
                    throw new IllegalArgumentException("not a header line: " + cut(line));
                }
                String value = line.substring(colon + 1).strip();
                for (int j = 0; j < value.length(); j++) {
                    char ch = value.charAt(j);
                    if ((ch < 0x20 && ch != '\t') || ch == 0x7f) {
                        throw new IllegalArgumentException("a control character in the header " + line.substring(0, colon));
                    }
                }
                String name = line.substring(0, colon).toLowerCase(Locale.ROOT);
                String before = headers.get(name);
                if (before != null && (name.equals("host") || name.equals("content-length"))) {
                    throw new IllegalArgumentException("the header " + name + " is given twice");
                }
                headers.put(name, before == null ? value : before + ", " + value);
            }
            return new Head(start[0], start[1], start[2].equals("HTTP/1.1"), headers);
        }

        boolean keepAlive() {
            String c = headers.getOrDefault("connection", "").toLowerCase(Locale.ROOT);
            return http11 ? !c.contains("close") : c.contains("keep-alive");
        }

        private static String cut(String s) {
            return s.substring(0, Math.min(s.length(), 80));
        }
    }

    static String reason(int status) {
        return switch (status) {
            case 200 -> "OK";
            case 204 -> "No Content";
            case 400 -> "Bad Request";
            case 401 -> "Unauthorized";
            case 403 -> "Forbidden";
            case 404 -> "Not Found";
            case 405 -> "Method Not Allowed";
            case 411 -> "Length Required";
            case 413 -> "Payload Too Large";
            case 414 -> "URI Too Long";
            case 431 -> "Request Header Fields Too Large";
            case 500 -> "Internal Server Error";
            case 503 -> "Service Unavailable";
            default -> "Status";
        };
    }
}
