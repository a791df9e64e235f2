package io.concord.layers.platform;


/** An agent's part in its host's platform, as {@link ContainerLayer#role()} reports it. */
public enum Role {
    /** Discovering the others, or electing: no container to follow yet. */
    SEEKING,
    /** Following a container. */
    MEMBER,
    /** Its host's container. */
    CONTAINER,
    /** The agent stopped. */
    STOPPED
}
