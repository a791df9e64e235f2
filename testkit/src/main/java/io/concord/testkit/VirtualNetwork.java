package io.concord.testkit;

import io.concord.core.net.Address;
import io.concord.core.net.Endpoint;
import io.concord.core.net.Network;
import io.concord.core.net.Receiver;
import io.concord.core.time.Clock;

import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.Set;
import java.util.random.RandomGenerator;

/**
 * A deterministic datagram network with a port space per virtual host. Sending schedules a
 * delivery at a virtual time chosen by the {@link FaultPlan} and the seeded random source;
 * {@link #poll} delivers what is due, in time order, ties broken by send order. Same seed, same
 * sends: same deliveries.
 *
 * <p>Single-threaded: the simulation's thread sends and polls.
 */
public final class VirtualNetwork implements Network {
    /** First port handed out for a bind to port 0. */
    public static final int EPHEMERAL_BASE = 40_000;

    private final RandomGenerator random;
    private final Clock clock;
    private FaultPlan plan;
    private Medium medium;
    private String mediumFromHost;
    private final Map<Address, VirtualEndpoint> bound = new HashMap<>();
    private final Map<Address, VirtualEndpoint> boundTcp = new HashMap<>();
    private final Map<Integer, java.util.List<VirtualEndpoint>> listeners = new HashMap<>();
    /** The host of a broadcast: delivered to every host's listener on the port. */
    public static final String BROADCAST = "255.255.255.255";
    private final Map<String, Long> lastTcpDelivery = new HashMap<>();
    private final Map<String, Integer> nextEphemeral = new HashMap<>();
    private final PriorityQueue<Delivery> pending = new PriorityQueue<>();
    private final Set<String> partitions = new HashSet<>();
    private final Set<String> downHosts = new HashSet<>();
    /** Addresses whose process is paused, until when: what arrives there waits (its socket buffers it). */
    private final Map<Address, Long> heldUntil = new HashMap<>();
    private long sequence;
    private long sent;
    private long sentBytes;
    private long delivered;
    private long dropped;

    /**
     * @param random the seeded source every fault is drawn from
     * @param plan   what the network does to datagrams
     * @param clock  the virtual clock deliveries are scheduled on
     */
    public VirtualNetwork(RandomGenerator random, FaultPlan plan, Clock clock) {
        this.random = random;
        this.plan = plan;
        this.clock = clock;
    }

    /** Changes the fault plan from now on. */
    public void setFaultPlan(FaultPlan plan) {
        this.plan = plan;
    }

    public FaultPlan faultPlan() {
        return plan;
    }

    /**
     * Puts a medium on the datagrams that a host sends (after the fault plan has let them through),
     * or removes it with {@code null}.
     */
    public void setMedium(String fromHost, Medium m) {
        this.mediumFromHost = fromHost;
        this.medium = m;
    }

    /** Cuts every datagram between two hosts, both ways, until {@link #heal}. */
    public void partition(String hostA, String hostB) {
        partitions.add(key(hostA, hostB));
    }

    /** Restores the link between two hosts. */
    public void heal(String hostA, String hostB) {
        partitions.remove(key(hostA, hostB));
    }

    /** Restores every link. */
    public void healAll() {
        partitions.clear();
    }

    /** Takes a host's link down (its datagrams in and out are lost) or up again. */
    public void setHostDown(String host, boolean down) {
        if (down) {
            downHosts.add(host);
        } else {
            downHosts.remove(host);
        }
    }

    private static String key(String a, String b) {
        return a.compareTo(b) <= 0 ? a + "|" + b : b + "|" + a;
    }

    /** Datagrams sent, delivered, and lost (dropped by the plan, a partition or a closed port). */
    public long sentCount() {
        return sent;
    }

    /** Bytes of the datagrams counted by {@link #sentCount()}. */
    public long sentBytes() {
        return sentBytes;
    }

    public long deliveredCount() {
        return delivered;
    }

    public long droppedCount() {
        return dropped;
    }

    /** True if a port is bound on the host. */
    public boolean isBound(String host, int port) {
        return bound.containsKey(new Address(host, port));
    }

    @Override
    public Endpoint tryBind(io.concord.core.net.Transport transport, String host, int port, Receiver receiver) {
        if (transport == io.concord.core.net.Transport.UDP) {
            return tryBind(host, port, receiver);
        }
        return bind(boundTcp, host, port, receiver, true);
    }

    /**
     * A TCP frame: reliable and in order, so the fault plan and the medium do not touch it; a
     * partition or a link down still loses it, as a broken connection would.
     */
    private void sendTcp(Address from, Address to, byte[] data, int offset, int length) {
        sent++;
        sentBytes += length;
        if (blocked(from.host(), to.host())) {
            dropped++;
            return;
        }
        String link = from + ">" + to;
        long at = Math.max(clock.nanoTime() + plan.latencyNs(), lastTcpDelivery.getOrDefault(link, 0L));
        lastTcpDelivery.put(link, at);
        pending.add(new Delivery(at, sequence++, from, to, Arrays.copyOfRange(data, offset, offset + length), true, null));
    }

    @Override
    public Endpoint tryBind(String host, int port, Receiver receiver) {
        return bind(bound, host, port, receiver, false);
    }

    /** Binds in a port space (UDP's or TCP's); port 0 takes the next free one from the ephemeral base. */
    private Endpoint bind(Map<Address, VirtualEndpoint> space, String host, int port, Receiver receiver, boolean tcp) {
        int p = port;
        if (p == 0) {
            String key = (tcp ? "tcp:" : "udp:") + host;
            p = nextEphemeral.getOrDefault(key, EPHEMERAL_BASE);
            while (space.containsKey(new Address(host, p))) {
                p++;
            }
            nextEphemeral.put(key, p + 1);
        }
        Address a = new Address(host, p);
        if (space.containsKey(a)) {
            return null;
        }
        VirtualEndpoint ep = new VirtualEndpoint(a, receiver, tcp);
        space.put(a, ep);
        return ep;
    }

    @Override
    public Endpoint bindListener(String host, int port, boolean broadcast, Receiver receiver) {
        VirtualEndpoint ep = new VirtualEndpoint(new Address(host, port), receiver, false);
        ep.listener = true;
        listeners.computeIfAbsent(port, k -> new java.util.ArrayList<>()).add(ep);
        return ep;
    }

    @Override
    public java.util.List<String> broadcastAddresses(String host) {
        return java.util.List.of(BROADCAST);
    }

    /** Closes every endpoint bound on a host, as a crash of its processes would. */
    public void closeHost(String host) {
        for (VirtualEndpoint ep : bound.values().toArray(new VirtualEndpoint[0])) {
            if (ep.local.host().equals(host)) {
                ep.close();
            }
        }
        for (VirtualEndpoint ep : boundTcp.values().toArray(new VirtualEndpoint[0])) {
            if (ep.local.host().equals(host)) {
                ep.close();
            }
        }
        for (java.util.List<VirtualEndpoint> l : listeners.values()) {
            for (VirtualEndpoint ep : l.toArray(new VirtualEndpoint[0])) {
                if (ep.local.host().equals(host)) {
                    ep.close();
                }
            }
        }
    }

    /** The endpoints a datagram to this address reaches: the bound one, or the listeners on its port. */
    private java.util.List<VirtualEndpoint> targets(Address to) {
        VirtualEndpoint ep = bound.get(to);
        if (ep != null) {
            return java.util.List.of(ep);
        }
        java.util.List<VirtualEndpoint> l = listeners.get(to.port());
        if (l == null) {
            return java.util.List.of();
        }
        java.util.List<VirtualEndpoint> out = new java.util.ArrayList<>(1);
        for (VirtualEndpoint e : l) {
            if (to.host().equals(BROADCAST) || e.local.host().equals(to.host())) {
                out.add(e);
            }
        }
        return out;
    }

    private void send(Address from, Address to, byte[] data, int offset, int length) {
        if (to.host().equals(BROADCAST)) {
            for (VirtualEndpoint e : targets(to)) {
                sendOne(from, to, e, data, offset, length);
            }
            return;
        }
        sendOne(from, to, null, data, offset, length);
    }

    private void sendOne(Address from, Address to, VirtualEndpoint target, byte[] data, int offset, int length) {
        Address hostOf = target != null ? target.local : to;
        sent++;
        sentBytes += length;
        if (blocked(from.host(), hostOf.host()) || random.nextDouble() < plan.dropRate()) {
            dropped++;
            return;
        }
        int copies = random.nextDouble() < plan.duplicateRate() ? 2 : 1;
        for (int c = 0; c < copies; c++) {
            byte[] bytes = Arrays.copyOfRange(data, offset, offset + length);
            if (bytes.length > 0 && random.nextDouble() < plan.corruptRate()) {
                int bit = random.nextInt(bytes.length * 8);
                bytes[bit >>> 3] ^= (byte) (1 << (bit & 7));
            }
            long delay = plan.latencyNs() + (plan.jitterNs() > 0 ? random.nextLong(plan.jitterNs()) : 0);
            if (plan.reorderDelayNs() > 0 && random.nextDouble() < plan.reorderRate()) {
                delay += 1 + random.nextLong(plan.reorderDelayNs());
            }
            long at = clock.nanoTime() + delay;
            if (medium != null && from.host().equals(mediumFromHost)) {
                medium.carry(from, to, bytes, (extraNs, b) -> pending.add(new Delivery(at + Math.max(0, extraNs),
                        sequence++, from, to, b.clone(), false, target)));
            } else {
                pending.add(new Delivery(at, sequence++, from, to, bytes, false, target));
            }
        }
    }

    private boolean blocked(String a, String b) {
        return downHosts.contains(a) || downHosts.contains(b) || (!partitions.isEmpty() && partitions.contains(key(a, b)));
    }

    @Override
    public int poll(long nowNs) {
        int n = 0;
        Delivery d;
        while ((d = pending.peek()) != null && d.timeNs <= nowNs) {
            pending.poll();
            VirtualEndpoint ep;
            if (d.target != null) {
                ep = d.target.open ? d.target : null;
            } else if (d.tcp) {
                ep = boundTcp.get(d.to);
            } else {
                java.util.List<VirtualEndpoint> t = targets(d.to);
                ep = t.isEmpty() ? null : t.get(t.size() - 1); // a unicast to a shared port: the last bound, as Linux does
            }
            if (ep == null || blocked(d.from.host(), ep.local.host())) {
                dropped++;
                continue;
            }
            Long until = heldUntil.get(ep.local);
            if (until != null) {
                if (until > nowNs) {
                    // Its process is paused: the datagram waits in the socket's buffer, in order.
                    pending.add(new Delivery(until, d.seq, d.from, d.to, d.data, d.tcp, ep));
                    continue;
                }
                heldUntil.remove(ep.local);
            }
            delivered++;
            n++;
            ep.receiver.onDatagram(d.from, d.data, 0, d.data.length, nowNs);
        }
        return n;
    }

    /**
     * Holds what arrives at these addresses until the given time, as the socket buffers of a
     * paused process do (the test kit's pause of a runtime, {@link Simulation#pause}).
     */
    public void holdUntil(java.util.Collection<Address> addresses, long untilNs) {
        for (Address a : addresses) {
            heldUntil.merge(a, untilNs, Math::max);
        }
    }

    @Override
    public long nextEventNs() {
        Delivery d = pending.peek();
        return d == null ? Long.MAX_VALUE : d.timeNs;
    }

    /** Datagrams in flight. */
    public int inFlight() {
        return pending.size();
    }

    @Override
    public void await(long timeoutNs) {
        // Virtual time does not pass by waiting; the simulation advances it.
    }

    @Override
    public void wakeup() {
        // Single-threaded: nothing to wake.
    }

    @Override
    public void close() {
        for (VirtualEndpoint ep : bound.values().toArray(new VirtualEndpoint[0])) {
            ep.close();
        }
        for (VirtualEndpoint ep : boundTcp.values().toArray(new VirtualEndpoint[0])) {
            ep.close();
        }
        pending.clear();
    }

    private record Delivery(long timeNs, long seq, Address from, Address to, byte[] data, boolean tcp,
                            VirtualEndpoint target)
            implements Comparable<Delivery> {
        @Override
        public int compareTo(Delivery o) {
            int c = Long.compare(timeNs, o.timeNs);
            return c != 0 ? c : Long.compare(seq, o.seq);
        }
    }

    private final class VirtualEndpoint implements Endpoint {
        private final Address local;
        private final Receiver receiver;
        private final boolean tcp;
        private boolean open = true;
        private boolean listener;

        VirtualEndpoint(Address local, Receiver receiver, boolean tcp) {
            this.local = local;
            this.receiver = receiver;
            this.tcp = tcp;
        }

        @Override
        public Address localAddress() {
            return local;
        }

        @Override
        public boolean send(Address to, byte[] data, int offset, int length) {
            if (!open) {
                return false;
            }
            if (tcp) {
                sendTcp(local, to, data, offset, length);
            } else {
                VirtualNetwork.this.send(local, to, data, offset, length);
            }
            return true;
        }

        @Override
        public void close() {
            if (open) {
                open = false;
                if (listener) {
                    java.util.List<VirtualEndpoint> l = listeners.get(local.port());
                    if (l != null) {
                        l.remove(this);
                    }
                } else {
                    (tcp ? boundTcp : bound).remove(local);
                }
            }
        }

        @Override
        public boolean isOpen() {
            return open;
        }
    }
}
