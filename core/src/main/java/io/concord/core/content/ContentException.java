package io.concord.core.content;

/**
 * Content that cannot be read, written or mapped: malformed text, a limit passed, a value that
 * breaks its schema. The message is written to be sent back as the reason of a NOT-UNDERSTOOD.
 */
public class ContentException extends Exception {
    private static final long serialVersionUID = 1L;

    /** With a reason. */
    public ContentException(String reason) {
        super(reason);
    }

    /** With a reason and a cause. */
    public ContentException(String reason, Throwable cause) {
        super(reason, cause);
    }

    /** The reason, fit for the content of a NOT-UNDERSTOOD. */
    public String reason() {
        return getMessage();
    }
}
