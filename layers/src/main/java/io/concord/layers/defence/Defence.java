package io.concord.layers.defence;

/**
 * The safety stack's defences, one per EN 50159 threat test. Every one is on in every stack,
 * unless a test builds a stack without some ({@code withoutDefences} of {@code SafetyStack.Builder} and
 * {@code Platform.Builder}) to show the threat it stands against reaching an agent. Every layer
 * reads its own switches here, so this sits below the layers, and the builders above them. The switch belongs to the stacks a builder makes,
 * never to the JVM: no code can weaken a stack it did not build, and tests run side by side.
 */
public enum Defence {
    /** The sequence layer drops frames it delivered or holds already ({@code repeated}). */
    SEQUENCE_WINDOW,
    /** The sender retransmits what the receiver NAKs or does not acknowledge. */
    RETRANSMISSION,
    /** The receiver holds frames that come early until the gap before them is filled. */
    REORDER_BUFFER,
    /** The security layer checks the CRC-32C safety code. */
    SAFETY_CODE,
    /** The security layer checks the HMAC tag (class 3). */
    HMAC_TAG,
    /** The temporal layer refuses frames stamped outside the acceptance window. */
    ACCEPTANCE_WINDOW,
    /** The parser layer compares a message's sender with the agent its frame authenticated. */
    IDENTIFICATION,
    /**
     * The sequence layer keeps at most the receiver's window of frames unacknowledged, holds the
     * rest (slowing the sending agent), and the receiver closes its window while its mailbox is full.
     */
    FLOW_CONTROL,
    /**
     * The sequence layer takes a peer's stream (its frames' numbers, and a new stream at its
     * restart) only from frames sealed to this agent, never from a frame for any agent, which any
     * key holder can seal in any agent's name ({@code unauthenticated}).
     */
    SESSION_PROOF,
    /**
     * The container layer changes container only on the claimed container's own word, sealed to
     * this agent; a claim in a frame for any agent (which any key holder can seal in any name) is
     * a hint, checked by asking the claimed container itself.
     */
    CLAIM_CHECK,
    /**
     * The container layer checks an agent of its host that fell silent by its port before taking
     * it for dead: a process that still holds its port is slow, not gone (no false eviction, no
     * election on a busy machine).
     */
    PORT_CHECK,
    /**
     * The platform's {@code Policy} decides who may use each service (the observation service,
     * the platform protocol, a chair's resume...): off, everyone may use everything, so that the
     * tests can show each refusal's attack succeed without it.
     */
    AUTHORITY
}
