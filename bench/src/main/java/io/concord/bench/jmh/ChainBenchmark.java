package io.concord.bench.jmh;

import io.concord.bench.concord.ConcordChainLink;
import io.concord.bench.jade.JadeChainLink;
import io.concord.bench.jade.JadePlatform;
import io.concord.bench.support.Chain;
import io.concord.bench.support.Platforms;
import io.concord.core.acl.AID;
import io.concord.core.agent.AgentRuntime;
import jade.wrapper.AgentController;
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
 * Experiment 4 of the dissertation, "pass the secret": N agents in one JVM pass a 500-byte content
 * round a ring; the first checks it came back unchanged and starts the next round. Time per round.
 */
@State(Scope.Benchmark)
public class ChainBenchmark extends RoundBenchmark {
    public static final int ROUNDS = 50;

    @Param({Platforms.CONCORD_CLASS7, Platforms.JADE})
    public String platform;

    @Param({"2", "6", "10", "19"})
    public int n;

    private ConcordChainLink first;

    @Setup(Level.Trial)
    public void start() throws Exception {
        if (platform.equals(Platforms.JADE)) {
            driver.jade = new JadePlatform();
            rounds.expectReady(n);
            for (int i = n - 1; i >= 0; i--) {
                AgentController a = driver.jade.start("link" + i, JadeChainLink.class, rounds, i, n, Chain.SECRET);
                if (i == 0) {
                    driver.jadeStarter = a;
                }
            }
            rounds.awaitReady();
            return;
        }
        driver.concord = Platforms.concord(platform);
        AgentRuntime concord = driver.concord;
        List<ConcordChainLink> links = new ArrayList<>();
        List<AID> ids = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            ConcordChainLink l = new ConcordChainLink(rounds, i == 0, Chain.SECRET);
            links.add(l);
            ids.add(concord.startAgent("link" + i, l));
        }
        for (int i = 0; i < n; i++) {
            links.get(i).next = ids.get((i + 1) % n);
        }
        first = links.get(0);
        driver.concordStart = first::startRound;
    }

    @Benchmark
    @OperationsPerInvocation(ROUNDS)
    public void round() throws Exception {
        driver.runBatch(ROUNDS);
    }
}
