package io.concord.bench.harness;

import io.concord.bench.support.Platforms;
import io.concord.bench.support.Rounds;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.Agent;
import io.concord.core.agent.CyclicBehaviour;
import io.concord.core.agent.PortRange;
import io.concord.core.agent.ThreadedBehaviourFactory;
import io.concord.testkit.EchoAgent;
import io.concord.layers.Platform;

import java.util.ArrayList;
import java.util.List;

/**
 * A blocking agent beside 100 non-blocking ones (issue 32): a prober pings each of 100 echo agents
 * in turn on a class-7 {@link Platform}, and the median time of a ping is taken with no other agent,
 * then with one more agent that blocks: its behaviour (on a thread of its own, as a blocking
 * behaviour must ask for) spends its time in {@code Thread.sleep} and {@code blockingReceive}. The
 * phases alternate, so that the machine's drift falls on both; the result is the ratio of the two
 * medians (1.0: unchanged). Timing, so here and never in a test.
 */
public final class BlockingBeside {
    /** Median µs per ping without and with the blocking agent. */
    public record Outcome(int echoes, double withoutUs, double blockingUs, int phases) {
        public double ratio() {
            return blockingUs / withoutUs;
        }
    }

    private BlockingBeside() {
    }

    /** Pings the echoes one after the other, a batch at a time (see {@link Rounds}). */
    static final class Prober extends Agent {
        private final Rounds rounds;
        volatile List<AID> echoes = List.of();
        private int next;

        Prober(Rounds rounds) {
            this.rounds = rounds;
        }

        /** Starts a batch; call on the runtime's loop. */
        void start() {
            ping();
        }

        private void ping() {
            AID to = echoes.get(next);
            next = (next + 1) % echoes.size();
            send(new AclMessage(Performative.REQUEST).addReceiver(to).setContent("ping"));
        }

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    AclMessage m = receive();
                    if (m == null) {
                        block();
                        return;
                    }
                    if (rounds.roundDone()) {
                        ping();
                    }
                }
            });
        }
    }

    /** Blocks, as JADE code does: sleeps, then waits in blockingReceive, again and again, on a thread of its own. */
    static final class Blocker extends Agent {
        @Override
        protected void setup() {
            addBehaviour(new ThreadedBehaviourFactory().wrap(new CyclicBehaviour(this) {
                @Override
                public void action() {
                    try {
                        Thread.sleep(50);
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        return;
                    }
                    myAgent.blockingReceive(null, 50);
                }
            }));
        }
    }

    public static Outcome run(boolean full) throws Exception {
        int echoes = 100;
        int phases = full ? 8 : 4;
        long phaseMs = full ? 3_000 : 1_500;
        Rounds rounds = new Rounds();
        try (Platform p = Platform.builder().name("bench-blocking").ports(new PortRange(8101, echoes + 30, 10))
                .platformKey(Platforms.KEY).build()) {
            Prober prober = new Prober(rounds);
            AID proberId = p.startAgent("prober", prober);
            List<AID> ids = new ArrayList<>();
            for (int i = 0; i < echoes; i++) {
                ids.add(p.startAgent("echo" + i, new EchoAgent()));
            }
            prober.echoes = List.copyOf(ids);
            Listed.await(p, proberId, echoes + 1, 60);
            roundsFor(p, prober, rounds, phaseMs);   // warm-up
            double[] without = new double[phases];
            double[] blocking = new double[phases];
            for (int k = 0; k < phases; k++) {
                without[k] = roundsFor(p, prober, rounds, phaseMs);
                Blocker b = new Blocker();
                p.startAgent("blocker" + k, b);
                Listed.await(p, proberId, echoes + 2, 60);
                Thread.sleep(200); // the blocker's thread is in its sleep and its blockingReceive by now
                blocking[k] = roundsFor(p, prober, rounds, phaseMs);
                p.runtime().execute(b::doDelete);
                Listed.await(p, proberId, echoes + 1, 60);
            }
            return new Outcome(echoes, Listed.median(without), Listed.median(blocking), phases);
        }
    }


    /** Pings for about that long; the median µs per ping over batches of 100 (one sweep of the echoes). */
    private static double roundsFor(Platform p, Prober prober, Rounds rounds, long ms) throws Exception {
        List<Double> perPing = new ArrayList<>();
        long end = System.nanoTime() + ms * 1_000_000;
        while (System.nanoTime() < end) {
            rounds.arm(100);
            long t0 = System.nanoTime();
            p.runtime().execute(prober::start);
            rounds.await();
            perPing.add((System.nanoTime() - t0) / 1e3 / 100);
        }
        return Listed.median(perPing.stream().mapToDouble(Double::doubleValue).toArray());
    }

}
