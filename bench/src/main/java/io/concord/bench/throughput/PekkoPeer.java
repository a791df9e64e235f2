package io.concord.bench.throughput;

import com.typesafe.config.ConfigFactory;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.ActorSystem;
import org.apache.pekko.actor.typed.Behavior;
import org.apache.pekko.actor.typed.javadsl.Behaviors;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Apache Pekko's typed actors as the throughput benchmark's second peer, in one JVM: S sender
 * actors and R receiver actors on Pekko's default dispatcher (a fork-join pool as wide as the
 * cores). A message is a record handed over by reference (Pekko copies nothing inside a JVM).
 * Pekko's mailboxes are unbounded, so the senders keep the same window as JADE's (at most
 * {@link #WINDOW} unacknowledged, acknowledged every {@link #ACK_EVERY}); a sender sends 32 a
 * turn and then tells itself to go on, so that it yields its thread as an agent's action does.
 * Each receiver counts on a counter of its own (one writer each); {@link #received()} sums them.
 */
public final class PekkoPeer implements AutoCloseable {
    static final int WINDOW = 2_048;
    static final int ACK_EVERY = 256;

    /** What a receiver takes. */
    record Inform(String content, ActorRef<ToSender> from) {
    }

    /** What a sender takes. */
    sealed interface ToSender permits Ack, Go {
    }

    record Ack(long upTo) implements ToSender {
    }

    enum Go implements ToSender { GO }

    private final ActorSystem<Void> system;
    private final List<AtomicLong> counts = new ArrayList<>();

    public PekkoPeer(int senders, int receivers, int bytes) {
        String content = Counters.content(bytes);
        for (int i = 0; i < receivers; i++) {
            counts.add(new AtomicLong());
        }
        system = ActorSystem.create(Behaviors.<Void>setup(ctx -> {
            List<ActorRef<Inform>> to = new ArrayList<>();
            for (int i = 0; i < receivers; i++) {
                to.add(ctx.spawn(receiver(counts.get(i)), "r" + i));
            }
            for (int i = 0; i < senders; i++) {
                ctx.spawn(sender(to.get(i % receivers), content), "s" + i).tell(Go.GO);
            }
            return Behaviors.empty();
        }), "bench", ConfigFactory.parseString("pekko.loglevel = WARNING\npekko.stdout-loglevel = WARNING\n"
                + "pekko.log-dead-letters = off\npekko.log-dead-letters-during-shutdown = off")
                .withFallback(ConfigFactory.load()));
    }

    private static Behavior<Inform> receiver(AtomicLong count) {
        Map<ActorRef<ToSender>, Long> perSender = new HashMap<>();
        return Behaviors.receive(Inform.class).onMessage(Inform.class, m -> {
            count.lazySet(count.get() + 1);
            long c = perSender.merge(m.from(), 1L, Long::sum);
            if (c % ACK_EVERY == 0) {
                m.from().tell(new Ack(c));
            }
            return Behaviors.same();
        }).build();
    }

    private static Behavior<ToSender> sender(ActorRef<Inform> to, String content) {
        return Behaviors.setup(ctx -> {
            long[] sentAcked = {0, 0};
            boolean[] waiting = {false};
            return Behaviors.receive(ToSender.class)
                    .onMessage(Ack.class, a -> {
                        sentAcked[1] = Math.max(sentAcked[1], a.upTo());
                        if (waiting[0] && sentAcked[0] - sentAcked[1] < WINDOW) {
                            waiting[0] = false;
                            ctx.getSelf().tell(Go.GO);
                        }
                        return Behaviors.same();
                    })
                    .onMessage(Go.class, g -> {
                        if (Counters.stopped()) {
                            return Behaviors.stopped();
                        }
                        if (sentAcked[0] - sentAcked[1] >= WINDOW) {
                            waiting[0] = true;
                            return Behaviors.same();
                        }
                        for (int i = 0; i < 32; i++) {
                            to.tell(new Inform(content, ctx.getSelf()));
                        }
                        sentAcked[0] += 32;
                        Counters.SENT.addAndGet(32);
                        ctx.getSelf().tell(Go.GO);
                        return Behaviors.same();
                    })
                    .build();
        });
    }

    /** Messages received so far, by every receiver. */
    public long received() {
        long n = 0;
        for (AtomicLong c : counts) {
            n += c.get();
        }
        return n;
    }

    @Override
    public void close() throws Exception {
        system.terminate();
        system.getWhenTerminated().toCompletableFuture().get(10, TimeUnit.SECONDS);
    }
}
