package io.concord.sim.board;

import io.concord.core.agent.AgentRuntime;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

/** Asks a runtime's loop, from a test's thread, for what only the loop may read. */
final class Loops {
    private Loops() {
    }

    /** Runs {@code s} on the runtime's loop and returns its result (fails after 10 s). */
    static <T> T call(AgentRuntime rt, Supplier<T> s) {
        CompletableFuture<T> f = new CompletableFuture<>();
        rt.execute(() -> {
            try {
                f.complete(s.get());
            } catch (RuntimeException e) {
                f.completeExceptionally(e);
            }
        });
        try {
            return f.get(10, TimeUnit.SECONDS);
        } catch (Exception e) {
            throw new AssertionError("the loop did not answer: " + e, e);
        }
    }
}
