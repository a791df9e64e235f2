package io.concord.core.agent;

import io.concord.core.net.Address;
import io.concord.core.net.Endpoint;
import io.concord.core.net.SocketNetwork;
import io.concord.core.net.Transport;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.VirtualNetwork;
import io.concord.core.time.ManualClock;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class PortRangeTest {

    @Test
    void takesTheFirstFreePortAndReportsHeldOnesBelowAndInTheWindow() {
        VirtualNetwork net = new VirtualNetwork(new SplittableRandom(1), FaultPlan.NONE, new ManualClock());
        PortRange r = new PortRange(7001, 50, 5);
        List<Endpoint> eps = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            eps.add(r.bindFirstFree(net, Transport.UDP, "h", (f, d, o, l, n) -> { }, new ArrayList<>()));
        }
        eps.get(1).close(); // a hole at 7002
        List<Address> held = new ArrayList<>();
        Endpoint e = r.bindFirstFree(net, Transport.UDP, "h", (f, d, o, l, n) -> { }, held);
        assertEquals(7002, e.localAddress().port());
        assertEquals(List.of(7001, 7003, 7004, 7005, 7006), held.stream().map(Address::port).toList());
    }

    @Test
    void aFullRangeNamesTheRangeAndHowToWidenIt() {
        VirtualNetwork net = new VirtualNetwork(new SplittableRandom(1), FaultPlan.NONE, new ManualClock());
        PortRange r = PortRange.of(7001, 7002);
        r.bindFirstFree(net, Transport.UDP, "h", (f, d, o, l, n) -> { }, new ArrayList<>());
        r.bindFirstFree(net, Transport.UDP, "h", (f, d, o, l, n) -> { }, new ArrayList<>());
        IllegalStateException ex = assertThrows(IllegalStateException.class,
                () -> r.bindFirstFree(net, Transport.UDP, "h", (f, d, o, l, n) -> { }, new ArrayList<>()));
        assertTrue(ex.getMessage().contains("7001-7002 on h is full") && ex.getMessage().contains("-ports 7001-7004") && !ex.getMessage().contains("--ports"),
                ex.getMessage());
    }

    @Test
    void parsesRangesAndRejectsBadOnes() {
        assertEquals(new PortRange(7001, 200, 10), PortRange.parse("7001-7200"));
        assertEquals(new PortRange(9000, 200, 10), PortRange.parse("9000"));
        assertThrows(IllegalArgumentException.class, () -> PortRange.parse("7001-x"));
        assertThrows(IllegalArgumentException.class, () -> PortRange.parse("7200-7001"));
        assertThrows(IllegalArgumentException.class, () -> new PortRange(65500, 100, 10));
    }

    @Test
    void probingRealSocketsDoesNotHoldThePortsItProbes() {
        // A probe must release its port at once: a channel registered with the selector would keep
        // it until the next select, and the next agent of the same loop would see it held.
        try (SocketNetwork net = new SocketNetwork()) {
            int base = 7501;
            PortRange r = new PortRange(base, 40, 10);
            List<Integer> ports = new ArrayList<>();
            for (int i = 0; i < 5; i++) {
                List<Address> held = new ArrayList<>();
                ports.add(r.bindFirstFree(net, Transport.UDP, "127.0.0.1", (f, d, o, l, n) -> { }, held).localAddress().port());
            }
            for (int i = 1; i < ports.size(); i++) {
                assertTrue(ports.get(i) - ports.get(i - 1) <= 2, "ports " + ports + " skip probed ones");
            }
        }
    }
}
