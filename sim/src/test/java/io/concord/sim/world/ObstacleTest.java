package io.concord.sim.world;

import io.concord.agents.chair.Pose;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Point;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Obstacles added and removed while the world runs: they block, they are sensed, people walk. */
class ObstacleTest {
    private final HospitalWorld world = HospitalWorld.builder(HospitalMap.defaultHospital()).seed(11).build();

    @Test
    void aBoxAddedAtRunTimeBlocksTheCorridorAndIsSensed() {
        SimChair c = world.addChair("chair1", ChairConfig.standard().noiseless(), new Pose(3, 10.8, 0));
        world.run(0.5);
        assertEquals(3.0, c.latest().range(0), 0.0, "nothing ahead yet");
        Obstacle trolley = world.addBox("trolley", new Point(6, 10.8), 0.8, 3.4, 0);
        world.run(0.5);
        // The chair's front is at 3.6, the trolley's face at 5.6.
        assertEquals(2.0, c.latest().range(0), 0.005);
        c.drive(50, 50);
        world.run(6);
        assertEquals(5.6 - 0.6, c.truePose().x(), 0.03, "stopped at the trolley: " + c.truePose());
        assertTrue(world.collisions().stream().anyMatch(x -> x.other().equals("trolley")));
        trolley.remove();
        world.run(3);
        assertTrue(c.truePose().x() > 6.5, "the way is free again: " + c.truePose());
        assertTrue(trolley.removed());
        assertTrue(world.obstacles().isEmpty());
    }

    @Test
    void aPersonWalksTheirPathAndStopsAtItsEnd() {
        Obstacle p = world.addPerson("nurse", List.of(new Point(2, 10.8), new Point(10, 10.8), new Point(10, 11.8)), 1.2, false);
        world.run(4);
        assertFalse(p.arrived());
        assertTrue(p.position().x() > 6, "walking east: " + p.position());
        world.run(8);
        assertTrue(p.arrived());
        assertEquals(10, p.position().x(), 0.15);
        assertEquals(11.8, p.position().y(), 0.15);
    }

    @Test
    void aChairWaitingInTheCorridorIsPushedNoFurtherThanAPersonCanPush() {
        SimChair c = world.addChair("chair1", ChairConfig.standard().noiseless(), new Pose(8, 10.8, 0));
        world.addPerson("visitor", List.of(new Point(4, 10.8), new Point(12, 10.8)), 1.0, false);
        world.run(10);
        assertTrue(world.collisions().stream().anyMatch(x -> x.other().equals("visitor")), "they met");
        assertTrue(c.truePose().x() < 8.5, "the braked chair barely moved: " + c.truePose());
    }

    @Test
    void badObstaclesAreRefusedWithTheReason() {
        world.addBox("bed", new Point(15, 6.2), 2.0, 0.9, 0);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> world.addRound("bed", new Point(1, 1), 1))
                .getMessage().contains("taken"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> world.addBox("x", new Point(1, 1), 0, 1, 0))
                .getMessage().contains("sizes"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> world.addPerson("y", List.of(), 1, false))
                .getMessage().contains("path"));
    }
}
