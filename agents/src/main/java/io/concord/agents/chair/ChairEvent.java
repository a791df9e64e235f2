package io.concord.agents.chair;

/**
 * Something a chair's board (or its driver) reported that is not a reading: a refusal, a change of
 * its arming, a reboot, a board that speaks another protocol, why the link went down, a host that
 * was frozen. Told to the driver's listener on the loop, once
 * per frame that carried it ({@link ChairListener#onEvent}); a {@link ChairSupervisor} turns them
 * into holds.
 *
 * @param kind   what happened
 * @param detail the board's reason in words ("not neutral", "watchdog", "boot 7 after boot 6")
 */
public record ChairEvent(Kind kind, String detail) {

    /** The kinds of event. */
    public enum Kind {
        /** The board refused a host frame (a NAK): the command was not applied. */
        REFUSED,
        /** The board says it is not armed (a STATE without the armed bit), with the reason it gives. */
        DISARMED,
        /** The board says it is armed again (a STATE with the armed bit). */
        ARMED,
        /** The board started again (a new boot number in HELLO or STATE): its motors are at zero, its counts restarted. */
        REBOOTED,
        /** The board speaks another version of the protocol: nothing it says is taken. */
        INCOMPATIBLE,
        /**
         * The link went down, and why ("every frame stale: ...", "the board has been silent for
         * 543 ms"): told just before {@link ChairListener#onOnline onOnline(false)}.
         */
        LINK_LOST,
        /**
         * The host was frozen or starved (its heartbeat ran late): the driver did not send the
         * command it held, sent neutral, and holds motion until {@link ChairDriver#releaseMotion()}.
         */
        HOST_FROZEN
    }

    @Override
    public String toString() {
        return kind + (detail == null || detail.isEmpty() ? "" : " (" + detail + ")");
    }
}
