package io.concord.testkit;

import io.concord.core.net.Address;
import io.concord.core.net.Endpoint;
import io.concord.core.time.ManualClock;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class VirtualNetworkTest {
    private final ManualClock clock = new ManualClock();

    private VirtualNetwork net(long seed, FaultPlan plan) {
        return new VirtualNetwork(new SplittableRandom(seed), plan, clock);
    }

    private static byte[] b(int i) {
        return new byte[]{(byte) i, (byte) (i >> 8), 0, 0};
    }

    /** Sends n datagrams a -> b and returns the first byte pairs of what arrived, in order. */
    private List<Integer> run(VirtualNetwork n, int count) {
        List<Integer> got = new ArrayList<>();
        Endpoint a = n.tryBind("h1", 1, (f, d, o, l, now) -> { });
        n.tryBind("h2", 2, (f, d, o, l, now) -> got.add((d[o] & 0xff) | (d[o + 1] & 0xff) << 8));
        for (int i = 0; i < count; i++) {
            a.send(new Address("h2", 2), b(i), 0, 4);
            clock.advanceNs(10_000);
            n.poll(clock.nanoTime());
        }
        clock.advanceMs(100);
        n.poll(clock.nanoTime());
        return got;
    }

    @Test
    void aPerfectNetworkDeliversEverythingInOrderAfterItsLatency() {
        VirtualNetwork n = net(1, FaultPlan.NONE);
        List<Integer> got = run(n, 100);
        List<Integer> expected = new ArrayList<>();
        for (int i = 0; i < 100; i++) {
            expected.add(i);
        }
        assertEquals(expected, got);
    }

    @Test
    void theFaultPlanDropsDuplicatesAndReordersAtRoughlyItsRates() {
        VirtualNetwork n = net(2, FaultPlan.lossy(0.2, 0.1, 0.3, 0));
        List<Integer> got = run(n, 5_000);
        long distinct = got.stream().distinct().count();
        assertTrue(distinct > 3_700 && distinct < 4_300, "about 80% arrive: " + distinct);
        assertTrue(got.size() - distinct > 250, "some arrive twice: " + (got.size() - distinct));
        int inversions = 0;
        for (int i = 1; i < got.size(); i++) {
            if (got.get(i) < got.get(i - 1)) {
                inversions++;
            }
        }
        assertTrue(inversions > 100, "some arrive out of order: " + inversions);
        assertEquals(n.sentCount() - n.droppedCount(), 5_000 - n.droppedCount());
    }

    @Test
    void corruptionFlipsBits() {
        VirtualNetwork n = net(3, new FaultPlan(0, 0, 0, 1.0, 50_000, 0, 0));
        List<byte[]> got = new ArrayList<>();
        Endpoint a = n.tryBind("h1", 1, (f, d, o, l, now) -> { });
        n.tryBind("h2", 2, (f, d, o, l, now) -> got.add(java.util.Arrays.copyOfRange(d, o, o + l)));
        a.send(new Address("h2", 2), new byte[8], 0, 8);
        clock.advanceMs(1);
        n.poll(clock.nanoTime());
        assertEquals(1, got.size());
        assertEquals(1, java.util.BitSet.valueOf(got.get(0)).cardinality());
    }

    @Test
    void theSameSeedGivesTheSameDeliveries() {
        List<Integer> first = run(net(9, FaultPlan.lossy(0.2, 0.1, 0.3, 0.05)), 500);
        List<Integer> second = run(net(9, FaultPlan.lossy(0.2, 0.1, 0.3, 0.05)), 500);
        List<Integer> other = run(net(10, FaultPlan.lossy(0.2, 0.1, 0.3, 0.05)), 500);
        assertEquals(first, second);
        assertFalse(first.equals(other));
    }

    @Test
    void aPortIsBoundOncePerHostAndFreedOnClose() {
        VirtualNetwork n = net(4, FaultPlan.NONE);
        Endpoint e = n.tryBind("h1", 7001, (f, d, o, l, now) -> { });
        assertNotNull(e);
        assertNull(n.tryBind("h1", 7001, (f, d, o, l, now) -> { }), "taken");
        assertNotNull(n.tryBind("h2", 7001, (f, d, o, l, now) -> { }), "another host has its own ports");
        e.close();
        assertNotNull(n.tryBind("h1", 7001, (f, d, o, l, now) -> { }));
        Endpoint any = n.tryBind("h1", 0, (f, d, o, l, now) -> { });
        assertEquals(VirtualNetwork.EPHEMERAL_BASE, any.localAddress().port());
    }

    @Test
    void aPartitionCutsBothWaysUntilHealed() {
        VirtualNetwork n = net(5, FaultPlan.NONE);
        List<String> got = new ArrayList<>();
        Endpoint a = n.tryBind("h1", 1, (f, d, o, l, now) -> got.add("a"));
        Endpoint b = n.tryBind("h2", 1, (f, d, o, l, now) -> got.add("b"));
        n.partition("h1", "h2");
        a.send(b.localAddress(), new byte[1], 0, 1);
        b.send(a.localAddress(), new byte[1], 0, 1);
        clock.advanceMs(1);
        n.poll(clock.nanoTime());
        assertEquals(List.of(), got);
        n.heal("h2", "h1");
        a.send(b.localAddress(), new byte[1], 0, 1);
        clock.advanceMs(1);
        n.poll(clock.nanoTime());
        assertEquals(List.of("b"), got);
    }

    @Test
    void aCrashedHostsPortsAreClosedAndDatagramsToThemAreLost() {
        VirtualNetwork n = net(6, FaultPlan.NONE);
        Endpoint a = n.tryBind("h1", 1, (f, d, o, l, now) -> { });
        n.tryBind("h2", 1, (f, d, o, l, now) -> { throw new AssertionError("delivered to a dead host"); });
        a.send(new Address("h2", 1), new byte[1], 0, 1);
        n.closeHost("h2");
        clock.advanceMs(1);
        n.poll(clock.nanoTime());
        assertFalse(n.isBound("h2", 1));
        assertEquals(1, n.droppedCount());
    }

    @Test
    void aFaultPlanRejectsImpossibleRates() {
        assertThrows(IllegalArgumentException.class, () -> FaultPlan.lossy(1.5, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new FaultPlan(0, 0, 0, 0, 0, 0, 0));
    }
}
