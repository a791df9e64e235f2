package io.concord.bench.jmh;

import io.concord.bench.support.Platforms;

import io.concord.bench.jade.JadeBooks;
import io.concord.bench.jade.JadePlatform;
import io.concord.core.acl.AID;
import io.concord.core.agent.AgentRuntime;
import io.concord.examples.BookBuyer;
import io.concord.examples.BookSeller;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

import java.util.ArrayList;
import java.util.List;

/**
 * Experiment 5 of the dissertation: one buyer, S sellers in one JVM. QUERY-REF to all sellers,
 * INFORM quotes (a buyer timeout for missing ones), REQUEST to the cheapest, AGREE. Time per round.
 * On Concord, the annex agents themselves ({@code io.concord.examples}); on JADE, {@link JadeBooks}.
 */
@State(Scope.Benchmark)
public class BooksBenchmark extends RoundBenchmark {
    public static final int ROUNDS = 50;
    /** How long the buyer waits for quotes: the annex buyer's second. */
    static final long TIMEOUT_MS = 1_000;

    @Param({Platforms.CONCORD_CLASS7, Platforms.JADE})
    public String platform;

    @Param({"1", "5", "10", "15"})
    public int s;


    static int price(int i) {
        return 40 + (i * 7919) % 23;
    }

    @Setup(Level.Trial)
    public void start() throws Exception {
        if (platform.equals(Platforms.JADE)) {
            driver.jade = new JadePlatform();
            rounds.expectReady(s + 1);
            for (int i = 0; i < s; i++) {
                driver.jade.start("seller" + i, JadeBooks.Seller.class, price(i), rounds);
            }
            driver.jadeStarter = driver.jade.start("buyer", JadeBooks.Buyer.class, rounds, s, TIMEOUT_MS);
            rounds.awaitReady();
            return;
        }
        driver.concord = Platforms.concord(platform);
        AgentRuntime concord = driver.concord;
        List<AID> sellers = new ArrayList<>();
        for (int i = 0; i < s; i++) {
            sellers.add(concord.startAgent("seller" + i, new BookSeller(price(i))));
        }
        BookBuyer buyer = new BookBuyer(sellers, rounds::roundDone);
        concord.startAgent("buyer", buyer);
        driver.concordStart = buyer::buy;
    }

    @Benchmark
    @OperationsPerInvocation(ROUNDS)
    public void round() throws Exception {
        driver.runBatch(ROUNDS);
    }
}
