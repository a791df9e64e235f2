package io.concord.bench.harness;

import io.concord.bench.support.Platforms;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.TickerBehaviour;
import io.concord.core.layer.SendRejectedException;
import io.concord.core.net.Transport;
import io.concord.layers.Profile;
import io.concord.layers.SafetyStack;
import io.concord.layers.security.IdentityStore;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Experiment 3 of the dissertation: a sender and a receiver in two runtimes (real sockets, the
 * class-7 stack), small messages every 2 ms for the whole run; in its second half, messages of
 * growing size too, up to and past the frame limit (those are refused to the sender, who goes on).
 * The receiver checks that the small ones arrive in order. Per window: the rate, and the heap in
 * use after a collection, to show there is no decay and memory stays flat.
 */
public final class StressHarness {
    /** What one run measured. */
    public record Outcome(Transport transport, List<Double> ratePerWindow, List<Double> heapMbPerWindow, long delivered,
                   long refused, long outOfOrder, long maxSizeDelivered, String drops) {
        double decayPct() {
            double first = ratePerWindow.get(0);
            double last = ratePerWindow.get(ratePerWindow.size() - 1);
            return first == 0 ? 0 : 100.0 * (first - last) / first;
        }
    }

    private static final class Receiver extends Agent {
        final AtomicLong small = new AtomicLong();
        final AtomicLong outOfOrder = new AtomicLong();
        final AtomicLong maxSize = new AtomicLong();
        private long expected;

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    AclMessage m;
                    while ((m = receive()) != null) {
                        String c = m.getContent();
                        if (c.startsWith("s")) {
                            long n = Long.parseLong(c.substring(1, c.indexOf(' ')));
                            if (n != expected) {
                                outOfOrder.incrementAndGet();
                            }
                            expected = n + 1;
                            small.incrementAndGet();
                        } else {
                            maxSize.accumulateAndGet(c.length(), Math::max);
                        }
                    }
                    block();
                }
            });
        }
    }

    private static final class Sender extends Agent {
        private final AID to;
        private final int limit;
        volatile boolean growing;
        final AtomicLong refused = new AtomicLong();
        private long n;
        private int size = 64;

        Sender(AID to, int limit) {
            this.to = to;
            this.limit = limit;
        }

        @Override
        protected void setup() {
            String pad = "p".repeat(400);
            addBehaviour(new TickerBehaviour(this, 2) {
                @Override
                protected void onTick() {
                    for (int i = 0; i < 4; i++) {
                        send(new AclMessage(Performative.INFORM).addReceiver(to).setContent("s" + (n++) + " " + pad));
                    }
                    if (growing) {
                        try {
                            send(new AclMessage(Performative.INFORM).addReceiver(to).setContent("g".repeat(size)));
                        } catch (SendRejectedException e) {
                            refused.incrementAndGet();
                        }
                        size = size >= 2 * limit ? 64 : size + 97;
                    }
                }
            });
        }
    }

    public static Outcome run(Transport transport, int seconds, int windows) throws InterruptedException {
        var stack = SafetyStack.builder().profile(Profile.CLASS_7).platformKey(Platforms.KEY)
                .identities(IdentityStore.ephemeral()).transport(transport).build();
        int limit = transport == Transport.UDP ? 8 * 1024 : 16 * 1024;
        try (AgentRuntime a = AgentRuntime.builder().platformName("bench").transport(transport).stack(stack).build().start();
             AgentRuntime b = AgentRuntime.builder().platformName("bench").transport(transport).stack(stack).build().start()) {
            Receiver receiver = new Receiver();
            AID to = b.startAgent("receiver", receiver);
            Sender sender = new Sender(to, limit);
            a.startAgent("sender", sender);
            List<Double> rates = new ArrayList<>();
            List<Double> heaps = new ArrayList<>();
            long windowMs = seconds * 1000L / windows;
            long before = receiver.small.get();
            for (int w = 0; w < windows; w++) {
                if (w == windows / 2) {
                    sender.growing = true;
                }
                long start = System.nanoTime();
                synchronized (StressHarness.class) {
                    StressHarness.class.wait(windowMs); // the run's duration is the point of this harness
                }
                long now = receiver.small.get();
                rates.add((now - before) * 1e9 / (System.nanoTime() - start));
                before = now;
                System.gc();
                Runtime rt = Runtime.getRuntime();
                heaps.add((rt.totalMemory() - rt.freeMemory()) / 1048576.0);
            }
            return new Outcome(transport, rates, heaps, receiver.small.get(), sender.refused.get(),
                    receiver.outOfOrder.get(), receiver.maxSize.get(), b.drops().toString());
        }
    }

    public static String describe(Outcome o) {
        return String.format(Locale.ROOT, "RESULT stress %s 500 rate_per_s=%.0f decay_pct=%.1f heap_mb_first=%.1f "
                        + "heap_mb_last=%.1f delivered=%d out_of_order=%d refused_over_limit=%d largest_delivered=%d",
                o.transport().name().toLowerCase(Locale.ROOT), o.ratePerWindow().get(0), o.decayPct(),
                o.heapMbPerWindow().get(0), o.heapMbPerWindow().get(o.heapMbPerWindow().size() - 1), o.delivered(),
                o.outOfOrder(), o.refused(), o.maxSizeDelivered());
    }
}
