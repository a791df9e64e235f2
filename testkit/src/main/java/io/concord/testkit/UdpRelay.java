package io.concord.testkit;

import io.concord.core.net.Address;
import io.concord.core.time.Clock;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketException;
import java.util.Arrays;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A man in the middle on real UDP sockets, between two agents A and B: A sends to the relay's
 * {@link #portFacingA()} as if it were B, and B to {@link #portFacingB()} as if it were A. Datagrams
 * from A to B pass through a {@link Medium}; B's answers pass unchanged. Each side sees the relay's
 * address as its peer's, so the relay is transparent to the platform. Loopback only.
 */
public final class UdpRelay implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(UdpRelay.class);

    private final DatagramSocket facingA;
    private final DatagramSocket facingB;
    private final InetSocketAddress b;
    private volatile InetSocketAddress a;
    private final Medium medium;
    private final ScheduledExecutorService delays = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "udp-relay-delays");
        t.setDaemon(true);
        return t;
    });
    private final AtomicLong carried = new AtomicLong();
    private final Object idle = new Object();
    private int delayed;
    private volatile boolean open = true;

    /**
     * @param agentB the real address of B
     * @param medium what happens to datagrams from A to B
     */
    public UdpRelay(Address agentB, Medium medium) throws SocketException {
        this.b = new InetSocketAddress(agentB.host(), agentB.port());
        this.medium = medium;
        this.facingA = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        this.facingB = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        start("relay-a-to-b", facingA, true);
        start("relay-b-to-a", facingB, false);
    }

    /** The port A sends to, standing for B. */
    public Address portFacingA() {
        return new Address("127.0.0.1", facingA.getLocalPort());
    }

    /** The port B sends to, standing for A. */
    public Address portFacingB() {
        return new Address("127.0.0.1", facingB.getLocalPort());
    }

    /** Datagrams from A that reached the medium. */
    public long carried() {
        return carried.get();
    }

    private void start(String name, DatagramSocket in, boolean fromA) {
        Thread t = new Thread(() -> {
            byte[] buf = new byte[65_536];
            while (open) {
                DatagramPacket p = new DatagramPacket(buf, buf.length);
                try {
                    in.receive(p);
                } catch (IOException e) {
                    if (open) {
                        LOG.warn("relay receive failed: {}", e.toString());
                    }
                    return;
                }
                byte[] data = Arrays.copyOfRange(p.getData(), p.getOffset(), p.getOffset() + p.getLength());
                if (fromA) {
                    a = (InetSocketAddress) p.getSocketAddress();
                    carried.incrementAndGet();
                    Address from = new Address(a.getHostString(), a.getPort());
                    Address to = new Address(b.getHostString(), b.getPort());
                    medium.carry(from, to, data, (delayNs, bytes) -> forward(facingB, bytes.clone(), b, delayNs));
                } else if (a != null) {
                    forward(facingA, data, a, 0);
                }
            }
        }, name);
        t.setDaemon(true);
        t.start();
    }

    private void forward(DatagramSocket out, byte[] data, InetSocketAddress to, long delayNs) {
        Runnable send = () -> {
            try {
                out.send(new DatagramPacket(data, data.length, to));
            } catch (IOException e) {
                if (open) {
                    LOG.warn("relay send failed: {}", e.toString());
                }
            }
        };
        if (delayNs <= 0) {
            send.run();
        } else {
            synchronized (idle) {
                delayed++;
            }
            delays.schedule(() -> {
                send.run();
                synchronized (idle) {
                    delayed--;
                    idle.notifyAll();
                }
            }, delayNs, TimeUnit.NANOSECONDS);
        }
    }

    /**
     * Waits until every datagram the medium delayed has been sent on.
     *
     * @return false if some are still held after {@code timeoutMs}
     */
    public boolean awaitDelayedSent(long timeoutMs) throws InterruptedException {
        // The system's clock: the relay's delays run on a real scheduler, between real sockets.
        Clock clock = Clock.system();
        long deadline = clock.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        synchronized (idle) {
            while (delayed > 0) {
                long left = deadline - clock.nanoTime();
                if (left <= 0) {
                    return false;
                }
                idle.wait(Math.max(1, TimeUnit.NANOSECONDS.toMillis(left)));
            }
            return true;
        }
    }

    @Override
    public void close() {
        open = false;
        facingA.close();
        facingB.close();
        delays.shutdownNow();
    }
}
