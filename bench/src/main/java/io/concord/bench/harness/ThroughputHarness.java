package io.concord.bench.harness;

import io.concord.bench.child.Children;
import io.concord.bench.child.ThroughputChild;
import io.concord.bench.jade.JadePlatform;
import io.concord.bench.support.Platforms;
import io.concord.bench.throughput.ConcordReceiver;
import io.concord.bench.throughput.ConcordSender;
import io.concord.bench.throughput.Counters;
import io.concord.bench.throughput.JadeReceiver;
import io.concord.bench.throughput.JadeSender;
import io.concord.bench.throughput.UdpFloor;
import io.concord.core.acl.AID;
import io.concord.core.agent.AgentRuntime;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;

/**
 * Sustained messages per second: S senders, R receivers (sender i sends to receiver i mod R), all
 * in this JVM or the receivers in a second one, for Concord (class 7, every defence on, its flow
 * control the only pacing), JADE 4.3 (a window of 2,048 unacknowledged messages kept by the
 * application, since JADE has none) and raw UDP (the floor: nothing acknowledged, what arrives
 * counts). Received messages are counted over a window after a warm-up; then the senders stop and
 * what was sent and never arrived is counted as lost.
 */
public final class ThroughputHarness {
    /** One measured point. */
    public record Result(String platform, String shape, boolean processes, int bytes, double msgsPerS, long sent,
                         long received, long pauses, Map<String, Long> drops) {
        public long lost() {
            return sent - received;
        }
    }

    private ThroughputHarness() {
    }

    public static int senders(String shape) {
        return shape.equals("1to1") ? 1 : 16;
    }

    public static int receivers(String shape) {
        return shape.equals("16pairs") ? 16 : 1;
    }

    public static Result run(String platform, String shape, boolean processes, int bytes, double warmS, double measureS)
            throws Exception {
        Counters.reset();
        int s = senders(shape);
        int r = receivers(shape);
        try (Children kids = new Children()) {
            LongSupplier received = processes ? () -> count(kids) : Counters.RECEIVED::get;
            switch (platform) {
                case "concord" -> {
                    try (AgentRuntime rt = Platforms.concord(Platforms.CONCORD_CLASS7)) {
                        List<AID> to = new ArrayList<>();
                        if (processes) {
                            kids.start(ThroughputChild.class, "concord", Integer.toString(r));
                            String[] addresses = kids.awaitReady().get(0).split(" ");
                            for (int i = 0; i < r; i++) {
                                to.add(new AID("r" + i + "@bench", addresses[i]));
                            }
                        } else {
                            for (int i = 0; i < r; i++) {
                                to.add(rt.startAgent("r" + i, new ConcordReceiver()));
                            }
                        }
                        for (int i = 0; i < s; i++) {
                            rt.startAgent("s" + i, new ConcordSender(to.get(i % r), bytes));
                        }
                        double rate = measure(received, warmS, measureS);
                        long got = drain(received);
                        CompletableFuture<Long> pauses = new CompletableFuture<>();
                        rt.execute(() -> pauses.complete(rt.pauses()));
                        return new Result(platform, shape, processes, bytes, rate, Counters.SENT.get(), got,
                                pauses.get(10, TimeUnit.SECONDS), rt.drops());
                    }
                }
                case "concord-loops", "concord-across" -> {
                    // One JVM on as many loops as cores, one loop group (as Platform.Builder.loops makes
                    // them). concord-loops: pair i (sender and receiver) on loop i % N, so a pair's
                    // messages are handed over on its own loop, the pairs in parallel. concord-across:
                    // every sender on the loop after its receiver's, so every message crosses loops.
                    int n = Math.max(2, Runtime.getRuntime().availableProcessors());
                    int shift = platform.equals("concord-across") ? 1 : 0;
                    io.concord.core.agent.LoopGroup group = new io.concord.core.agent.LoopGroup();
                    List<AgentRuntime> loops = new ArrayList<>();
                    try {
                        for (int i = 0; i < n; i++) {
                            loops.add(Platforms.concord(Platforms.CONCORD_CLASS7, group));
                        }
                        List<AID> to = new ArrayList<>();
                        for (int i = 0; i < r; i++) {
                            to.add(loops.get(i % n).startAgent("r" + i, new ConcordReceiver()));
                        }
                        for (int i = 0; i < s; i++) {
                            loops.get((i % r + shift) % n).startAgent("s" + i, new ConcordSender(to.get(i % r), bytes));
                        }
                        double rate = measure(received, warmS, measureS);
                        long got = drain(received);
                        long paused = 0;
                        Map<String, Long> drops = new java.util.TreeMap<>();
                        for (AgentRuntime rt : loops) {
                            CompletableFuture<Long> pauses = new CompletableFuture<>();
                            rt.execute(() -> pauses.complete(rt.pauses()));
                            paused += pauses.get(10, TimeUnit.SECONDS);
                            rt.drops().forEach((k, v) -> drops.merge(k, v, Long::sum));
                        }
                        return new Result(platform, shape, processes, bytes, rate, Counters.SENT.get(), got, paused, drops);
                    } finally {
                        for (AgentRuntime rt : loops) {
                            rt.close();
                        }
                    }
                }
                case "pekko" -> {
                    if (processes) {
                        throw new IllegalArgumentException("Pekko runs in one JVM only here (no remoting in the bench)");
                    }
                    try (io.concord.bench.throughput.PekkoPeer pekko = new io.concord.bench.throughput.PekkoPeer(s, r, bytes)) {
                        double rate = measure(pekko::received, warmS, measureS);
                        long got = drain(pekko::received);
                        return new Result(platform, shape, false, bytes, rate, Counters.SENT.get(), got, 0, Map.of());
                    }
                }
                case "jade" -> {
                    try (JadePlatform jade = new JadePlatform()) {
                        if (processes) {
                            kids.start(ThroughputChild.class, "jade", Integer.toString(r), Integer.toString(jade.port()));
                            kids.awaitReady();
                        } else {
                            for (int i = 0; i < r; i++) {
                                jade.start("r" + i, JadeReceiver.class);
                            }
                        }
                        for (int i = 0; i < s; i++) {
                            jade.start("s" + i, JadeSender.class, "r" + (i % r), bytes);
                        }
                        double rate = measure(received, warmS, measureS);
                        long got = drain(received);
                        return new Result(platform, shape, processes, bytes, rate, Counters.SENT.get(), got, 0, Map.of());
                    }
                }
                case "udp" -> {
                    UdpFloor.Receivers local = null;
                    List<Integer> ports = new ArrayList<>();
                    if (processes) {
                        kids.start(ThroughputChild.class, "udp", Integer.toString(r));
                        for (String p : kids.awaitReady().get(0).split(" ")) {
                            ports.add(Integer.parseInt(p));
                        }
                    } else {
                        local = new UdpFloor.Receivers(r);
                        ports.addAll(local.ports());
                    }
                    try {
                        Thread sender = UdpFloor.startSenders(s, ports, bytes);
                        double rate = measure(received, warmS, measureS);
                        Counters.stopSenders();
                        sender.join(5_000);
                        long got = drain(received);
                        return new Result(platform, shape, processes, bytes, rate, Counters.SENT.get(), got, 0, Map.of());
                    } finally {
                        if (local != null) {
                            local.close();
                        }
                    }
                }
                default -> throw new IllegalArgumentException(platform);
            }
        }
    }

    private static long count(Children kids) {
        try {
            return Long.parseLong(kids.ask(0, "COUNT", "COUNT").substring(6).trim());
        } catch (IOException e) {
            throw new IllegalStateException("the receivers' JVM did not answer: " + e.getMessage(), e);
        }
    }

    /** Received per second over {@code measureS}, after {@code warmS}. */
    private static double measure(LongSupplier received, double warmS, double measureS) throws InterruptedException {
        Thread.sleep((long) (warmS * 1000));
        long c0 = received.getAsLong();
        long t0 = System.nanoTime();
        Thread.sleep((long) (measureS * 1000));
        long c1 = received.getAsLong();
        long t1 = System.nanoTime();
        return (c1 - c0) * 1e9 / (t1 - t0);
    }

    /** Stops the senders and waits until what they sent has arrived, or nothing more arrives for 2 s. */
    private static long drain(LongSupplier received) throws InterruptedException {
        Counters.stopSenders();
        Thread.sleep(100); // let a sender in the middle of an action finish it
        long last = -1;
        long quietSince = System.nanoTime();
        while (true) {
            long got = received.getAsLong();
            if (got >= Counters.SENT.get()) {
                return got;
            }
            if (got != last) {
                last = got;
                quietSince = System.nanoTime();
            } else if (System.nanoTime() - quietSince > 2_000_000_000L) {
                return got;
            }
            Thread.sleep(20);
        }
    }
}
