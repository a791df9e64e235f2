package io.concord.console;

import java.util.List;

/**
 * Drop reasons grouped by the EN 50159 threat their defence stands against (docs/security.md),
 * plus the limits that keep a flood from growing memory or work, and the rest; first, apart from
 * every threat, the copies the stack sends on purpose against loss (dropped as {@code copy}),
 * which a healthy platform on UDP counts by the thousand.
 */
final class Threats {
    /** The column of copies sent on purpose: not a threat. */
    static final String COPIES = "copies (expected)";
    /**
     * The column of another platform's frames (one sharing the port range: under another key, or
     * under the same key with another name), skipped: not a threat.
     */
    static final String OTHER_PLATFORMS = "other platforms (skipped)";
    static final List<String> ORDER = List.of(COPIES, OTHER_PLATFORMS, "repetition", "deletion", "insertion", "resequence", "corruption",
            "delay", "masquerade", "flooding", "other");
    /** The columns that are no threat: shown grey, never counted towards the alarm. */
    static final List<String> EXPECTED = List.of(COPIES, OTHER_PLATFORMS);

    private Threats() {
    }

    /** The threat a drop reason counts against. */
    static String of(String reason) {
        switch (reason) {
            case "copy", "handshake-late" -> {
                return COPIES;   // sent on purpose against loss, or a second answer to a retried hello
            }
            case "foreign-key", "foreign-platform" -> {
                return OTHER_PLATFORMS;
            }
            case "repeated", "replayed-handshake" -> {
                return "repetition";
            }
            case "lost", "nak-limit" -> {
                return "deletion";
            }
            case "misdirected", "no-session-key", "not-member", "unsolicited", "no-handshake", "unknown-receiver" -> {
                return "insertion";
            }
            case "reorder-overflow" -> {
                return "resequence";
            }
            case "corrupt", "bad-tag", "malformed", "malformed-frame", "malformed-handshake", "malformed-platform",
                 "tcp-malformed", "too-large", "list-too-large", "http-malformed", "http-too-large" -> {
                return "corruption";
            }
            case "stale", "from-future", "expired", "unexpected-time" -> {
                return "delay";
            }
            case "masquerade", "identification", "bad-secret", "unauthenticated", "unprotected",
                 "crossed-handshake" -> {
                return "masquerade";
            }
            default -> {
                if (reason.endsWith("-limit") || reason.endsWith("-full") || reason.startsWith("http-")
                        || reason.equals("tcp-connect-timeout") || reason.equals("pair-evicted")) {
                    return "flooding";
                }
                return "other";
            }
        }
    }
}
