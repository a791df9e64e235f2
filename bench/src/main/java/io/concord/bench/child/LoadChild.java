package io.concord.bench.child;

import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.core.layer.Tracer;
import io.concord.layers.Platform;
import io.concord.layers.defence.Defence;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.platform.ServiceDescription;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * {@code <platform> <first port> <last port> <process> <agents> [<expect> [<without> [<host> [<services>]]]]}: one process of a platform shared
 * by several on this host, for {@code bench/run load}. Its agents register a service each through
 * the Java API. Prints {@code READY} once it holds a list of {@code <expect>} agents (default its own) and finds {@code <services>}
 * services (default {@code <expect>}; more where other hosts' agents count, through the GAL). It binds {@code <host>}
 * (default 127.0.0.1) and builds its stacks without the defences named in {@code <without>} (comma-separated, or empty).
 * Commands: {@code stats} prints {@code STATS removed=.. elections=.. lag_ms=.. agents=.. services=..}
 * (since the last stats: agents removed from a list, containers taken or failovers started, the
 * loop's worst lag; now: agents in its list and services of the type found in its copy);
 * {@code watch N} prints {@code AT <nanoTime>} once its list holds N agents.
 */
public final class LoadChild {
    private LoadChild() {
    }

    public static final class Seller extends Agent {
        @Override
        protected void setup() {
            Platform.of(this).register(ServiceDescription.of("load-service", getLocalName()));
        }
    }

    public static void main(String[] args) throws Exception {
        String name = args[0];
        int first = Integer.parseInt(args[1]);
        int last = Integer.parseInt(args[2]);
        String process = args[3];
        int n = Integer.parseInt(args[4]);
        int expect = args.length > 5 ? Integer.parseInt(args[5]) : n;
        String host = args.length > 7 ? args[7] : "127.0.0.1";
        int expectServices = args.length > 8 ? Integer.parseInt(args[8]) : expect;
        AtomicLong removed = new AtomicLong();
        AtomicLong elections = new AtomicLong();
        Tracer tracer = (ns, node, event, detail) -> {
            if (event.equals("platform-removed") || event.equals("platform-host-gone")) {
                removed.incrementAndGet();
            } else if (event.equals("platform-container") || event.equals("platform-failover")) {
                elections.incrementAndGet();
            }
        };
        AgentRuntime rt = AgentRuntime.builder().platformName(name).host(host).tracer(tracer).build();
        // A 7th argument names defences to build the stacks without (a comparison run: PORT_CHECK).
        Defence[] off = args.length > 6 && !args[6].isEmpty()
                ? Arrays.stream(args[6].split(",")).map(Defence::valueOf).toArray(Defence[]::new)
                : new Defence[0];
        Platform p = Platform.builder().name(name).runtime(rt).ports(PortRange.of(first, last)).withoutDefences(off).build();
        rt.start();
        AID[] aids = new AID[n];
        for (int i = 0; i < n; i++) {
            aids[i] = p.startAgent("p" + process + "s" + i, new Seller());
        }
        // The loop's lag: how late a task handed to it every 20 ms runs.
        AtomicLong worstLagNs = new AtomicLong();
        Thread prober = new Thread(() -> {
            while (!Thread.currentThread().isInterrupted()) {
                long t0 = System.nanoTime();
                rt.execute(() -> worstLagNs.accumulateAndGet(System.nanoTime() - t0, Math::max));
                try {
                    Thread.sleep(20);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "lag-probe");
        prober.setDaemon(true);
        prober.start();
        while (count(rt, aids[0], false) < expect || count(rt, aids[0], true) < expectServices) {
            Thread.sleep(20);
        }
        System.out.println("READY");
        System.out.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        String line;
        while ((line = in.readLine()) != null) {
            if (line.equals("stats")) {
                System.out.println("STATS removed=" + removed.getAndSet(0) + " elections=" + elections.getAndSet(0)
                        + " lag_ms=" + worstLagNs.getAndSet(0) / 1_000_000 + " agents=" + count(rt, aids[0], false)
                        + " services=" + count(rt, aids[0], true));
            } else if (line.startsWith("watch ")) {
                int want = Integer.parseInt(line.substring(6).trim());
                while (count(rt, aids[0], false) != want) {
                    Thread.sleep(1);
                }
                System.out.println("AT " + System.nanoTime());
            }
            System.out.flush();
        }
        prober.interrupt();
        p.close();
        rt.close();
        System.exit(0);
    }

    /** Agents in the list of the agent, or services of the load type in its copy. Asked on the loop. */
    private static int count(AgentRuntime rt, AID at, boolean services) throws Exception {
        CompletableFuture<Integer> f = new CompletableFuture<>();
        rt.execute(() -> {
            ContainerLayer l = Platform.containerLayer(rt, at);
            if (l == null || l.containerName() == null) {
                f.complete(0);
            } else if (services) {
                List<AgentEntry> found = l.search(ServiceDescription.ofType("load-service"));
                f.complete(found.size());
            } else {
                f.complete(l.agents().size());
            }
        });
        return f.get(120, TimeUnit.SECONDS);
    }
}
