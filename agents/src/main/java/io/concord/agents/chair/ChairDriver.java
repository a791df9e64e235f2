package io.concord.agents.chair;

/**
 * The one interface between a chair and the agent that drives it. Motor powers go in; state
 * reports (encoders, range sensors, bumper, battery, faults, odometry) come out at the chair's
 * rate. The simulated chair of {@code io.concord.sim} implements it, and so does the serial
 * driver of a real chair, so the control agent does not know which it drives.
 *
 * <p>Confined to one thread: call it, and receive its callbacks, on the loop of the runtime it
 * was attached to. A driver never blocks.
 */
public interface ChairDriver {

    /** The chair's name, unique in its world ("chair1"). */
    String name();

    /** What the chair is: body, wheels, encoders, sensors (in the order of the readings). */
    ChairLayout layout();

    /**
     * Sets each wheel's motor power, in percent of full power, -100 (full reverse) to 100 (full
     * forward). The wheels follow with the chair's acceleration curve; the powers hold until the
     * next call. Values outside the range are clamped; NaN counts as 0.
     */
    void drive(double leftPercent, double rightPercent);

    /** Both powers to 0: the chair brakes to a stand. */
    default void stop() {
        drive(0, 0);
    }

    /**
     * A supervisor holds motion (docs/chair-safety.md): the driver forgets the last command at
     * once and sends only neutral, whatever it is asked, until {@link #releaseMotion()}. A driver
     * that repeats its command by itself (the serial driver's heartbeat) must never repeat one
     * given before the hold. The default stops the chair.
     */
    default void holdMotion() {
        stop();
    }

    /**
     * The supervisor resumed (the board says it is armed again after a decision): commands reach
     * the motors again. A driver that holds motion by itself (a new session, a lost link, a host
     * that was frozen) stays held until this call. The default does nothing.
     */
    default void releaseMotion() {
    }

    /**
     * The supervisor's decision to resume, while the board is not armed: a driver whose board arms
     * only on an explicit step (the serial chair's ARM, docs/chair-protocol.md version 3) sends it,
     * for the board's state its last reading showed. Only the supervisor calls this, on a resume
     * and while it waits for the board to say it is armed; no heartbeat and no neutral command ever
     * arms a board. The default does nothing (a chair that {@link #reportsArming() reports no arming}).
     */
    default void arm() {
    }

    /** The latest state report, or null before the first. */
    ChairReadings latest();

    /** True while the link to the chair is up. A simulated chair is always online. */
    boolean online();

    /**
     * True if the chair has a board that arms (docs/chair-protocol.md): it drives only after an
     * {@link #arm() ARM} since its last switch-on, watchdog trip, e-stop or new session, says whether
     * it is armed in each reading, and refuses commands with events ({@link ChairListener#onEvent}).
     * A simulated chair does not: it is always armed, unless its e-stop is pressed.
     */
    default boolean reportsArming() {
        return false;
    }

    /**
     * Why the link is down, in words a user can act on ("every frame from the board fails its MAC:
     * ..."), or null when it is up or the driver cannot tell.
     */
    default String whyOffline() {
        return null;
    }

    /**
     * The frames the link to the chair dropped, by reason ({@code stale}, {@code corrupt}, {@code mac}...), for an
     * operator's safety column and the log; empty for a chair with no link (the simulated one).
     */
    default java.util.Map<String, Long> linkDrops() {
        return java.util.Map.of();
    }

    /** Sets the one listener told of every report (replacing any before); null removes it. */
    void setListener(ChairListener listener);
}
