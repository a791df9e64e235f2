package io.concord.core.layer;

/**
 * Receives trace events: a message sent, received, dropped (with its reason), a timer fired. A
 * simulation hashes them to prove determinism; a real platform may log them.
 */
@FunctionalInterface
public interface Tracer {
    /** Discards everything. */
    Tracer NONE = (nowNs, node, event, detail) -> { };

    /**
     * @param nowNs  loop time
     * @param node   who (an agent's name)
     * @param event  what, a short word: {@code send}, {@code deliver}, {@code drop}, ...
     * @param detail more, free text
     */
    void trace(long nowNs, String node, String event, String detail);

    /** True if this tracer wants events; callers skip building details otherwise. */
    default boolean enabled() {
        return this != NONE;
    }

    /** A message as traces show it: act, sender, conversation, content length and hash. */
    static String describe(io.concord.core.acl.AclMessage m) {
        String c = m.getContent();
        return m.getPerformative().wireName() + " from " + (m.getSender() == null ? "?" : m.getSender().name())
                + " conv=" + m.getConversationId() + " content=" + (c == null ? 0 : c.length()) + "/"
                + (c == null ? 0 : c.hashCode());
    }
}
