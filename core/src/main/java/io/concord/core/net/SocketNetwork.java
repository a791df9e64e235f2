package io.concord.core.net;

import io.concord.core.net.internal.Neighbourhood;
import io.concord.core.time.Clock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.BindException;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.HashMap;
import java.util.Iterator;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * Real sockets, UDP and TCP, non-blocking, all registered with one {@link Selector} so that a
 * single loop serves every agent of a JVM. TCP is described in {@link TcpEndpoint}.
 */
public final class SocketNetwork implements Network {
    /** Largest UDP payload over IPv4. */
    public static final int MAX_DATAGRAM = 65507;
    /**
     * Datagrams (or TCP frames) read from one socket in one poll. A socket with more waiting is read
     * again at the next poll, after the loop has run its timers and the other sockets: a flood on
     * one port cannot keep the loop from the rest.
     */
    static final int READ_BUDGET = 64;
    /**
     * ... and while the agents of this JVM have frames for each other waiting: the loop then looks
     * at the sockets every few cycles, and reads a few frames from each. A flood at a port is then
     * left to the kernel, which drops what its buffer cannot hold, at no cost to the loop.
     */
    static final int BUSY_READ_BUDGET = 4;
    private int readBudget = READ_BUDGET;
    /**
     * A datagram that carries several frames starts with these two bytes (a frame starts with
     * 0xC07D), followed by each frame as a big-endian u16 length and its bytes.
     */
    public static final int BUNDLE_MAGIC = 0xC07B;
    /** Frames in one bundle at most, sent or read; what a bundle holds past this is dropped as one malformed frame. */
    public static final int MAX_BUNDLE_FRAMES = 64;
    /** A bundle's size at most to a loopback address (one host: no fragmentation). */
    public static final int LOOPBACK_BUNDLE_BYTES = 16_384;
    /** ... and to any other address: within an Ethernet frame, so that a bundle is never fragmented. */
    public static final int BUNDLE_BYTES = 1_472;
    private final boolean bundling;
    /** The endpoints holding gathered frames, to be sent at the end of the loop's cycle. */
    private final java.util.ArrayList<UdpEndpoint> gathering = new java.util.ArrayList<>();
    private final java.util.ArrayDeque<Bundle> bundlePool = new java.util.ArrayDeque<>();
    /** Bundles kept for the next cycles at most (a cycle in which a thousand agents each sent made as many). */
    private static final int MAX_POOLED_BUNDLES = 256;

    /** Frames gathered for one address and lane. */
    private static final class Bundle {
        /** Grown as frames come, up to the limit: most bundles hold a frame or two. */
        byte[] buf = new byte[2_048];
        Address to;
        int lane;
        /** The bundle of another lane to the same address this cycle, if any. */
        Bundle otherLane;
        int limit;
        int length;
        int frames;

        Bundle start(Address to, int lane, int limit) {
            this.to = to;
            this.lane = lane;
            this.limit = limit;
            buf[0] = (byte) (BUNDLE_MAGIC >>> 8);
            buf[1] = (byte) BUNDLE_MAGIC;
            length = 2;
            frames = 0;
            return this;
        }

        boolean fits(int frameLength) {
            return frames < MAX_BUNDLE_FRAMES && length + 2 + frameLength <= limit;
        }

        void add(byte[] data, int offset, int frameLength) {
            if (length + 2 + frameLength > buf.length) {
                buf = java.util.Arrays.copyOf(buf, Math.min(limit, Math.max(2 * buf.length, length + 2 + frameLength)));
            }
            buf[length] = (byte) (frameLength >>> 8);
            buf[length + 1] = (byte) frameLength;
            System.arraycopy(data, offset, buf, length + 2, frameLength);
            length += 2 + frameLength;
            frames++;
        }
    }
    private static final Logger LOG = LoggerFactory.getLogger(SocketNetwork.class);

    private final Selector selector;
    private final Clock clock;
    private final ByteBuffer receiveBuffer = ByteBuffer.allocateDirect(MAX_DATAGRAM + 1);
    private final byte[] receiveArray = new byte[MAX_DATAGRAM + 1];
    private final Map<InetSocketAddress, Address> addressCache = new HashMap<>();
    private final Map<Address, InetSocketAddress> socketAddressCache = new HashMap<>();
    private final int socketBufferBytes;
    private final boolean localDelivery;
    private final Map<Address, UdpEndpoint> localUdp = new HashMap<>();
    private final java.util.ArrayDeque<LocalFrame> localQueue = new java.util.ArrayDeque<>();
    private int cyclesWithoutSelect;

    private record LocalFrame(Address from, UdpEndpoint to, byte[] data) {
    }

    /** A network with 1 MiB socket buffers and in-memory delivery between its own UDP endpoints. */
    public SocketNetwork() {
        this(1 << 20, true);
    }

    /**
     * @param socketBufferBytes the send and receive buffer size asked of the kernel
     * @param localDelivery     true to hand a datagram between two UDP endpoints of this network
     *                          over in memory (on the same loop, no system call, no thread switch);
     *                          false to send every datagram through the kernel
     */
    public SocketNetwork(int socketBufferBytes, boolean localDelivery) {
        this(socketBufferBytes, localDelivery, !Boolean.getBoolean("concord.bundle.off"));
    }

    /**
     * ... and {@code bundling}: true to gather the frames one cycle of the loop sends to one address
     * on one lane into one datagram (see {@link Endpoint#send(Address, byte[], int, int, int)});
     * false (or {@code -Dconcord.bundle.off=true}) for one datagram per frame.
     */
    public SocketNetwork(int socketBufferBytes, boolean localDelivery, boolean bundling) {
        this(socketBufferBytes, localDelivery, bundling, Clock.system());
    }

    /**
     * ... and the {@code clock} that times what the sockets themselves take (the 5 s a TCP
     * connection may take to open): the system's by default, since a socket connects in real time
     * whatever clock the agents' loop runs on.
     */
    public SocketNetwork(int socketBufferBytes, boolean localDelivery, boolean bundling, Clock clock) {
        this.clock = java.util.Objects.requireNonNull(clock, "clock");
        this.socketBufferBytes = socketBufferBytes;
        this.localDelivery = localDelivery;
        this.bundling = bundling;
        try {
            selector = Selector.open();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot open a selector for UDP sockets", e);
        }
    }

    /** Something registered with the selector. */
    interface Handler {
        /** The key is ready; returns the frames delivered. */
        int onReady(SelectionKey key, long nowNs);

        void close();
    }

    @Override
    public <T> T capability(Class<T> type) {
        return type == Channels.class ? type.cast(channels) : null;
    }

    /** The loop's selector lent to the JADE bridge: {@link Channels}. */
    private final Channels channels = this::register;

    private SelectionKey register(java.nio.channels.SelectableChannel channel, int ops, Channels.Ready ready) throws IOException {
        java.util.Objects.requireNonNull(ready, "ready");
        return channel.register(selector, ops, new Handler() {
            @Override
            public int onReady(SelectionKey key, long nowNs) {
                ready.onReady(key, nowNs);
                return 1;
            }

            @Override
            public void close() {
                try {
                    channel.close();
                } catch (IOException ignored) {
                    // closing anyway
                }
            }
        });
    }

    @Override
    public Endpoint tryBind(Transport transport, String host, int port, Receiver receiver) {
        if (transport == Transport.UDP) {
            return tryBind(host, port, receiver);
        }
        return TcpEndpoint.bind(selector, host, port, receiver, clock);
    }

    /**
     * Binds and closes a bare channel, never registered with the selector: a registered channel's
     * port is released only at the selector's next select, which would make the port look held.
     */
    @Override
    public boolean isHeld(Transport transport, String host, int port) {
        try (java.nio.channels.NetworkChannel ch = transport == Transport.UDP ? DatagramChannel.open()
                : java.nio.channels.ServerSocketChannel.open()) {
            if (transport == Transport.TCP) {
                ch.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            }
            ch.bind(new InetSocketAddress(host, port));
            return false;
        } catch (BindException e) {
            return true;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot probe " + transport + " " + host + ":" + port + ": " + e.getMessage(), e);
        }
    }

    @Override
    public Endpoint bindListener(String host, int port, boolean broadcast, Receiver receiver) {
        DatagramChannel ch = null;
        try {
            ch = DatagramChannel.open(java.net.StandardProtocolFamily.INET);
            ch.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            ch.setOption(StandardSocketOptions.SO_BROADCAST, true);
            ch.setOption(StandardSocketOptions.SO_RCVBUF, socketBufferBytes);
            ch.bind(broadcast ? new InetSocketAddress(port) : new InetSocketAddress(host, port));
            ch.configureBlocking(false);
            UdpEndpoint ep = new UdpEndpoint(ch, receiver);
            ch.register(selector, SelectionKey.OP_READ, ep);
            return ep;
        } catch (BindException e) {
            closeQuietly(ch);
            return null;
        } catch (IOException e) {
            closeQuietly(ch);
            throw new UncheckedIOException("cannot bind the shared UDP port " + port + ": " + e.getMessage(), e);
        }
    }

    @Override
    public java.util.List<String> broadcastAddresses(String host) {
        try {
            java.net.InetAddress a = java.net.InetAddress.getByName(host);
            if (a.isLoopbackAddress() || a.isAnyLocalAddress() || !(a instanceof java.net.Inet4Address)) {
                return java.util.List.of();
            }
            java.util.List<String> out = new java.util.ArrayList<>();
            java.net.NetworkInterface ni = java.net.NetworkInterface.getByInetAddress(a);
            if (ni != null) {
                for (java.net.InterfaceAddress ia : ni.getInterfaceAddresses()) {
                    if (ia.getAddress().equals(a) && ia.getBroadcast() != null) {
                        out.add(ia.getBroadcast().getHostAddress());
                    }
                }
            }
            out.add("255.255.255.255");
            return out;
        } catch (IOException e) {
            return java.util.List.of();
        }
    }

    @Override
    public Endpoint tryBind(String host, int port, Receiver receiver) {
        DatagramChannel ch = null;
        try {
            ch = DatagramChannel.open();
            ch.setOption(StandardSocketOptions.SO_RCVBUF, socketBufferBytes);
            ch.setOption(StandardSocketOptions.SO_SNDBUF, socketBufferBytes);
            ch.setOption(StandardSocketOptions.SO_BROADCAST, true);
            ch.bind(new InetSocketAddress(host, port));
            ch.configureBlocking(false);
            UdpEndpoint ep = new UdpEndpoint(ch, receiver);
            ch.register(selector, SelectionKey.OP_READ, ep);
            localUdp.put(ep.localAddress(), ep);
            return ep;
        } catch (BindException e) {
            closeQuietly(ch);
            return null;
        } catch (IOException e) {
            closeQuietly(ch);
            throw new UncheckedIOException("cannot bind UDP " + host + ":" + port + ": " + e.getMessage(), e);
        }
    }

    private static void closeQuietly(DatagramChannel ch) {
        if (ch != null) {
            try {
                ch.close();
            } catch (IOException ignored) {
                // nothing more to release
            }
        }
    }

    @Override
    public int poll(long nowNs) {
        int local = drainLocal(nowNs);
        // While frames between agents of this JVM keep the loop busy, look at the sockets only every
        // few cycles: a selectNow() is a system call, as costly as a whole in-memory hop.
        if (local > 0 && ++cyclesWithoutSelect < 16) {
            return local;
        }
        cyclesWithoutSelect = 0;
        try {
            // selectNow() counts only keys newly selected; keys that a blocking await() already put
            // in the selected set must be drained too, so look at the set, not at the count.
            selector.selectNow();
        } catch (IOException e) {
            LOG.warn("selector failed: {}", e.toString());
            return local;
        }
        readBudget = local > 0 ? BUSY_READ_BUDGET : READ_BUDGET;
        return local + (selector.selectedKeys().isEmpty() ? 0 : drainSelected(nowNs));
    }

    /** Delivers the frames handed over in memory, including those their receivers send meanwhile. */
    private int drainLocal(long nowNs) {
        int n = 0;
        LocalFrame f;
        while ((f = localQueue.poll()) != null) {
            if (f.to().isOpen()) {
                f.to().receiver.onDatagram(f.from(), f.data(), 0, f.data().length, nowNs);
                n++;
            }
        }
        return n;
    }

    private int drainSelected(long nowNs) {
        int delivered = 0;
        Iterator<SelectionKey> it = selector.selectedKeys().iterator();
        while (it.hasNext()) {
            SelectionKey key = it.next();
            it.remove();
            if (key.isValid()) {
                delivered += ((Handler) key.attachment()).onReady(key, nowNs);
            }
        }
        return delivered;
    }

    @Override
    public long nextEventNs() {
        return Long.MAX_VALUE;
    }

    /** {@code select()} counts whole milliseconds. */
    @Override
    public long awaitResolutionNs() {
        return 1_000_000;
    }

    @Override
    public void await(long timeoutNs) {
        if (!localQueue.isEmpty()) {
            return;
        }
        try {
            if (timeoutNs <= 0) {
                selector.selectNow();
            } else {
                long ms = Math.max(1, TimeUnit.NANOSECONDS.toMillis(timeoutNs));
                selector.select(ms);
            }
            // Selected keys are drained by the next poll.
        } catch (IOException e) {
            LOG.warn("selector failed: {}", e.toString());
        }
    }

    @Override
    public void wakeup() {
        selector.wakeup();
    }

    @Override
    public void flush() {
        if (gathering.isEmpty()) {
            return;
        }
        for (int i = 0; i < gathering.size(); i++) {
            gathering.get(i).flush();
        }
        gathering.clear();
    }

    /** True for an address of this host's loopback, where a datagram of any size stays whole. */
    private static boolean loopback(Address a) {
        String h = a.host();
        return h.startsWith("127.") || h.equals("::1") || h.equals("0:0:0:0:0:0:0:1") || h.equals("localhost");
    }

    @Override
    public void close() {
        flush();
        for (SelectionKey k : selector.keys()) {
            ((Handler) k.attachment()).close();
        }
        try {
            selector.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }

    private Address toAddress(SocketAddress sa) {
        InetSocketAddress isa = (InetSocketAddress) sa;
        Address a = addressCache.get(isa);
        if (a == null) {
            a = new Address(isa.getAddress().getHostAddress(), isa.getPort());
            if (addressCache.size() > 100_000) {
                addressCache.clear();
            }
            addressCache.put(isa, a);
        }
        return a;
    }

    private InetSocketAddress toSocketAddress(Address a) {
        InetSocketAddress isa = socketAddressCache.get(a);
        if (isa == null) {
            isa = new InetSocketAddress(a.host(), a.port());
            if (socketAddressCache.size() > 100_000) {
                socketAddressCache.clear();
            }
            socketAddressCache.put(a, isa);
        }
        return isa;
    }

    private final class UdpEndpoint implements Endpoint, Handler {
        private final DatagramChannel channel;
        private final Receiver receiver;
        private final Address local;

        UdpEndpoint(DatagramChannel channel, Receiver receiver) throws IOException {
            this.channel = channel;
            this.receiver = receiver;
            InetSocketAddress la = (InetSocketAddress) channel.getLocalAddress();
            this.local = new Address(la.getAddress().getHostAddress(), la.getPort());
        }

        @Override
        public int onReady(SelectionKey key, long nowNs) {
            return key.isReadable() ? drain(nowNs) : 0;
        }

        int drain(long nowNs) {
            int n = 0;
            try {
                while (n < readBudget) {
                    receiveBuffer.clear();
                    SocketAddress from = channel.receive(receiveBuffer);
                    if (from == null) {
                        return n;
                    }
                    receiveBuffer.flip();
                    int len = receiveBuffer.remaining();
                    receiveBuffer.get(receiveArray, 0, len);
                    // The budget counts frames: a bundle spends as much of it as the frames it holds.
                    if (len >= 2 && (receiveArray[0] & 0xFF) == BUNDLE_MAGIC >>> 8 && (receiveArray[1] & 0xFF) == (BUNDLE_MAGIC & 0xFF)) {
                        n += unbundle(toAddress(from), len, nowNs);
                    } else {
                        n++;
                        receiver.onDatagram(toAddress(from), receiveArray, 0, len, nowNs);
                    }
                }
                return n;
            } catch (ClosedChannelException e) {
                return n;
            } catch (IOException e) {
                LOG.debug("receive on {} failed: {}", local, e.toString());
                return n;
            }
        }

        /**
         * Hands each frame of a bundle up on its own. A length that runs past the datagram, or a
         * frame past {@link #MAX_BUNDLE_FRAMES}, ends it: the rest goes up as one frame, which the
         * stack drops as malformed and counts. Returns the pieces handed up.
         */
        private int unbundle(Address from, int len, long nowNs) {
            int at = 2;
            int frames = 0;
            while (at < len) {
                int frameLength = at + 2 <= len ? (receiveArray[at] & 0xFF) << 8 | receiveArray[at + 1] & 0xFF : 0;
                if (frameLength == 0 || at + 2 + frameLength > len || frames == MAX_BUNDLE_FRAMES) {
                    receiver.onDatagram(from, receiveArray, at, len - at, nowNs);
                    return frames + 1;
                }
                receiver.onDatagram(from, receiveArray, at + 2, frameLength, nowNs);
                at += 2 + frameLength;
                frames++;
            }
            return Math.max(1, frames);
        }

        @Override
        public Address localAddress() {
            return local;
        }

        private java.util.function.ObjIntConsumer<Address> sendFailed = (to, frames) -> { };
        /** The bundles gathered this cycle, in the order they were begun. */
        private final java.util.ArrayList<Bundle> bundles = new java.util.ArrayList<>();
        /** The same by address (one per lane, chained), found without a search of them all. */
        private final Map<Address, Bundle> byAddress = new HashMap<>();

        @Override
        public void onSendFailure(java.util.function.ObjIntConsumer<Address> failed) {
            sendFailed = failed;
        }

        @Override
        public boolean send(Address to, byte[] data, int offset, int length) {
            return send(to, data, offset, length, 0);
        }

        @Override
        public boolean send(Address to, byte[] data, int offset, int length, int lane) {
            if (!channel.isOpen()) {
                return false;
            }
            if (localDelivery) {
                UdpEndpoint peer = localUdp.get(to);
                if (peer != null && peer.isOpen()) {
                    localQueue.add(new LocalFrame(local, peer, java.util.Arrays.copyOfRange(data, offset, offset + length)));
                    return true;
                }
            }
            if (!bundling) {
                return sendNow(to, data, offset, length);
            }
            Bundle first = byAddress.get(to);
            Bundle b = first;
            while (b != null && b.lane != lane) {
                b = b.otherLane;
            }
            int limit = b != null ? b.limit : loopback(to) ? LOOPBACK_BUNDLE_BYTES : BUNDLE_BYTES;
            if (length + 4 > limit) {
                if (b != null) {
                    sendBundle(b); // what was gathered first goes first
                }
                return sendNow(to, data, offset, length);
            }
            if (b == null) {
                if (bundles.isEmpty()) {
                    gathering.add(this);
                }
                Bundle pooled = bundlePool.poll();
                b = (pooled != null ? pooled : new Bundle()).start(to, lane, limit);
                b.otherLane = first;
                byAddress.put(to, b);
                bundles.add(b);
            } else if (!b.fits(length)) {
                sendBundle(b);
            }
            b.add(data, offset, length);
            return true;
        }

        /** Sends the bundles gathered this cycle. */
        void flush() {
            for (int i = 0; i < bundles.size(); i++) {
                Bundle b = bundles.get(i);
                sendBundle(b);
                b.otherLane = null;
                if (bundlePool.size() < MAX_POOLED_BUNDLES) {
                    bundlePool.add(b);
                }
            }
            bundles.clear();
            byAddress.clear();
        }

        /** One frame as it is; several as a bundle. */
        private void sendBundle(Bundle b) {
            if (b.frames == 0) {
                return;
            }
            boolean sent = b.frames == 1 ? sendNow(b.to, b.buf, 4, b.length - 4) : sendNow(b.to, b.buf, 0, b.length);
            if (!sent) {
                sendFailed.accept(b.to, b.frames);
            }
            b.frames = 0;
            b.length = 2;
        }

        private boolean sendNow(Address to, byte[] data, int offset, int length) {
            if (!channel.isOpen()) {
                return false;
            }
            try {
                return channel.send(ByteBuffer.wrap(data, offset, length), toSocketAddress(to)) > 0;
            } catch (IOException e) {
                LOG.debug("send from {} to {} failed: {}", local, to, e.toString());
                return false;
            }
        }

        @Override
        public boolean inMemoryTo(Address to) {
            if (!localDelivery) {
                return false;
            }
            UdpEndpoint peer = localUdp.get(to);
            return peer != null && peer.isOpen();
        }

        @Override
        public void close() {
            flush(); // what was sent before the close goes out
            gathering.remove(this);
            closeQuietly(channel);
            localUdp.remove(local, this);
        }

        @Override
        public boolean isOpen() {
            return channel.isOpen();
        }
    }
}
