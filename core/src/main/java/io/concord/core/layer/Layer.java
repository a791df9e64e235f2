package io.concord.core.layer;

/**
 * One layer of an agent's communication stack. Handles messages going down ({@link #onDown}, on
 * send) and up ({@link #onUp}, on receive), and control events; by default each passes through.
 * Layers are started bottom-up and stopped top-down. A layer never lets one bad message stop the
 * stack: it drops it through {@link LayerContext#drop}, and goes on. An exception thrown by a
 * layer is caught by the stack, counted as a drop with reason {@code "layer-error"}, and logged.
 *
 * <p>A layer instance belongs to one stack (one agent) and is called only from that stack's loop.
 */
public abstract class Layer {

    /** A short name for traces; the class's simple name by default. */
    public String name() {
        return getClass().getSimpleName();
    }

    /**
     * True if this layer finds where a receiver known only by its name is (the container layer,
     * from the platform's agent lists): the node then passes it such receivers with no
     * destination, and the layer sets one or drops the message. False by default: the node drops
     * a message for a receiver it cannot place, and tells the sender.
     */
    public boolean resolvesNames() {
        return false;
    }

    /**
     * True if this layer lets an application message between two agents of one runtime be handed
     * over in memory, past both stacks (see {@code AgentRuntime.Builder#handOver}). A layer that
     * acts on such a message itself (answers it, or reports it to a sniffer) says false for it.
     * Called on the loop, for the sender's stack and the receiver's.
     */
    public boolean mayHandOver(io.concord.core.acl.AclMessage message) {
        return true;
    }

    /** Called once when the stack is built, bottom layer first. */
    public void init(LayerContext ctx) {
    }

    /** Called when the stack starts, bottom layer first. */
    public void start(LayerContext ctx) {
    }

    /** Called when the stack stops, top layer first. */
    public void stop(LayerContext ctx) {
    }

    /** A message on its way to the network. */
    public void onDown(LayerContext ctx, Envelope env) {
        ctx.passDown(env);
    }

    /** A message on its way to the agent. */
    public void onUp(LayerContext ctx, Envelope env) {
        ctx.passUp(env);
    }

    /** A control event; passed on in its direction by default. */
    public void onEvent(LayerContext ctx, StackEvent event) {
        ctx.fireEvent(event);
    }
}
