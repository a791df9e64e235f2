package io.concord.agents.door;

/** Told, on the thread that drives the door, when its leaf meets something or stops where it was sent. */
public interface DoorListener {

    /** The leaf met {@code what} (a chair's or an obstacle's name) while moving, and stopped. */
    void onContact(DoorDriver door, String what);

    /** The leaf reached the position it was commanded to (open or closed). */
    default void onArrived(DoorDriver door) {
    }
}
