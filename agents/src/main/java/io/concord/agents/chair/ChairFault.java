package io.concord.agents.chair;

/** Faults a chair's board reports; the control agent stops the chair on any of them. */
public enum ChairFault {
    /** The left motor or its power stage failed. */
    MOTOR_LEFT,
    /** The right motor or its power stage failed. */
    MOTOR_RIGHT,
    /** A range sensor gives no readings. */
    SENSOR,
    /** The battery is below its cut-off voltage. */
    BATTERY_LOW,
    /** The board's watchdog stopped the motors: the host went silent. */
    WATCHDOG,
    /** The link to the chair is down (serial port gone); readings are stale. */
    LINK
}
