package io.concord.core.layer;

/**
 * A layer refuses to send a message for a reason the caller can fix (it is too large, say). Unlike
 * other exceptions in layers, it is not swallowed by the stack: it is counted as a drop and then
 * reaches the code that called {@code send}, with the reason and what to do.
 */
public class SendRejectedException extends RuntimeException {
    private final String reason;

    /**
     * @param reason  the drop reason it is counted under, e.g. {@code "too-large"}
     * @param message what was wrong and what to do
     */
    public SendRejectedException(String reason, String message) {
        super(message);
        this.reason = reason;
    }

    private boolean counted;

    /** True the first time: the stack counts the drop once, where the layer refused. */
    boolean countOnce() {
        boolean first = !counted;
        counted = true;
        return first;
    }

    /** The drop reason. */
    public String reason() {
        return reason;
    }
}
