package io.concord.layers.temporal;

import io.concord.core.layer.Envelope;
import io.concord.core.net.Address;
import io.concord.testkit.LayerHarness;
import io.concord.core.time.ManualClock;
import io.concord.layers.frame.Frames;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

class TemporalLayerTest {
    private static final Address A = new Address("h", 1);
    private static final Address SOURCE = new Address("h", 9);

    private static Envelope payload() {
        byte[] buf = new byte[Frames.HEADROOM + 3];
        return Envelope.control(2, A, buf, Frames.HEADROOM, 3);
    }

    private static Envelope arriving(Envelope sent, Address from, long fromId) {
        byte[] wire = sent.dataCopy();
        Envelope e = Envelope.incoming(from, wire, 0, wire.length, 0);
        e.setPeerId(fromId);
        return e;
    }

    @Test
    void passesFramesInsideTheWindowAndDropsStaleAndFutureOnes() {
        ManualClock clock = new ManualClock();
        LayerHarness sender = new LayerHarness("a@p", clock, new TemporalLayer(TemporalLayer.Config.window(500), new PlatformClock()));
        LayerHarness receiver = new LayerHarness("b@p", clock, new TemporalLayer(TemporalLayer.Config.window(500), new PlatformClock()));
        sender.sendDown(payload());
        Envelope fresh = sender.pollDown();
        receiver.receiveUp(arriving(fresh, A, 1));
        assertNotNull(receiver.pollUp());
        Envelope late = arriving(fresh, A, 1);
        clock.advanceMs(501);
        receiver.receiveUp(late);
        assertNull(receiver.pollUp());
        assertEquals(1, receiver.drops().get("stale"));
        ManualClock ahead = new ManualClock(ManualClock.DEFAULT_EPOCH_MS + 10_000);
        LayerHarness fast = new LayerHarness("c@p", ahead, new TemporalLayer(TemporalLayer.Config.window(500), new PlatformClock()));
        fast.sendDown(payload());
        receiver.receiveUp(arriving(fast.pollDown(), A, 3));
        assertEquals(1, receiver.drops().get("from-future"));
    }

    @Test
    void anAgentLearnsThePlatformTimeFromItsTimeSource() {
        // The time source's clock is 5 s ahead of the agent's host clock.
        ManualClock sourceClock = new ManualClock(ManualClock.DEFAULT_EPOCH_MS + 5_000);
        ManualClock agentClock = new ManualClock();
        long sourceId = Frames.id("container@p");
        LayerHarness source = new LayerHarness("container@p", sourceClock,
                new TemporalLayer(TemporalLayer.Config.window(60_000), new PlatformClock()));
        PlatformClock agentTime = new PlatformClock();
        LayerHarness agent = new LayerHarness("a@p", agentClock,
                new TemporalLayer(new TemporalLayer.Config(60_000, sourceId, SOURCE, 1_000), agentTime));
        for (int round = 0; round < 3; round++) {
            Envelope request = agent.pollDown();
            assertNotNull(request, "the agent asks for the time");
            source.receiveUp(arriving(request, A, Frames.id("a@p")));
            Envelope response = source.pollDown();
            agent.receiveUp(arriving(response, SOURCE, sourceId));
            agentClock.advanceMs(200);
            sourceClock.advanceMs(200);
            agent.advanceMs(0);
        }
        assertTrue(agentTime.isSynced());
        assertEquals(5_000_000, agentTime.offsetUs(), 2_000, "offset within the exchange's error");
        assertEquals(sourceClock.epochMillis(), agentTime.nowMs(), 2);
    }

    @Test
    void aTimeResponseFromAnyoneButTheSourceIsIgnored() {
        PlatformClock agentTime = new PlatformClock();
        LayerHarness agent = new LayerHarness("a@p", new ManualClock(),
                new TemporalLayer(new TemporalLayer.Config(60_000, Frames.id("container@p"), SOURCE, 1_000), agentTime));
        Envelope request = agent.pollDown();
        LayerHarness rogue = new LayerHarness("rogue@p", new ManualClock(ManualClock.DEFAULT_EPOCH_MS + 50_000),
                new TemporalLayer(TemporalLayer.Config.window(600_000), new PlatformClock()));
        rogue.receiveUp(arriving(request, A, Frames.id("a@p")));
        agent.receiveUp(arriving(rogue.pollDown(), new Address("h", 66), Frames.id("rogue@p")));
        assertEquals(0, agentTime.offsetUs());
        assertEquals(1, agent.drops().get("unexpected-time"));
    }

    @Test
    void anAgentReadsThePlatformTimeItsTemporalLayerKeeps() {
        try (io.concord.testkit.Simulation sim = new io.concord.testkit.Simulation(12,
                io.concord.testkit.FaultPlan.NONE)) {
            io.concord.core.agent.AgentRuntime rt = sim.newRuntime("h", () -> java.util.List.of(
                    new io.concord.layers.parser.ParserLayer(io.concord.layers.parser.Membership.open(), null, true),
                    new TemporalLayer(TemporalLayer.Config.window(1_000), new PlatformClock()),
                    new io.concord.layers.security.SecurityLayer(new io.concord.layers.security.SecurityLayer.Config(
                            io.concord.layers.security.SecurityLayer.Protection.CRC, null, null, 1_000, 1)),
                    new io.concord.layers.communication.CommunicationLayer(
                            new io.concord.layers.communication.CommunicationLayer.Config(8192, 1))));
            io.concord.core.agent.Agent[] ref = new io.concord.core.agent.Agent[1];
            io.concord.core.acl.AID a = rt.startAgent("a", new io.concord.core.agent.LambdaAgent(ag -> ref[0] = ag));
            PlatformClock clock = ((TemporalLayer) rt.layers(a).get(1)).clock();
            clock.update(7_000_000, 100);
            assertEquals(sim.clock().epochMillis() + 7_000, ref[0].currentTimeMillis(),
                    "the agent reads the platform time, 7 s ahead of its host's");
        }
    }
}
