package io.concord.serial;

/**
 * The wire to the board as {@link SerialChair} uses it: a serial port ({@link SerialPortLink}), or
 * a test's stand-in, so that the driver's rules can be shown on a manual clock with no port.
 */
interface BoardLink {

    /** Waits for bytes and reads them into {@code buf}; the count read, or -1 once the port is gone. */
    int read(byte[] buf);

    /** Writes one frame's bytes; false if the port did not take them all. */
    boolean write(byte[] frame);

    /** Closes the port; a read under way returns. */
    void close();

    /** Opens the link to the board. */
    @FunctionalInterface
    interface Opener {
        /** The link, or null if it cannot be opened now (the driver tries again with back-off). */
        BoardLink open();
    }
}
