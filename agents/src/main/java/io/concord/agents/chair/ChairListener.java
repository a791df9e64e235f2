package io.concord.agents.chair;

/**
 * Told by a chair driver, on the thread of the runtime that drives the chair (the agents' loop),
 * of every state report and of the link going down or coming back.
 */
public interface ChairListener {

    /** A state report arrived. */
    void onReadings(ChairReadings readings);

    /** The link is up (true) or down (false); while down, readings stop and the chair stands. */
    default void onOnline(boolean online) {
    }

    /** The board reported an event: a refusal, a change of its arming, a reboot (a serial chair; a simulated one has none). */
    default void onEvent(ChairEvent event) {
    }
}
