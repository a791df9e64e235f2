package io.concord.agents.door;

import io.concord.agents.map.Door;

import java.util.List;

/**
 * The one interface between a door's mechanism and the door agent: the motion (open, close,
 * halt) and the sensing (where the leaf is, whether it met something, who is in the doorway and
 * in the leaf's sweep). The simulated door of {@code io.concord.sim} implements it; a real
 * door's controller would too. The door agent owns the state machine.
 *
 * <p>Confined to one thread: call it, and receive its callbacks, on the loop that drives it.
 */
public interface DoorDriver {
    /** What the leaf is doing. */
    enum Motion { STILL, OPENING, CLOSING }

    /** The door of the map this is. */
    Door spec();

    /** The door's id in the map. */
    default String id() {
        return spec().id();
    }

    /** The mechanism's clock, nanoseconds: the door agent times the door's motion and its closing on it. */
    long nowNs();

    /** Starts opening; ignored while the mechanism has failed. */
    void open();

    /** Starts closing; ignored while the mechanism has failed. */
    void close();

    /** Stops the leaf where it is and holds it there. */
    void halt();

    /** What the leaf is doing now. */
    Motion motion();

    /** How open the door is: 0 closed, 1 fully open. */
    double openFraction();

    /** True if open far enough to pass. */
    boolean isOpen();

    /** True if the leaf closes the opening. */
    boolean isClosed();

    /** True if the leaf stopped because it met something, until the next command. */
    boolean blocked();

    /** The name of what the leaf last met, or null. */
    String lastContact();

    /** True while the mechanism has failed: the door cannot move. */
    boolean mechanismFailed();

    /** The chairs and obstacles in the doorway, by name. */
    List<String> inDoorway();

    /** True if anything is in the doorway. */
    default boolean doorwayOccupied() {
        return !inDoorway().isEmpty();
    }

    /** The chairs and obstacles where the leaf moves, by name. */
    List<String> inSweep();

    /** True if anything is where the leaf moves. */
    default boolean sweepOccupied() {
        return !inSweep().isEmpty();
    }

    /** Sets the one listener (replacing any before); null removes it. */
    void setListener(DoorListener listener);
}
