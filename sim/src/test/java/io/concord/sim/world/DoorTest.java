package io.concord.sim.world;

import io.concord.agents.door.DoorListener;
import io.concord.agents.door.DoorDriver;
import io.concord.agents.chair.Pose;
import io.concord.agents.map.HospitalMap;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Each kind of door opens, closes, and stops on a chair in its way without pushing it. In the
 * default hospital: A1 is hinged (hinge at (1.9, 12.6), swinging north into room A1), WA sliding
 * (across the corridor at x = 20, sliding north into the wall), WB rotating (across the corridor
 * at x = 28, pivot at (28, 10.8)).
 */
class DoorTest {
    private final HospitalWorld world = HospitalWorld.builder(HospitalMap.defaultHospital()).seed(3).build();
    private final List<String> events = new ArrayList<>();

    private WorldDoor door(String id) {
        WorldDoor d = world.door(id);
        d.setListener(new DoorListener() {
            @Override
            public void onContact(DoorDriver door, String what) {
                events.add("contact " + door.id() + " " + what);
            }

            @Override
            public void onArrived(DoorDriver door) {
                events.add("arrived " + door.id() + " " + (door.isOpen() ? "open" : door.isClosed() ? "closed" : "between"));
            }
        });
        return d;
    }

    private void opensAndCloses(String id) {
        WorldDoor d = door(id);
        assertTrue(d.isClosed(), id + " starts closed");
        d.open();
        assertEquals(DoorDriver.Motion.OPENING, d.motion());
        world.run(0.5);
        assertFalse(d.isClosed(), "moving: " + d);
        assertFalse(d.isOpen(), "not there yet: " + d);
        world.run(6);
        assertTrue(d.isOpen(), "open: " + d);
        assertEquals(DoorDriver.Motion.STILL, d.motion());
        d.close();
        world.run(8);
        assertTrue(d.isClosed(), "closed: " + d);
        assertEquals(List.of("arrived " + id + " open", "arrived " + id + " closed"), events);
    }

    @Test
    void aHingedDoorOpensAndCloses() {
        opensAndCloses("A1");
    }

    @Test
    void aSlidingDoorOpensAndCloses() {
        opensAndCloses("WA");
    }

    @Test
    void aRotatingDoorOpensAndClosesTurningOneWay() {
        WorldDoor d = world.door("WB");
        opensAndCloses("WB");
        // A revolving door closes by turning on: half a turn in all.
        assertEquals(Math.PI, d.position(), 0.01);
    }

    @Test
    void anOpenDoorLeavesThePassageFree() {
        WorldDoor d = world.door("WA");
        d.open();
        world.run(7);
        SimChair c = world.addChair("chair1", ChairConfig.standard().noiseless(), new Pose(17.5, 10.8, 0));
        c.drive(50, 50);
        world.run(8);
        assertTrue(c.truePose().x() > 22, "through the doorway: " + c.truePose());
        assertEquals(0, c.bumps());
    }

    @Test
    void aClosedDoorStopsAChair() {
        SimChair c = world.addChair("chair1", ChairConfig.standard().noiseless(), new Pose(17.5, 10.8, 0));
        c.drive(50, 50);
        world.run(8);
        assertEquals(20 - 0.025 - 0.6, c.truePose().x(), 0.03, "at the leaf: " + c.truePose());
        assertTrue(world.collisions().stream().anyMatch(x -> x.other().equals("door WA")));
    }

    private void stopsOnAChair(String id, Pose chairAt, boolean closeFromOpen) {
        WorldDoor d = door(id);
        if (closeFromOpen) {
            d.open();
            world.run(8);
            events.clear();
        }
        SimChair c = world.addChair("chair1", ChairConfig.standard().noiseless(), chairAt);
        assertTrue(d.sweepOccupied(), "the chair stands where the leaf moves");
        assertEquals(List.of("chair1"), d.inSweep());
        if (closeFromOpen) {
            d.close();
        } else {
            d.open();
        }
        world.run(8);
        assertTrue(d.blocked(), "stopped: " + d);
        assertEquals(DoorDriver.Motion.STILL, d.motion());
        assertEquals("chair1", d.lastContact());
        assertEquals(List.of("contact " + id + " chair1"), events);
        assertFalse(d.isOpen() || d.isClosed(), "stopped between: " + d);
        assertTrue(c.truePose().distanceTo(chairAt) < 0.03, "the leaf did not push the chair: " + c.truePose());
        // It stays stopped: the leaf holds where it met the chair.
        double held = d.openFraction();
        world.run(3);
        assertEquals(held, d.openFraction(), 0.01);
    }

    @Test
    void aHingedDoorStopsOnAChairInItsSwing() {
        stopsOnAChair("A1", new Pose(2.9, 13.9, 0), false);
    }

    @Test
    void aSlidingDoorStopsOnAChairInItsWay() {
        stopsOnAChair("WA", new Pose(20, 11.4, 0), true);
    }

    @Test
    void aRotatingDoorStopsOnAChairInItsSweep() {
        stopsOnAChair("WB", new Pose(28.9, 10.0, 0), false);
    }

    @Test
    void aBlockedDoorOpensAgainWhenCommandedAndTheWayIsFree() {
        stopsOnAChair("A1", new Pose(2.9, 13.9, 0), false);
        world.removeChair("chair1");
        world.door("A1").open();
        world.run(4);
        assertTrue(world.door("A1").isOpen());
        assertFalse(world.door("A1").blocked());
    }

    @Test
    void theDoorwaySeesWhoStandsInIt() {
        WorldDoor d = world.door("WA");
        d.open();
        world.run(7);
        assertFalse(d.doorwayOccupied());
        world.addChair("chair1", ChairConfig.standard().noiseless(), new Pose(19.5, 10.8, 0));
        assertEquals(List.of("chair1"), d.inDoorway());
        world.addPerson("visitor", List.of(new io.concord.agents.map.Point(20.4, 12.0)), 1.0, false);
        assertEquals(2, d.inDoorway().size());
    }

    @Test
    void aFailedMechanismIgnoresCommands() {
        WorldDoor d = world.door("A5");
        d.setMechanismFailed(true);
        d.open();
        world.run(4);
        assertTrue(d.isClosed());
        assertTrue(d.mechanismFailed());
        d.setMechanismFailed(false);
        d.open();
        world.run(4);
        assertTrue(d.isOpen());
    }
}
