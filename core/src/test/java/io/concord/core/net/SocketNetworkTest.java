package io.concord.core.net;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

class SocketNetworkTest {
    private static final Receiver IGNORE = (from, data, offset, length, nowNs) -> { };

    @Test
    void saysWhichDestinationsItHandsOverInMemory() {
        try (SocketNetwork net = new SocketNetwork()) {
            Endpoint a = net.tryBind("127.0.0.1", 0, IGNORE);
            Endpoint b = net.tryBind("127.0.0.1", 0, IGNORE);
            assertNotNull(a);
            assertNotNull(b);
            assertTrue(a.inMemoryTo(b.localAddress()), "an endpoint of the same network");
            assertFalse(a.inMemoryTo(new Address("127.0.0.1", 9)), "a port this network does not hold");
            b.close();
            assertFalse(a.inMemoryTo(b.localAddress()), "a closed endpoint");
        }
    }

    @Test
    void handsNothingOverInMemoryWhenToldToUseTheKernel() {
        try (SocketNetwork net = new SocketNetwork(1 << 16, false)) {
            Endpoint a = net.tryBind("127.0.0.1", 0, IGNORE);
            Endpoint b = net.tryBind("127.0.0.1", 0, IGNORE);
            assertFalse(a.inMemoryTo(b.localAddress()));
        }
    }

    @Test
    void aFloodOnOnePortLeavesTheLoopAfterABoundedReadingAndTheOtherPortsAreRead() throws Exception {
        try (SocketNetwork net = new SocketNetwork(1 << 20, false);
             java.nio.channels.DatagramChannel attacker = java.nio.channels.DatagramChannel.open()) {
            int[] flooded = new int[1];
            int[] quiet = new int[1];
            Endpoint target = net.tryBind("127.0.0.1", 0, (from, data, offset, length, nowNs) -> flooded[0]++);
            Endpoint other = net.tryBind("127.0.0.1", 0, (from, data, offset, length, nowNs) -> quiet[0]++);
            java.net.InetSocketAddress to = new java.net.InetSocketAddress("127.0.0.1", target.localAddress().port());
            for (int i = 0; i < 500; i++) {
                attacker.send(java.nio.ByteBuffer.wrap(new byte[32]), to);
            }
            attacker.send(java.nio.ByteBuffer.wrap(new byte[32]),
                    new java.net.InetSocketAddress("127.0.0.1", other.localAddress().port()));
            // Loopback datagrams are queued at the receiver when send returns.
            int first = net.poll(0);
            assertEquals(SocketNetwork.READ_BUDGET + 1, first, "one poll reads at most the budget from the flooded port");
            assertEquals(1, quiet[0], "and reads the other port in the same poll");
            int polls = 1;
            while (flooded[0] < 500) {
                assertTrue(net.poll(0) <= SocketNetwork.READ_BUDGET);
                polls++;
            }
            assertEquals((500 + SocketNetwork.READ_BUDGET - 1) / SocketNetwork.READ_BUDGET, polls, "the rest over the next polls, none lost");
        }
    }

    @Test
    void whileTheAgentsOfTheJvmHaveFramesForEachOtherAFloodedPortIsReadAFewFramesAtATime() throws Exception {
        try (SocketNetwork net = new SocketNetwork(1 << 20, true);
             java.nio.channels.DatagramChannel attacker = java.nio.channels.DatagramChannel.open()) {
            int[] flooded = new int[1];
            Endpoint a = net.tryBind("127.0.0.1", 0, IGNORE);
            Endpoint b = net.tryBind("127.0.0.1", 0, IGNORE);
            Endpoint target = net.tryBind("127.0.0.1", 0, (from, data, offset, length, nowNs) -> flooded[0]++);
            java.net.InetSocketAddress to = new java.net.InetSocketAddress("127.0.0.1", target.localAddress().port());
            for (int i = 0; i < 500; i++) {
                attacker.send(java.nio.ByteBuffer.wrap(new byte[32]), to);
            }
            int read = 0;
            for (int i = 0; i < 64; i++) {
                a.send(b.localAddress(), new byte[8], 0, 8); // in memory: local work for every poll
                int before = flooded[0];
                net.poll(0);
                assertTrue(flooded[0] - before <= SocketNetwork.BUSY_READ_BUDGET,
                        "a poll with local work read " + (flooded[0] - before) + " datagrams of the flood");
                read += flooded[0] - before;
            }
            assertTrue(read > 0, "the flooded port is still read");
            int before = flooded[0];
            net.poll(0);
            assertEquals(SocketNetwork.READ_BUDGET, flooded[0] - before, "with no local work waiting, the full budget");
        }
    }

    @Test
    void aTcpEndpointWithSeveralOutboundStreamsCloses() {
        try (SocketNetwork net = new SocketNetwork()) {
            Endpoint a = net.tryBind(Transport.TCP, "127.0.0.1", 0, IGNORE);
            Endpoint b = net.tryBind(Transport.TCP, "127.0.0.1", 0, IGNORE);
            Endpoint c = net.tryBind(Transport.TCP, "127.0.0.1", 0, IGNORE);
            assertTrue(a.send(b.localAddress(), new byte[8], 0, 8));
            assertTrue(a.send(c.localAddress(), new byte[8], 0, 8));
            net.poll(0);
            // Each stream takes itself out of the endpoint's map as it closes: this threw
            // ConcurrentModificationException when the endpoint closed them while walking that map.
            a.close();
        }
    }
}
