package io.concord.layers;

import io.concord.layers.defence.Defence;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.layer.Layer;
import io.concord.core.net.Address;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Medium;
import io.concord.testkit.Simulation;
import io.concord.testkit.UdpRelay;
import io.concord.layers.security.IdentityStore;
import io.concord.layers.security.PlatformKey;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

/**
 * Two agents, A (sender) and B (receiver), with the class-7 stack, and a medium on the way from A
 * to B: on the virtual network, or on real UDP sockets through a {@link UdpRelay}. A third host M
 * can run agents that attack B directly.
 */
abstract class ThreatWorld implements AutoCloseable {
    static final String PLATFORM = "plat";

    /** B: records what reaches it, and wakes whoever waits for it. */
    static final class Receiver extends Agent {
        final BlockingQueue<AclMessage> got = new LinkedBlockingQueue<>();

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    AclMessage m;
                    while ((m = receive()) != null) {
                        record(m);
                    }
                    block();
                }
            });
        }

        private synchronized void record(AclMessage m) {
            got.add(m);
            notifyAll();
        }

        /** Waits for the n-th message (another thread's loop delivers them). */
        synchronized boolean awaitCount(int n, long timeoutMs) throws InterruptedException {
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
            while (got.size() < n) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    return false;
                }
                wait(Math.max(1, TimeUnit.NANOSECONDS.toMillis(left)));
            }
            return true;
        }
    }

    /** An agent that does only what the test tells it to. */
    static final class Puppet extends Agent {
    }

    final Receiver receiver = new Receiver();
    final Puppet sender = new Puppet();
    final long windowMs;

    final Profile profile;
    /** The sequence layer's settings, or {@code null} for the defaults. */
    final io.concord.layers.sequence.SequenceLayer.Config sequence;
    /** The defences the stacks are built without (a threat test's), usually none. */
    final java.util.Set<Defence> off;

    ThreatWorld(long windowMs, Profile profile, io.concord.layers.sequence.SequenceLayer.Config sequence, java.util.Set<Defence> off) {
        this.windowMs = windowMs;
        this.profile = profile;
        this.sequence = sequence;
        this.off = off;
    }

    Supplier<List<Layer>> stack() {
        SafetyStack.Builder b = Stacks.builder(profile).acceptanceWindowMs(windowMs).withoutDefences(off);
        if (sequence != null) {
            b.sequence(sequence);
        }
        return b.build();
    }

    Supplier<List<Layer>> stackWithKey(PlatformKey key) {
        return SafetyStack.builder().profile(Profile.CLASS_7).platformKey(key).identities(IdentityStore.ephemeral())
                .acceptanceWindowMs(windowMs).build();
    }

    /** B's AID as A must address it (through the medium). */
    abstract AID receiverAsSeenByA();

    /** B's AID with its direct address (for attackers that skip the medium). */
    abstract AID receiverDirect();

    /** Has A send each content to B, on A's loop. */
    abstract void send(Agent from, AID to, String... contents);

    /** Starts an attacker agent on host M. */
    abstract AID startOnM(String name, Agent agent, Supplier<List<Layer>> stack);

    /** Starts an attacker on a second attacking host (it may reuse a name taken on M). */
    AID startOnM2(String name, Agent agent, Supplier<List<Layer>> stack) {
        return startOnHost("host-m2", name, agent, stack);
    }

    /** Starts an attacker on a third attacking host. */
    AID startOnM3(String name, Agent agent, Supplier<List<Layer>> stack) {
        return startOnHost("host-m3", name, agent, stack);
    }

    abstract AID startOnHost(String host, String name, Agent agent, Supplier<List<Layer>> stack);

    /** Waits until a condition on B's counters holds (bounded). */
    abstract void awaitDrops(java.util.function.BooleanSupplier condition);

    /** Waits until B has received {@code n} messages in all (bounded; false if not). */
    abstract boolean awaitReceived(int n);

    /** Lets everything in flight settle: what B gets after this, it got. */
    abstract void settle(long ms);

    abstract Map<String, Long> receiverDrops();

    /** What B received, as contents, in order. */
    List<String> received() {
        List<String> out = new ArrayList<>();
        for (AclMessage m : receiver.got) {
            out.add(m.getSender().localName() + ":" + m.getContent());
        }
        return out;
    }

    static List<String> expected(String from, int n) {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            out.add(from + ":" + "m" + i);
        }
        return out;
    }

    static String[] contents(int n) {
        String[] c = new String[n];
        for (int i = 0; i < n; i++) {
            c[i] = "m" + i;
        }
        return c;
    }

    /** The virtual network, deterministic, in virtual time. */
    static final class Virtual extends ThreatWorld {
        private final Simulation sim = new Simulation(77, FaultPlan.NONE).platformName(PLATFORM);
        private final AgentRuntime a;
        private final AgentRuntime b;
        private final AID bAid;

        Virtual(Medium medium, long windowMs) {
            this(medium, windowMs, Profile.CLASS_7);
        }

        Virtual(Medium medium, long windowMs, Profile profile) {
            this(medium, windowMs, profile, null);
        }

        Virtual(Medium medium, long windowMs, Profile profile, io.concord.layers.sequence.SequenceLayer.Config sequence) {
            this(medium, windowMs, profile, sequence, java.util.Set.of());
        }

        Virtual(Medium medium, long windowMs, Profile profile, io.concord.layers.sequence.SequenceLayer.Config sequence,
                java.util.Set<Defence> off) {
            super(windowMs, profile, sequence, off);
            a = sim.newRuntime("host-a", stack());
            b = sim.newRuntime("host-b", stack());
            bAid = b.startAgent("b", receiver);
            a.startAgent("a", sender);
            sim.network().setMedium("host-a", medium);
        }

        @Override
        AID receiverAsSeenByA() {
            return bAid;
        }

        @Override
        AID receiverDirect() {
            return bAid;
        }

        @Override
        void send(Agent from, AID to, String... contents) {
            for (String c : contents) {
                from.send(new AclMessage(Performative.INFORM).addReceiver(to).setContent(c));
            }
        }

        @Override
        AID startOnM(String name, Agent agent, Supplier<List<Layer>> stack) {
            return startOnHost("host-m", name, agent, stack);
        }

        @Override
        AID startOnHost(String host, String name, Agent agent, Supplier<List<Layer>> stack) {
            return sim.newRuntime(host, stack).startAgent(name, agent);
        }

        @Override
        void awaitDrops(java.util.function.BooleanSupplier condition) {
            sim.runUntil(condition, 120_000);
        }

        @Override
        boolean awaitReceived(int n) {
            return sim.runUntil(() -> receiver.got.size() >= n, 120_000);
        }

        @Override
        void settle(long ms) {
            sim.runFor(ms);
        }

        @Override
        Map<String, Long> receiverDrops() {
            return b.drops();
        }

        @Override
        public void close() {
            sim.close();
        }
    }

    /** Real UDP sockets on loopback, separate runtimes, and a relay carrying the medium. */
    static final class RealUdp extends ThreatWorld {
        private final AgentRuntime a;
        private final AgentRuntime b;
        private final List<AgentRuntime> attackers = new ArrayList<>();
        private final UdpRelay relay;
        private final AID bDirect;
        private final AID bViaRelay;
        private int markers;

        RealUdp(Medium medium, long windowMs) throws Exception {
            this(medium, windowMs, Profile.CLASS_7);
        }

        RealUdp(Medium medium, long windowMs, Profile profile) throws Exception {
            this(medium, windowMs, profile, null);
        }

        RealUdp(Medium medium, long windowMs, Profile profile, io.concord.layers.sequence.SequenceLayer.Config sequence)
                throws Exception {
            this(medium, windowMs, profile, sequence, java.util.Set.of());
        }

        RealUdp(Medium medium, long windowMs, Profile profile, io.concord.layers.sequence.SequenceLayer.Config sequence,
                java.util.Set<Defence> off) throws Exception {
            super(windowMs, profile, sequence, off);
            // The media work on frames (a frame's copies come one after the other): A sends one frame
            // per datagram. A bundle a man in the middle splits is as many frames (BundleTest).
            a = AgentRuntime.builder().platformName(PLATFORM).stack(stack())
                    .network(new io.concord.core.net.SocketNetwork(1 << 20, true, false)).build().start();
            b = AgentRuntime.builder().platformName(PLATFORM).stack(stack()).build().start();
            bDirect = b.startAgent("b", receiver);
            relay = new UdpRelay(Address.parse(bDirect.addresses().get(0)), medium);
            bViaRelay = new AID(bDirect.name(), relay.portFacingA().toUri());
            a.startAgent("a", sender);
        }

        @Override
        AID receiverAsSeenByA() {
            return bViaRelay;
        }

        @Override
        AID receiverDirect() {
            return bDirect;
        }

        @Override
        void send(Agent from, AID to, String... contents) {
            from.runtime().execute(() -> {
                for (String c : contents) {
                    from.send(new AclMessage(Performative.INFORM).addReceiver(to).setContent(c));
                }
            });
        }

        @Override
        AID startOnM(String name, Agent agent, Supplier<List<Layer>> stack) {
            return startOnHost("m", name, agent, stack);
        }

        @Override
        AID startOnHost(String host, String name, Agent agent, Supplier<List<Layer>> stack) {
            AgentRuntime m = AgentRuntime.builder().platformName(PLATFORM).stack(stack).build().start();
            attackers.add(m);
            return m.startAgent(name, agent);
        }

        @Override
        void awaitDrops(java.util.function.BooleanSupplier condition) {
            // B's counters change on B's loop; ask again each time B receives or a drop may have happened.
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (!condition.getAsBoolean() && System.nanoTime() < deadline) {
                java.util.concurrent.locks.LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(2));
            }
        }

        @Override
        boolean awaitReceived(int n) {
            try {
                return receiver.awaitCount(n, 60_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }

        @Override
        void settle(long ms) {
            // Wait for the relay to have sent on every frame it held back; then a marker sent after
            // them through the same path shows that B has processed them all.
            try {
                relay.awaitDelayedSent(60_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
            String marker = "marker" + markers++;
            int before = receiver.got.size();
            send(sender, bViaRelay, marker);
            awaitReceived(before + 1);
            receiver.got.removeIf(m -> m.getContent().equals(marker));
        }

        @Override
        Map<String, Long> receiverDrops() {
            return b.drops();
        }

        @Override
        public void close() {
            relay.close();
            a.close();
            b.close();
            attackers.forEach(AgentRuntime::close);
        }
    }
}
