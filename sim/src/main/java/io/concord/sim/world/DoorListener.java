package io.concord.sim.world;

/** Told, on the thread that steps the world, when a door's leaf meets something or stops moving. */
public interface DoorListener {

    /** The leaf met {@code what} (a chair's or an obstacle's name) while moving, and stopped. */
    void onContact(WorldDoor door, String what);

    /** The leaf reached the position it was commanded to (open or closed). */
    default void onArrived(WorldDoor door) {
    }
}
