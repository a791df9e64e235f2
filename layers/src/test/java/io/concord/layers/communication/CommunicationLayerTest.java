package io.concord.layers.communication;

import io.concord.core.layer.Envelope;
import io.concord.core.layer.SendRejectedException;
import io.concord.core.net.Address;
import io.concord.testkit.LayerHarness;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class CommunicationLayerTest {
    private static Envelope frame(int size) {
        return Envelope.control(1, new Address("h", 1), new byte[size], 0, size);
    }

    @Test
    void sendsEachFrameTheConfiguredNumberOfTimes() {
        LayerHarness h = new LayerHarness(new CommunicationLayer(new CommunicationLayer.Config(8192, 3)));
        h.sendDown(frame(100));
        assertEquals(3, h.downCount());
        assertEquals(java.util.List.of(0, 1, 2), h.downLanes(), "each copy on a lane of its own: never two in one datagram");
    }

    @Test
    void sendsAFrameHandedOverInMemoryOnceAndOthersStillRepeated() {
        LayerHarness h = new LayerHarness(new CommunicationLayer(new CommunicationLayer.Config(8192, 2)));
        Address local = new Address("h", 1);
        h.setInMemory(local::equals);
        h.sendDown(frame(100));
        assertEquals(1, h.downCount(), "nothing to repeat against in memory");
        h.pollDown();
        h.sendDown(Envelope.control(1, new Address("h", 2), new byte[100], 0, 100));
        assertEquals(2, h.downCount(), "a frame that goes through the network is still repeated");
    }

    @Test
    void refusesToSendAFrameOverTheLimitAndTellsTheCaller() {
        LayerHarness h = new LayerHarness(new CommunicationLayer(new CommunicationLayer.Config(8192, 2)));
        SendRejectedException e = assertThrows(SendRejectedException.class, () -> h.sendDown(frame(8193)));
        assertTrue(e.getMessage().contains("8193") && e.getMessage().contains("8192"), e.getMessage());
        assertEquals(0, h.downCount(), "nothing half-sent");
        assertEquals(1, h.drops().get("too-large"));
    }

    @Test
    void dropsAnArrivingFrameOverTheLimit() {
        LayerHarness h = new LayerHarness(new CommunicationLayer(new CommunicationLayer.Config(8192, 2)));
        h.receiveUp(Envelope.incoming(new Address("h", 2), new byte[9000], 0, 9000, 0));
        assertNull(h.pollUp());
        assertEquals(1, h.drops().get("too-large"));
        h.receiveUp(Envelope.incoming(new Address("h", 2), new byte[8192], 0, 8192, 0));
        assertEquals(8192, h.pollUp().length());
    }

    @Test
    void refusesSettingsThatCannotWork() {
        assertThrows(IllegalArgumentException.class, () -> new CommunicationLayer.Config(70_000, 2));
        assertThrows(IllegalArgumentException.class, () -> new CommunicationLayer.Config(8192, 0));
    }
}
