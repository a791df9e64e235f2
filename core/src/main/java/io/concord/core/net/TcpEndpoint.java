package io.concord.core.net;

import io.concord.core.time.Clock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.BindException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

/**
 * An agent's TCP endpoint: a listening socket, and one connection per direction to each peer (so
 * no connection is ever shared by two senders). A connection starts with a preamble, {@code CTCP},
 * a u16 length and the sender's listening address as {@code host:port}, so that the receiver knows
 * whom frames come from; then each frame is a u32 length and its bytes. A stream that does not
 * start like that, or announces a frame over 1 MiB, is closed. Sending never blocks: frames wait
 * in a bounded queue until the socket takes them.
 */
final class TcpEndpoint implements Endpoint, SocketNetwork.Handler {
    private static final Logger LOG = LoggerFactory.getLogger(TcpEndpoint.class);
    static final int MAX_FRAME = 1 << 20;
    static final int MAX_QUEUED_BYTES = 4 << 20;
    /**
     * Streams into one endpoint at once. At the limit a new one pushes out the stream that has been
     * quiet longest (a real peer that was pushed out connects again on its next send, and the
     * sequence layer recovers what was under way), so that streams opened and left idle by someone
     * else cannot keep real peers out.
     */
    static final int MAX_INBOUND = 64;
    /** How long a connection may take to open before what waits for it is dropped. */
    static final long CONNECT_TIMEOUT_NS = 5_000_000_000L;
    private static final byte[] MAGIC = {'C', 'T', 'C', 'P'};

    private final Selector selector;
    private final ServerSocketChannel server;
    private final Receiver receiver;
    private final Clock clock;
    private final Address local;
    private final byte[] preamble;
    private final Map<Address, Outbound> outbound = new HashMap<>();
    private final Set<Inbound> inbound = new HashSet<>();
    private boolean open = true;

    private TcpEndpoint(Selector selector, ServerSocketChannel server, Receiver receiver, Clock clock) throws IOException {
        this.selector = selector;
        this.server = server;
        this.receiver = receiver;
        this.clock = clock;
        InetSocketAddress la = (InetSocketAddress) server.getLocalAddress();
        this.local = new Address(la.getAddress().getHostAddress(), la.getPort());
        byte[] me = local.toString().getBytes(StandardCharsets.UTF_8);
        preamble = new byte[6 + me.length];
        System.arraycopy(MAGIC, 0, preamble, 0, 4);
        preamble[4] = (byte) (me.length >>> 8);
        preamble[5] = (byte) me.length;
        System.arraycopy(me, 0, preamble, 6, me.length);
    }

    static TcpEndpoint bind(Selector selector, String host, int port, Receiver receiver, Clock clock) {
        ServerSocketChannel ch = null;
        try {
            ch = ServerSocketChannel.open();
            ch.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            ch.bind(new InetSocketAddress(host, port));
            ch.configureBlocking(false);
            TcpEndpoint ep = new TcpEndpoint(selector, ch, receiver, clock);
            ch.register(selector, SelectionKey.OP_ACCEPT, ep);
            return ep;
        } catch (BindException e) {
            closeQuietly(ch);
            return null;
        } catch (IOException e) {
            closeQuietly(ch);
            throw new UncheckedIOException("cannot listen on TCP " + host + ":" + port + ": " + e.getMessage(), e);
        }
    }

    private static void closeQuietly(java.nio.channels.Channel ch) {
        if (ch != null) {
            try {
                ch.close();
            } catch (IOException ignored) {
                // nothing more to release
            }
        }
    }

    @Override
    public Address localAddress() {
        return local;
    }

    @Override
    public boolean isOpen() {
        return open;
    }

    /** Accepts waiting connections. */
    @Override
    public int onReady(SelectionKey key, long nowNs) {
        if (!key.isAcceptable()) {
            return 0;
        }
        try {
            SocketChannel ch;
            while ((ch = server.accept()) != null) {
                if (inbound.size() >= MAX_INBOUND) {
                    Inbound quietest = null;
                    for (Inbound i : inbound) {
                        if (quietest == null || i.lastActiveNs < quietest.lastActiveNs) {
                            quietest = i;
                        }
                    }
                    quietest.close();
                    receiver.onRefused(quietest.peer, "tcp-connections", MAX_INBOUND + " TCP streams were open into "
                            + local + "; the one quiet longest was closed for a new one");
                }
                ch.configureBlocking(false);
                ch.setOption(StandardSocketOptions.TCP_NODELAY, true);
                Inbound in = new Inbound(ch, nowNs);
                inbound.add(in);
                ch.register(selector, SelectionKey.OP_READ, in);
            }
        } catch (IOException e) {
            LOG.debug("accept on {} failed: {}", local, e.toString());
        }
        return 0;
    }

    @Override
    public boolean send(Address to, byte[] data, int offset, int length) {
        if (!open || length > MAX_FRAME) {
            return false;
        }
        Outbound o = outbound.get(to);
        if (o != null && !o.connected && !o.closed && clock.nanoTime() - o.startedNs > CONNECT_TIMEOUT_NS) {
            receiver.onRefused(to, "tcp-connect-timeout", "the connection to " + to + " did not open in "
                    + CONNECT_TIMEOUT_NS / 1_000_000_000L + " s; " + o.queue.size() + " frames waiting for it dropped");
            o.close();
        }
        if (o == null || o.closed) {
            o = connect(to);
            if (o == null) {
                return false;
            }
        }
        return o.enqueue(data, offset, length);
    }

    private Outbound connect(Address to) {
        SocketChannel ch = null;
        try {
            ch = SocketChannel.open();
            ch.configureBlocking(false);
            ch.setOption(StandardSocketOptions.TCP_NODELAY, true);
            Outbound o = new Outbound(to, ch);
            boolean done = ch.connect(new InetSocketAddress(to.host(), to.port()));
            o.key = ch.register(selector, done ? SelectionKey.OP_READ : SelectionKey.OP_CONNECT, o);
            o.connected = done;
            o.enqueueRaw(ByteBuffer.wrap(preamble.clone()));
            outbound.put(to, o);
            return o;
        } catch (IOException | RuntimeException e) {
            closeQuietly(ch);
            LOG.debug("cannot connect from {} to {}: {}", local, to, e.toString());
            return null;
        }
    }

    @Override
    public void close() {
        if (!open) {
            return;
        }
        open = false;
        closeQuietly(server);
        for (Outbound o : new java.util.ArrayList<>(outbound.values())) {
            o.close(); // which takes it out of the map
        }
        for (Inbound i : new HashSet<>(inbound)) {
            i.close();
        }
        outbound.clear();
        inbound.clear();
    }

    /** The sending side of one direction. */
    private final class Outbound implements SocketNetwork.Handler {
        private final Address peer;
        private final SocketChannel ch;
        private final ArrayDeque<ByteBuffer> queue = new ArrayDeque<>();
        private long queuedBytes;
        private SelectionKey key;
        private boolean connected;
        private boolean closed;
        private final long startedNs = clock.nanoTime();

        Outbound(Address peer, SocketChannel ch) {
            this.peer = peer;
            this.ch = ch;
        }

        boolean enqueue(byte[] data, int offset, int length) {
            if (queuedBytes + length + 4 > MAX_QUEUED_BYTES) {
                return false;
            }
            ByteBuffer b = ByteBuffer.allocate(4 + length);
            b.putInt(length).put(data, offset, length).flip();
            enqueueRaw(b);
            return !closed;
        }

        void enqueueRaw(ByteBuffer b) {
            queue.add(b);
            queuedBytes += b.remaining();
            if (connected) {
                flush();
            }
        }

        private void flush() {
            try {
                while (!queue.isEmpty()) {
                    ByteBuffer head = queue.peek();
                    int n = ch.write(head);
                    queuedBytes -= n;
                    if (head.hasRemaining()) {
                        key.interestOps(SelectionKey.OP_READ | SelectionKey.OP_WRITE);
                        return;
                    }
                    queue.poll();
                }
                key.interestOps(SelectionKey.OP_READ);
            } catch (IOException e) {
                LOG.debug("send from {} to {} failed: {}", local, peer, e.toString());
                close();
            }
        }

        @Override
        public int onReady(SelectionKey k, long nowNs) {
            try {
                if (k.isConnectable()) {
                    ch.finishConnect();
                    connected = true;
                    flush();
                    return 0;
                }
                if (k.isWritable()) {
                    flush();
                }
                if (k.isValid() && k.isReadable()) {
                    // The peer never writes on this direction: reading tells only that it closed.
                    ByteBuffer sink = ByteBuffer.allocate(64);
                    if (ch.read(sink) < 0) {
                        close();
                    }
                }
            } catch (IOException e) {
                LOG.debug("connection from {} to {} failed: {}", local, peer, e.toString());
                close();
            }
            return 0;
        }

        @Override
        public void close() {
            if (!closed) {
                closed = true;
                queue.clear();
                queuedBytes = 0;
                closeQuietly(ch);
                outbound.remove(peer, this);
            }
        }
    }

    /** The receiving side of one direction. */
    private final class Inbound implements SocketNetwork.Handler {
        private final SocketChannel ch;
        private ByteBuffer buf = ByteBuffer.allocate(16 * 1024);
        private Address peer;
        private long lastActiveNs;

        Inbound(SocketChannel ch, long nowNs) {
            this.ch = ch;
            this.lastActiveNs = nowNs;
        }

        @Override
        public int onReady(SelectionKey k, long nowNs) {
            int delivered = 0;
            try {
                while (true) {
                    if (!buf.hasRemaining()) {
                        ByteBuffer bigger = ByteBuffer.allocate(Math.min(buf.capacity() * 2, MAX_FRAME + 4));
                        buf.flip();
                        bigger.put(buf);
                        buf = bigger;
                    }
                    int n = ch.read(buf);
                    if (n < 0) {
                        close();
                        return delivered;
                    }
                    delivered += parse(nowNs);
                    if (delivered > 0) {
                        lastActiveNs = nowNs;
                    }
                    if (n == 0 || delivered >= SocketNetwork.READ_BUDGET) {
                        return delivered; // more, if any, at the next poll
                    }
                }
            } catch (IOException e) {
                LOG.debug("a TCP stream into {} failed: {}", local, e.getMessage());
                close();
                return delivered;
            } catch (StreamException e) {
                receiver.onRefused(peer, "tcp-malformed", "closed a TCP stream into " + local + ": " + e.getMessage());
                close();
                return delivered;
            }
        }

        /** Delivers every whole frame in the buffer. */
        private int parse(long nowNs) throws StreamException {
            buf.flip();
            int delivered = 0;
            try {
                if (peer == null) {
                    if (buf.remaining() < 6) {
                        return 0;
                    }
                    for (int i = 0; i < 4; i++) {
                        if (buf.get(buf.position() + i) != MAGIC[i]) {
                            throw new StreamException("not a Concord stream (it must start with CTCP)");
                        }
                    }
                    int len = ((buf.get(buf.position() + 4) & 0xFF) << 8) | (buf.get(buf.position() + 5) & 0xFF);
                    if (buf.remaining() < 6 + len) {
                        return 0;
                    }
                    String who = new String(buf.array(), buf.position() + 6, len, StandardCharsets.UTF_8);
                    peer = Address.parse(who);
                    if (peer == null) {
                        throw new StreamException("the stream's preamble names no address: '" + who + "'");
                    }
                    buf.position(buf.position() + 6 + len);
                }
                while (buf.remaining() >= 4) {
                    int len = buf.getInt(buf.position());
                    if (len < 0 || len > MAX_FRAME) {
                        throw new StreamException("a frame of " + len + " bytes announced, over the 1 MiB limit");
                    }
                    if (buf.remaining() < 4 + len) {
                        // The buffer grows as the bytes come (doubling when full), never on the
                        // announced length alone: a header costs nothing until its frame arrives.
                        break;
                    }
                    int at = buf.position() + 4;
                    receiver.onDatagram(peer, buf.array(), at, len, nowNs);
                    delivered++;
                    buf.position(at + len);
                }
            } finally {
                buf.compact();
            }
            return delivered;
        }

        @Override
        public void close() {
            closeQuietly(ch);
            inbound.remove(this);
        }
    }

    /** A peer broke the stream's format. */
    private static final class StreamException extends Exception {
        StreamException(String message) {
            super(message, null, false, false);
        }
    }
}
