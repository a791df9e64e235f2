package io.concord.bench.jmh;

import io.concord.bench.child.HttpTarget;
import io.concord.bench.jade.JadeHttpRequester;
import io.concord.bench.jade.JadePlatform;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;

/**
 * The JADE bridge: a JADE agent REQUESTs an agent of another platform over FIPA's HTTP MTP and waits
 * for its INFORM (500 bytes each way). The other platform is Concord (class 7, its container serving
 * the HTTP MTP), JADE itself, or the floor (the least an HTTP MTP can do: {@link HttpTarget}'s
 * precomputed answer), in the same run; each runs in a JVM of its own. Time per request and reply.
 */
@State(Scope.Benchmark)
public class HttpBenchmark {
    public static final int ROUNDS = 20;
    static final String CONTENT = "h".repeat(500);

    @Param({"concord", "jade", "floor"})
    public String target;

    private final RoundDriver driver = new RoundDriver();

    @Setup(Level.Trial)
    public void start() throws Exception {
        int targetHttp = JadePlatform.freePort();
        // The other platform runs in a JVM of its own, JADE or Concord alike: a JVM holds one JADE platform.
        driver.children.start(HttpTarget.class, target, Integer.toString(targetHttp));
        String targetName = driver.children.awaitReady().get(0);
        driver.jade = new JadePlatform("httpsource", JadePlatform.freePort());
        driver.rounds.expectReady(1);
        driver.jadeStarter = driver.jade.start("requester", JadeHttpRequester.class, driver.rounds, targetName,
                "http://127.0.0.1:" + targetHttp + "/acc", CONTENT);
        driver.rounds.awaitReady();
        driver.runBatch(2); // the first requests wait for the container's gateway and the HTTP paths
    }

    @Benchmark
    @OperationsPerInvocation(ROUNDS)
    public void requestReply() throws Exception {
        driver.runBatch(ROUNDS);
    }

    @TearDown(Level.Trial)
    public void stop() {
        driver.close();
    }
}
