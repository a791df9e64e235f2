package io.concord.bench.harness;

import io.concord.core.acl.AID;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.Platform;

import java.util.Arrays;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/** What the in-JVM harnesses that measure beside a platform share: waiting for its lists, and medians. */
final class Listed {
    private Listed() {
    }

    /** Waits until {@code who}'s copy of the platform's lists holds that many agents, at most {@code seconds}. */
    static void await(Platform p, AID who, int agents, int seconds) throws Exception {
        long until = System.nanoTime() + seconds * 1_000_000_000L;
        while (System.nanoTime() < until) {
            CompletableFuture<Integer> k = new CompletableFuture<>();
            p.runtime().execute(() -> {
                ContainerLayer c = Platform.containerLayer(p.runtime(), who);
                k.complete(c == null || c.containerName() == null ? -1 : c.agents().size());
            });
            if (k.get(10, TimeUnit.SECONDS) == agents) {
                return;
            }
            Thread.sleep(20);
        }
        throw new IllegalStateException("the platform's lists never held " + agents + " agents");
    }

    static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
    }
}
