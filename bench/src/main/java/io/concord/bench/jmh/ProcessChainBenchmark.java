package io.concord.bench.jmh;

import io.concord.bench.child.Children;
import io.concord.bench.child.ProcessAgent;
import io.concord.bench.concord.ConcordChainLink;
import io.concord.bench.jade.JadeChainLink;
import io.concord.bench.jade.JadePlatform;
import io.concord.bench.jade.JadeProcessAgent;
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

import java.util.List;

/**
 * The chain with one process per agent: link 0 in the benchmark's JVM, every other link in a JVM
 * of its own. Concord over UDP with the class-7 stack; JADE with a main container here and a
 * peripheral container per agent.
 */
@State(Scope.Benchmark)
public class ProcessChainBenchmark extends RoundBenchmark {
    public static final int ROUNDS = 20;

    @Param({Platforms.CONCORD_CLASS7, Platforms.CONCORD_CLOSED, Platforms.JADE})
    public String platform;

    @Param({"2", "6"})
    public int n;

    private final Children children = driver.children;
    private ConcordChainLink first;

    @Setup(Level.Trial)
    public void start() throws Exception {
        if (platform.equals(Platforms.JADE)) {
            driver.jade = new JadePlatform();
            for (int i = 1; i < n; i++) {
                children.start(JadeProcessAgent.class, Integer.toString(driver.jade.port()), "link", "link" + i,
                        Integer.toString(i), Integer.toString(n));
            }
            children.awaitReady();
            rounds.expectReady(1);
            driver.jadeStarter = driver.jade.start("link0", JadeChainLink.class, rounds, 0, n, Chain.SECRET);
            rounds.awaitReady();
            return;
        }
        for (int i = 1; i < n; i++) {
            children.start(ProcessAgent.class, "link", "link" + i, platform);
        }
        List<String> addresses = children.awaitReady();
        driver.concord = Platforms.concord(platform);
        AgentRuntime concord = driver.concord;
        first = new ConcordChainLink(rounds, true, Chain.SECRET);
        AID firstAid = concord.startAgent("link0", first);
        for (int i = 1; i < n; i++) {
            AID next = i + 1 < n ? new AID("link" + (i + 1) + "@bench", addresses.get(i)) : firstAid;
            children.tell(i - 1, "NEXT " + next.localName() + " " + next.addresses().get(0));
        }
        first.next = new AID("link1@bench", addresses.get(0));
        driver.concordStart = first::startRound;
    }

    @Benchmark
    @OperationsPerInvocation(ROUNDS)
    public void round() throws Exception {
        driver.runBatch(ROUNDS);
    }
}
