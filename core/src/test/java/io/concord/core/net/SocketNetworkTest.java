package io.concord.core.net;

import org.junit.jupiter.api.Test;

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
}
