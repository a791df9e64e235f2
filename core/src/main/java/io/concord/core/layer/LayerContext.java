package io.concord.core.layer;

/**
 * A layer's handle on its place in the stack. Layers never hold their neighbours; they forward
 * through this context, which makes each layer testable alone (see {@code LayerHarness}).
 */
public interface LayerContext {

    /** The layer's name, for traces and drop reasons. */
    String layerName();

    /** Passes an envelope to the layer below (or to the network, at the bottom). */
    void passDown(Envelope env);

    /** Passes an envelope to the layer above (or to the agent, at the top). */
    void passUp(Envelope env);

    /** Passes an event on in its direction. */
    void fireEvent(StackEvent event);

    /**
     * Drops an envelope: counts it under {@code reason}, traces it with the detail, and goes on.
     *
     * @param reason a short stable word, e.g. {@code "malformed"}
     * @param detail what exactly was wrong, for the trace
     */
    void drop(Envelope env, String reason, String detail);

    /**
     * The topmost layer of this type in the same stack, or {@code null} if it has none: how a layer
     * reads the state of another (the observer reports the container's role and the temporal
     * layer's clock). Messages still go only to the neighbours, through {@link #passDown} and
     * {@link #passUp}.
     */
    <T> T find(Class<T> type);

    /** The node's services: time, timers, tracing. */
    StackHost host();

    /** Shorthand for {@code host().nowNs()}. */
    default long nowNs() {
        return host().nowNs();
    }
}
