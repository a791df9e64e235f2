package io.concord.bench.child;

import io.concord.core.acl.AID;
import io.concord.layers.Boot;
import io.concord.layers.Platform;
import io.concord.layers.platform.ContainerLayer;

import java.io.OutputStream;
import java.io.PrintStream;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/**
 * {@code <name> <first port> <agents>}: a Concord platform of idle agents in this JVM, started with
 * Boot's command line and its defaults (class 7). Prints {@code READY} once every agent follows one
 * container and holds the list of them all; exits when its input closes.
 */
public final class IdlePlatform {
    private IdlePlatform() {
    }

    public static void main(String[] args) throws Exception {
        String name = args[0];
        int first = Integer.parseInt(args[1]);
        int n = Integer.parseInt(args[2]);
        StringBuilder agents = new StringBuilder();
        for (int i = 0; i < n; i++) {
            agents.append("i").append(i).append(':').append(IdleAgent.class.getName()).append(';');
        }
        // One platform per child: its own name, port range and discovery port.
        Platform p = Boot.start(new String[]{"-name", name, "-ports", first + "-" + (first + n + 20),
                "-discovery-port", Integer.toString(first + n + 21), "-agents", agents.toString()},
                new PrintStream(OutputStream.nullOutputStream()));
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(Long.getLong("concord.idle.converge", 60));
        while (!converged(p, n)) {
            if (System.nanoTime() > deadline) {
                throw new IllegalStateException("the " + n + " agents did not agree on one container in " + Long.getLong("concord.idle.converge", 60) + " s");
            }
            Thread.sleep(50);
        }
        System.out.println("READY");
        System.out.flush();
        while (System.in.read() >= 0) {
            // until the parent closes our input
        }
        p.close();
        System.exit(0);
    }

    /** Every agent follows one container, and holds the list of all of them. Asked on the loop. */
    private static boolean converged(Platform p, int n) throws Exception {
        CompletableFuture<Boolean> f = new CompletableFuture<>();
        p.runtime().execute(() -> {
            String container = null;
            for (AID a : p.runtime().agents()) {
                ContainerLayer c = Platform.containerLayer(p.runtime(), a);
                if (c == null || c.containerName() == null || (container != null && !container.equals(c.containerName()))) {
                    f.complete(false);
                    return;
                }
                container = c.containerName();
                if (c.agents().size() != n) {
                    f.complete(false); // every agent holds the whole list, not only the container
                    return;
                }
            }
            f.complete(container != null);
        });
        return f.get(120, TimeUnit.SECONDS); // a loop busy with a thousand joins answers late
    }
}
