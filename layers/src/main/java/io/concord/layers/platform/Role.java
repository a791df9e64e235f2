package io.concord.layers.platform;

/** An agent's part in its host's platform, as {@link ContainerLayer#role()} reports it. */
public enum Role {
    /** Discovering the others, or electing: no container to follow yet. */
    SEEKING,
    /** A member: it follows its container (or, after a failover, waits for the next). */
    MEMBER,
    /** Its host's container. */
    CONTAINER,
    /** The agent stopped. */
    STOPPED
}
