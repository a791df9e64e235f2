package io.concord.serial;

/** A frame that is not taken, with the reason it is counted under and what was wrong. */
final class FrameException extends RuntimeException {
    private final String reason;

    /**
     * @param reason the drop counter's reason: corrupt, oversized, mac, malformed, unknown-type
     * @param detail what was wrong
     */
    public FrameException(String reason, String detail) {
        super(reason + ": " + detail);
        this.reason = reason;
    }

    /** The drop counter's reason. */
    public String reason() {
        return reason;
    }
}
