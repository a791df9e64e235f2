package io.concord.layers;

import io.concord.layers.security.SecurityLayer;

/**
 * Named after the EN 50159 transmission classes: pick one word, get the defences that class
 * needs. Every profile keeps the safety code; they differ in cryptography.
 */
public enum Profile {
    /** A closed network (classes 1-2): CRC-32C, sequence numbers, timestamps. */
    CLOSED(SecurityLayer.Protection.CRC),
    /** A LAN others may reach (class 3): adds HMAC-SHA256 with the platform key. */
    CLASS_3(SecurityLayer.Protection.HMAC),
    /**
     * An open network, the Internet (class 7; the default): AES-GCM with per-pair keys agreed by
     * a handshake signed with each agent's Ed25519 identity; identification and membership.
     */
    CLASS_7(SecurityLayer.Protection.GCM_PAIR);

    private final SecurityLayer.Protection protection;

    Profile(SecurityLayer.Protection protection) {
        this.protection = protection;
    }

    /** The protection of data frames. */
    public SecurityLayer.Protection protection() {
        return protection;
    }
}
