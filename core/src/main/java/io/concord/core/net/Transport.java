package io.concord.core.net;

import java.util.Locale;

/** How an agent's frames travel; each agent chooses one. */
public enum Transport {
    /** Datagrams: one frame a datagram; loss, duplication and reordering are the stack's to handle. */
    UDP,
    /** A stream per direction between two agents; frames are length-prefixed. */
    TCP;

    /** The scheme prefix in AID addresses: {@code udp://} or {@code tcp://}. */
    public String scheme() {
        return name().toLowerCase(Locale.ROOT) + "://";
    }
}
