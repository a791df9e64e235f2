package io.concord.core.agent;

import io.concord.core.layer.Layer;
import io.concord.core.net.Transport;

import java.util.List;
import java.util.Objects;
import java.util.function.Supplier;

/**
 * How one agent is started, where it differs from its runtime's defaults: its reception port, its
 * transport and its own stack of layers (each agent may choose them).
 *
 * @param port      the reception port, or 0 for any free one
 * @param stack     the agent's layers, top first, or {@code null} for the runtime's
 * @param transport UDP or TCP, or {@code null} for the runtime's
 */
public record AgentOptions(int port, Supplier<List<Layer>> stack, Transport transport, PortRange portRange) {

    public AgentOptions {
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be 0..65535, got " + port);
        }
        if (port != 0 && portRange != null) {
            throw new IllegalArgumentException("choose a fixed port or a port range, not both");
        }
    }

    public AgentOptions(int port, Supplier<List<Layer>> stack, Transport transport) {
        this(port, stack, transport, null);
    }

    /**
     * Port-binding discovery: the agent takes the first free port of the range; the ports it finds
     * held below it and in the probe window past it are its potential peers
     * ({@link io.concord.core.net.internal.Neighbourhood#neighbours()}).
     */
    public AgentOptions withPortRange(PortRange range) {
        return new AgentOptions(0, stack, transport, Objects.requireNonNull(range, "range"));
    }

    /** Any free port, the runtime's stack. */
    public static AgentOptions defaults() {
        return new AgentOptions(0, null, null);
    }

    public AgentOptions withPort(int p) {
        return new AgentOptions(p, stack, transport, portRange);
    }

    public AgentOptions withStack(Supplier<List<Layer>> topFirstLayers) {
        return new AgentOptions(port, Objects.requireNonNull(topFirstLayers, "stack"), transport, portRange);
    }

    public AgentOptions withTransport(Transport t) {
        return new AgentOptions(port, stack, Objects.requireNonNull(t, "transport"), portRange);
    }
}
