package io.concord.layers.platform;

/**
 * A platform message that would make an agent hold more than a limit allows (a list's pages, the
 * hosts it knows): it is dropped and counted with {@link #reason()}, as a malformed one is.
 */
final class PlatformLimit extends IllegalArgumentException {
    private final String reason;

    PlatformLimit(String reason, String message) {
        super(message);
        this.reason = reason;
    }

    /** The drop counter's reason. */
    String reason() {
        return reason;
    }
}
