package io.concord.bench.jmh;

import io.concord.bench.child.Children;
import io.concord.bench.child.ProcessAgent;

import io.concord.bench.jade.JadeBooks;
import io.concord.bench.jade.JadePlatform;
import io.concord.bench.jade.JadeProcessAgent;
import io.concord.bench.support.Platforms;
import io.concord.core.acl.AID;
import io.concord.core.agent.AgentRuntime;
import io.concord.examples.BookBuyer;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

import java.util.ArrayList;
import java.util.List;

/** The book buyer with one process per agent: the buyer here, every seller in a JVM of its own. */
@State(Scope.Benchmark)
public class ProcessBooksBenchmark extends RoundBenchmark {
    public static final int ROUNDS = 20;

    @Param({Platforms.CONCORD_CLASS7, Platforms.CONCORD_CLOSED, Platforms.JADE})
    public String platform;

    @Param({"1", "5"})
    public int s;

    private final Children children = driver.children;

    @Setup(Level.Trial)
    public void start() throws Exception {
        if (platform.equals(Platforms.JADE)) {
            driver.jade = new JadePlatform();
            for (int i = 0; i < s; i++) {
                children.start(JadeProcessAgent.class, Integer.toString(driver.jade.port()), "seller", "seller" + i,
                        Integer.toString(BooksBenchmark.price(i)));
            }
            children.awaitReady();
            rounds.expectReady(1);
            driver.jadeStarter = driver.jade.start("buyer", JadeBooks.Buyer.class, rounds, s, BooksBenchmark.TIMEOUT_MS);
            rounds.awaitReady();
            return;
        }
        for (int i = 0; i < s; i++) {
            children.start(ProcessAgent.class, "seller", "seller" + i, Integer.toString(BooksBenchmark.price(i)), platform);
        }
        List<String> addresses = children.awaitReady();
        List<AID> sellers = new ArrayList<>();
        for (int i = 0; i < s; i++) {
            sellers.add(new AID("seller" + i + "@bench", addresses.get(i)));
        }
        driver.concord = Platforms.concord(platform);
        AgentRuntime concord = driver.concord;
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
