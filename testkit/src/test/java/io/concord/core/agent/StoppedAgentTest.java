package io.concord.core.agent;

import io.concord.core.acl.AID;
import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerContext;
import io.concord.core.net.Address;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * A stopped agent does nothing more: a timer its layers set before it stopped never runs (it used
 * to run, send on the closed port, and log a {@code send-failed} warning at every demo's end).
 */
class StoppedAgentTest {

    /** A layer that, once started, means to send a frame 100 ms later. */
    static final class Later extends Layer {
        boolean ran;

        @Override
        public void start(LayerContext ctx) {
            ctx.host().schedule(ctx.nowNs() + 100_000_000L, () -> {
                ran = true;
                ctx.passDown(Envelope.control(1, new Address("h2", 9), new byte[8], 0, 8));
            });
        }
    }

    /** One agent whose stack is a {@link Later}, stopped after 10 ms or not; what its layer did by 510 ms. */
    private static void run(boolean stop, java.util.function.BiConsumer<Later, AgentRuntime> check) {
        try (Simulation sim = new Simulation(3, FaultPlan.NONE)) {
            Later[] layer = new Later[1];
            AgentRuntime rt = sim.newRuntime("h1", () -> {
                layer[0] = new Later();
                return List.of(layer[0]);
            });
            AID aid = rt.startAgent("agent", new Agent() { });
            sim.runFor(10);
            if (stop) {
                rt.execute(() -> rt.agent(aid).doDelete());
            }
            sim.runFor(500);
            check.accept(layer[0], rt);
        }
    }

    @Test
    void aTimerOfAStoppedAgentsLayersNeverRuns() {
        run(true, (layer, rt) -> {
            assertFalse(layer.ran, "the stopped agent's timer ran");
            assertEquals(0L, rt.drops().getOrDefault("send-failed", 0L));
        });
    }

    @Test
    void aTimerOfARunningAgentsLayersRuns() {
        run(false, (layer, rt) -> assertEquals(true, layer.ran));
    }
}
