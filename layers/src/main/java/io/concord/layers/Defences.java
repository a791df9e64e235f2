package io.concord.layers;

/**
 * Switches for the threat tests, and only for them: each EN 50159 threat test switches the defence
 * it names off and shows that it then fails, so that no threat test passes by luck or by another
 * defence. Every switch is on in any real use; nothing in Concord turns one off. Set them before
 * the agents start (their loops read them unsynchronised).
 */
public final class Defences {
    /** The sequence layer drops frames it delivered or holds already ({@code repeated}). */
    public static boolean sequenceWindow = true;
    /** The sender retransmits what the receiver NAKs or does not acknowledge. */
    public static boolean retransmission = true;
    /** The receiver holds frames that come early until the gap before them is filled. */
    public static boolean reorderBuffer = true;
    /** The security layer checks the CRC-32C safety code. */
    public static boolean safetyCode = true;
    /** The security layer checks the HMAC tag (class 3). */
    public static boolean hmacTag = true;
    /** The temporal layer refuses frames stamped outside the acceptance window. */
    public static boolean acceptanceWindow = true;
    /** The parser layer compares a message's sender with the agent its frame authenticated. */
    public static boolean identification = true;
    /**
     * The sequence layer keeps at most the receiver's window of frames unacknowledged, holds the
     * rest (slowing the sending agent), and the receiver closes its window while its mailbox is full.
     */
    public static boolean flowControl = true;

    private Defences() {
    }

    /** Every defence on again (after a test switched one off). */
    public static void allOn() {
        sequenceWindow = true;
        retransmission = true;
        reorderBuffer = true;
        safetyCode = true;
        hmacTag = true;
        acceptanceWindow = true;
        identification = true;
        flowControl = true;
    }
}
