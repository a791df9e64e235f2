package io.concord.core.codec;

/**
 * A message could not be decoded. Names the offset in the input, what was expected there and
 * what was found, so the sender of a bad message can be told precisely what is wrong.
 */
public final class AclParseException extends Exception {
    private final int offset;
    private final String expected;
    private final String found;

    public AclParseException(int offset, String expected, String found) {
        super("malformed ACL message at offset " + offset + ": expected " + expected + " but found " + found);
        this.offset = offset;
        this.expected = expected;
        this.found = found;
    }

    /** Offset in the input (characters for the string codec, bytes for the binary one). */
    public int offset() {
        return offset;
    }

    /** What the decoder expected at {@link #offset()}. */
    public String expected() {
        return expected;
    }

    /** What it found there. */
    public String found() {
        return found;
    }
}
