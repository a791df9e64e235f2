package io.concord.layers.platform;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.agent.internal.CoLocated;
import io.concord.core.layer.SendRejectedException;
import io.concord.core.net.Address;
import io.concord.core.net.Channels;

import java.util.random.RandomGenerator;

/**
 * What the roles, the federation, the gateway relay and the directory may use of the container
 * layer: sending platform messages, timers, tracing, counting drops, and who this agent is. They
 * get this, never the layer.
 */
interface PlatformContext {

    PlatformConfig config();

    /** The platform's name (the part after {@code @}). */
    String platform();

    /** This agent's name. */
    String self();

    /** This agent's entry as the lists hold it (its services included). */
    AgentEntry selfEntry();

    AID selfAid();

    /** The loop's time. */
    long nowNs();

    /** This host's wall clock, in ms. */
    long epochMillis();

    /** Runs a task on the loop after {@code ms}; returns the timer's id. */
    long after(long ms, Runnable task);

    /** Cancels a timer if {@code id >= 0}; returns -1, to assign back. */
    long cancel(long id);

    RandomGenerator random();

    /** Fills {@code out} with bytes nobody can guess (the runtime's SecureRandom; its seeded source in a simulation). */
    void secretBytes(byte[] out);

    /**
     * The agents of this agent's runtime, reached in memory: they live and die with this loop, so
     * they need no alive messages to be known alive. {@code null} where the node offers none.
     */
    default CoLocated coLocated() {
        return null;
    }

    /** The loop's selector, for a gateway that serves sockets on the loop; {@code null} where the network has none. */
    default Channels channels() {
        return null;
    }

    /**
     * The container layer of the entry's agent, if it runs in this agent's runtime and the runtime
     * lets a layer read its peer's in memory (on the loop); {@code null} otherwise.
     */
    default ContainerLayer peerLayer(AgentEntry e) {
        CoLocated c = coLocated();
        Address a = e.transportAddress();
        return c == null || a == null ? null : c.layer(a, ContainerLayer.class);
    }

    /**
     * Whether the entry's agent still holds its port on this host: false proves its process gone
     * (crashed or killed), true that it lives (perhaps slow); {@code null} where this cannot be told
     * (another host, or no such check here).
     */
    default Boolean portHeld(AgentEntry e) {
        return null;
    }

    /** True if the entry's agent runs in this agent's runtime, reached in memory. */
    default boolean here(AgentEntry e) {
        CoLocated c = coLocated();
        Address a = e.transportAddress();
        return c != null && a != null && c.here(a);
    }

    /** A platform message from this agent to one receiver: the platform's ontology and language, the protocol given. */
    AclMessage message(Performative act, String protocol, AID to, String content);

    /** Sends a platform message; a refusal is counted, never thrown. */
    void send(Performative act, String protocol, AID to, PlatformMessage content);

    /** A reply to a message with a platform message, as this agent (to send with {@link #sendQuietly}). */
    AclMessage reply(AclMessage to, Performative act, PlatformMessage content);

    /**
     * Sends a message through this agent's whole stack, as the agent would.
     *
     * @throws SendRejectedException if the stack refuses it at once
     */
    void sendOrThrow(AclMessage m);

    /** Sends a message as it is; a refusal is counted, never thrown. */
    void sendQuietly(AclMessage m);

    /** Whoever holds a port: the receiver of discovery. */
    AID anyAt(Address a);

    void trace(String event, String detail);

    /** Counts a drop of something that is not an envelope (a relay nothing can carry, a bad secret). */
    void drop(String reason, String detail);
}
