package io.concord.layers.security;

import java.security.MessageDigest;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;

/**
 * The identity keys pinned on first use, by agent name (case does not make another name): a
 * member cannot later speak as another. Loop thread only.
 */
final class Pins {
    /**
     * Identities pinned. At the limit a new name's handshake is refused rather than an old pin
     * forgotten: forgetting one would let a holder of the platform key who floods new names take
     * over a real agent's name with another identity.
     */
    static final int MAX_PINS = 16_384;

    /** What {@link #pin} found. */
    enum Outcome {
        /** The name is pinned to this key now, or was before. */
        PINNED,
        /** The name is pinned to another key. */
        OTHER_KEY,
        /** A new name, and {@link #MAX_PINS} are pinned already: not pinned. */
        FULL
    }

    private final Map<String, byte[]> pins = new HashMap<>();

    /** Pins the name to the signing key if it is new; says whether the key is the one pinned. */
    Outcome pin(String name, byte[] signingKey) {
        String pinKey = name.toLowerCase(Locale.ROOT);
        byte[] pinned = pins.get(pinKey);
        if (pinned == null) {
            if (pins.size() >= MAX_PINS) {
                return Outcome.FULL;
            }
            pins.put(pinKey, signingKey);
            return Outcome.PINNED;
        }
        return MessageDigest.isEqual(pinned, signingKey) ? Outcome.PINNED : Outcome.OTHER_KEY;
    }
}
