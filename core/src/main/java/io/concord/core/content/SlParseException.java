package io.concord.core.content;

/** Malformed SL text, or text past the reader's limits; names the character offset. */
public final class SlParseException extends ContentException {
    private static final long serialVersionUID = 1L;
    private final int position;

    /** At a 0-based character offset. */
    public SlParseException(String what, int position) {
        super(what + " at position " + position);
        this.position = position;
    }

    /** The 0-based character offset where reading stopped. */
    public int position() {
        return position;
    }
}
