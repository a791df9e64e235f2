package io.concord.bench.throughput;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.ArrayList;
import java.util.List;

/**
 * The floor: raw UDP datagrams of the content's size on loopback, one thread sending from S
 * sockets as fast as the kernel takes them, one thread receiving on R sockets through a selector,
 * as Concord's one loop does. Nothing is acknowledged, so what the receiver misses is lost: the
 * rate is what arrives.
 */
public final class UdpFloor {
    private UdpFloor() {
    }

    /** R receiving sockets and their counting thread; {@link #close()} stops it. */
    public static final class Receivers implements AutoCloseable {
        private final List<DatagramChannel> channels = new ArrayList<>();
        private final Selector selector;
        private final Thread thread;
        private volatile boolean running = true;

        public Receivers(int r) throws IOException {
            selector = Selector.open();
            for (int i = 0; i < r; i++) {
                DatagramChannel ch = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0));
                ch.setOption(java.net.StandardSocketOptions.SO_RCVBUF, 1 << 20);
                ch.configureBlocking(false);
                ch.register(selector, SelectionKey.OP_READ);
                channels.add(ch);
            }
            thread = new Thread(this::run, "udp-floor-receiver");
            thread.setDaemon(true);
            thread.start();
        }

        public List<Integer> ports() throws IOException {
            List<Integer> p = new ArrayList<>();
            for (DatagramChannel ch : channels) {
                p.add(((InetSocketAddress) ch.getLocalAddress()).getPort());
            }
            return p;
        }

        private void run() {
            ByteBuffer buf = ByteBuffer.allocateDirect(65_536);
            try {
                while (running) {
                    if (selector.select(100) == 0) {
                        continue;
                    }
                    for (SelectionKey k : selector.selectedKeys()) {
                        DatagramChannel ch = (DatagramChannel) k.channel();
                        int n = 0;
                        buf.clear();
                        while (ch.receive(buf) != null) {
                            n++;
                            buf.clear();
                        }
                        Counters.RECEIVED.addAndGet(n);
                    }
                    selector.selectedKeys().clear();
                }
            } catch (IOException e) {
                // closed
            }
        }

        @Override
        public void close() throws IOException {
            running = false;
            selector.wakeup();
            try {
                thread.join(2_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            selector.close();
            for (DatagramChannel ch : channels) {
                ch.close();
            }
        }
    }

    /** Sends from {@code s} sockets to the ports (sender i to port i mod ports) until {@link Counters#stopped}. */
    public static Thread startSenders(int s, List<Integer> ports, int bytes) throws IOException {
        List<DatagramChannel> from = new ArrayList<>();
        List<InetSocketAddress> to = new ArrayList<>();
        for (int i = 0; i < s; i++) {
            DatagramChannel ch = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0));
            from.add(ch);
            to.add(new InetSocketAddress("127.0.0.1", ports.get(i % ports.size())));
        }
        ByteBuffer payload = ByteBuffer.allocateDirect(bytes);
        payload.put(Counters.content(bytes).getBytes(java.nio.charset.StandardCharsets.US_ASCII)).flip();
        Thread t = new Thread(() -> {
            try {
                while (!Counters.stopped()) {
                    for (int i = 0; i < from.size(); i++) {
                        payload.rewind();
                        if (from.get(i).send(payload, to.get(i)) > 0) {
                            Counters.SENT.incrementAndGet();
                        }
                    }
                }
                for (DatagramChannel ch : from) {
                    ch.close();
                }
            } catch (IOException e) {
                // closed
            }
        }, "udp-floor-sender");
        t.setDaemon(true);
        t.start();
        return t;
    }
}
