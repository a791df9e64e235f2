package io.concord.bench.harness;

import io.concord.bench.concord.ConcordChainLink;
import io.concord.bench.support.Platforms;
import io.concord.bench.support.Rounds;
import io.concord.console.Console;
import io.concord.core.acl.AID;
import io.concord.core.agent.PortRange;
import io.concord.layers.Platform;

import java.io.InputStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/**
 * What the console costs the agents: the chain (N links pass a 500-byte secret round a ring) on a
 * class-7 {@link Platform}, its rounds timed with no console, then with the console serving a
 * browser that shows the platform and the safety views (the console asks every agent for its
 * status every 2 s), then with the sniffer on one link too. The phases alternate, so that the
 * machine's drift falls on both.
 */
public final class ConsoleCost {
    /** Median round times in µs: without, with the console open, with the sniffer on one link. */
    public record Outcome(int links, double withoutUs, double openUs, double sniffUs, int phases) {
        public double openCost() {
            return openUs / withoutUs - 1;
        }

        public double sniffCost() {
            return sniffUs / withoutUs - 1;
        }
    }

    private ConsoleCost() {
    }

    public static Outcome run(boolean full) throws Exception {
        int n = 6;
        int phases = full ? 8 : 4;
        long phaseMs = full ? 3_000 : 1_500;
        Rounds rounds = new Rounds();
        try (Platform p = Platform.builder().name("bench-console").ports(new PortRange(7801, 40, 10)).platformKey(Platforms.KEY).build()) {
            List<ConcordChainLink> links = new ArrayList<>();
            List<AID> ids = new ArrayList<>();
            for (int i = 0; i < n; i++) {
                ConcordChainLink l = new ConcordChainLink(rounds, i == 0, "s".repeat(492) + "checksum");
                links.add(l);
                ids.add(p.startAgent("link" + i, l));
            }
            for (int i = 0; i < n; i++) {
                links.get(i).next = ids.get((i + 1) % n);
            }
            Listed.await(p, ids.get(0), n, 30);
            roundsFor(p, links.get(0), rounds, phaseMs);   // warm-up
            double[] without = new double[phases];
            double[] open = new double[phases];
            double[] sniff = new double[phases];
            HttpClient http = HttpClient.newHttpClient();
            for (int k = 0; k < phases; k++) {
                without[k] = roundsFor(p, links.get(0), rounds, phaseMs);
                try (Console c = Console.start(p, Console.Config.port(0).withAgentName("console" + k))) {
                    Listed.await(p, ids.get(0), n + 1, 30);
                    CompletableFuture<HttpResponse<InputStream>> browser = http.sendAsync(HttpRequest.newBuilder(
                            URI.create("http://127.0.0.1:" + c.port() + "/api/events?topics=platform,safety")).build(),
                            HttpResponse.BodyHandlers.ofInputStream());
                    Thread reader = drain(browser);
                    open[k] = roundsFor(p, links.get(0), rounds, phaseMs);
                    CompletableFuture<HttpResponse<InputStream>> sniffer = http.sendAsync(HttpRequest.newBuilder(
                            URI.create("http://127.0.0.1:" + c.port() + "/api/events?topics=sniff&sniff=link3@bench-console")).build(),
                            HttpResponse.BodyHandlers.ofInputStream());
                    Thread reader2 = drain(sniffer);
                    sniff[k] = roundsFor(p, links.get(0), rounds, phaseMs);
                    reader.interrupt();
                    reader2.interrupt();
                }
                Listed.await(p, ids.get(0), n, 30);
            }
            return new Outcome(n, Listed.median(without), Listed.median(open), Listed.median(sniff), phases);
        }
    }

    private static Thread drain(CompletableFuture<HttpResponse<InputStream>> f) {
        Thread t = new Thread(() -> {
            try (InputStream in = f.get(10, TimeUnit.SECONDS).body()) {
                byte[] b = new byte[8192];
                while (!Thread.currentThread().isInterrupted() && in.read(b) >= 0) {
                    // a browser reads what comes
                }
            } catch (Exception e) {
                // closed with its phase
            }
        }, "bench-browser");
        t.setDaemon(true);
        t.start();
        return t;
    }


    /** Runs rounds for about that long; the median µs per round over batches of 50. */
    private static double roundsFor(Platform p, ConcordChainLink first, Rounds rounds, long ms) throws Exception {
        List<Double> perRound = new ArrayList<>();
        long end = System.nanoTime() + ms * 1_000_000;
        while (System.nanoTime() < end) {
            rounds.arm(50);
            long t0 = System.nanoTime();
            p.runtime().execute(first::startRound);
            rounds.await();
            perRound.add((System.nanoTime() - t0) / 1e3 / 50);
        }
        return Listed.median(perRound.stream().mapToDouble(Double::doubleValue).toArray());
    }

}
