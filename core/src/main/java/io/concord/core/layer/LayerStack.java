package io.concord.core.layer;

import io.concord.core.acl.AclMessage;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.function.Consumer;

/**
 * An agent's stack of layers, top (next to the agent) first, frozen when built. Envelopes enter
 * at the top with {@link #sendDown} and leave at the bottom into the transmit sink; they enter at
 * the bottom with {@link #receiveUp} and leave at the top into the deliver sink.
 */
public final class LayerStack {
    private static final Logger LOG = LoggerFactory.getLogger(LayerStack.class);

    private final List<Layer> layers;
    private final Ctx[] contexts;
    private final boolean resolvesNames;
    private final StackHost host;
    private final Consumer<Envelope> deliver;
    private final Consumer<Envelope> transmit;
    private final Consumer<StackEvent> eventSink;
    private boolean started;

    /**
     * @param layers    top first
     * @param host      the owning node's services
     * @param deliver   receives envelopes leaving the top (to the agent)
     * @param transmit  receives envelopes leaving the bottom (to the network)
     * @param eventSink receives events leaving either end
     */
    public LayerStack(List<Layer> layers, StackHost host, Consumer<Envelope> deliver,
                      Consumer<Envelope> transmit, Consumer<StackEvent> eventSink) {
        this.layers = List.copyOf(layers);
        this.host = Objects.requireNonNull(host, "host");
        this.deliver = Objects.requireNonNull(deliver, "deliver");
        this.transmit = Objects.requireNonNull(transmit, "transmit");
        this.eventSink = Objects.requireNonNull(eventSink, "eventSink");
        this.contexts = new Ctx[this.layers.size()];
        boolean byName = false;
        for (int i = 0; i < contexts.length; i++) {
            contexts[i] = new Ctx(i, this.layers.get(i));
            byName |= contexts[i].layer.resolvesNames();
        }
        this.resolvesNames = byName;
        for (int i = contexts.length - 1; i >= 0; i--) {
            contexts[i].layer.init(contexts[i]);
        }
    }

    /** The layers, top first. */
    public List<Layer> layers() {
        return layers;
    }

    /** The topmost layer of this type, or {@code null}. */
    public <T> T find(Class<T> type) {
        for (Layer l : layers) {
            if (type.isInstance(l)) {
                return type.cast(l);
            }
        }
        return null;
    }

    /** Starts the layers, bottom first. */
    public void start() {
        if (started) {
            return;
        }
        for (int i = contexts.length - 1; i >= 0; i--) {
            contexts[i].layer.start(contexts[i]);
        }
        started = true;
    }

    /** Stops the layers, top first. */
    public void stop() {
        if (!started) {
            return;
        }
        started = false;
        for (Ctx c : contexts) {
            try {
                c.layer.stop(c);
            } catch (RuntimeException e) {
                LOG.warn("layer {} failed to stop: {}", c.layer.name(), e.toString());
            }
        }
    }

    /** True if every layer of this stack lets the message be handed over in memory ({@link Layer#mayHandOver}). */
    public boolean mayHandOver(AclMessage message) {
        for (Ctx c : contexts) {
            if (!c.layer.mayHandOver(message)) {
                return false;
            }
        }
        return true;
    }

    /** True if a layer of this stack resolves receivers by name ({@link Layer#resolvesNames()}). */
    public boolean resolvesNames() {
        return resolvesNames;
    }

    /** Sends an envelope down from the top. */
    public void sendDown(Envelope env) {
        down(0, env);
    }

    /** Passes received bytes up from the bottom. */
    public void receiveUp(Envelope env) {
        up(contexts.length - 1, env);
    }

    /** Fires an event from the top going down, or from the bottom going up. */
    public void fireEvent(StackEvent event) {
        event(event.up() ? contexts.length - 1 : 0, event);
    }

    private void down(int index, Envelope env) {
        if (index >= contexts.length) {
            transmit.accept(env);
            return;
        }
        Ctx c = contexts[index];
        try {
            c.layer.onDown(c, env);
        } catch (SendRejectedException e) {
            if (e.countOnce()) { // by the layer that refused, not again by each above it
                drop(c.name, env, e.reason(), e.getMessage());
            }
            throw e;
        } catch (RuntimeException e) {
            c.failed(env, e);
        }
    }

    private void up(int index, Envelope env) {
        if (index < 0) {
            deliver.accept(env);
            return;
        }
        Ctx c = contexts[index];
        try {
            c.layer.onUp(c, env);
        } catch (RuntimeException e) {
            c.failed(env, e);
        }
    }

    private void event(int index, StackEvent ev) {
        if (index < 0 || index >= contexts.length) {
            eventSink.accept(ev);
            return;
        }
        Ctx c = contexts[index];
        try {
            c.layer.onEvent(c, ev);
        } catch (RuntimeException e) {
            LOG.warn("layer {} failed on event {}: {}", c.layer.name(), ev.type(), e.toString());
        }
    }

    /** Counts and traces a drop on behalf of a layer. */
    void drop(String layer, Envelope env, String reason, String detail) {
        host.drops().record(host.nodeName(), layer, reason, detail);
        Tracer t = host.tracer();
        if (t.enabled()) {
            t.trace(host.nowNs(), host.nodeName(), "drop", layer + " " + reason + ": " + detail + " " + env);
        }
    }

    private final class Ctx implements LayerContext {
        private final int index;
        private final Layer layer;
        private final String name;

        Ctx(int index, Layer layer) {
            this.index = index;
            this.layer = layer;
            this.name = layer.name();
        }

        @Override
        public String layerName() {
            return name;
        }

        @Override
        public void passDown(Envelope env) {
            down(index + 1, env);
        }

        @Override
        public void passUp(Envelope env) {
            up(index - 1, env);
        }

        @Override
        public void fireEvent(StackEvent event) {
            event(event.up() ? index - 1 : index + 1, event);
        }

        @Override
        public void drop(Envelope env, String reason, String detail) {
            LayerStack.this.drop(name, env, reason, detail);
        }

        @Override
        public <T> T find(Class<T> type) {
            return LayerStack.this.find(type);
        }

        @Override
        public StackHost host() {
            return host;
        }

        /** Exception classes this layer has thrown, each logged with its stack trace once. */
        private final Set<Class<?>> traced = new HashSet<>();

        void failed(Envelope env, RuntimeException e) {
            // Once per layer and exception class with the stack trace; after that only counted (a
            // frame that makes a layer throw, sent a million times, must not write a million traces).
            if (traced.add(e.getClass())) {
                tracesLogged++;
                LOG.warn("layer {} of {} threw on {} (logged once for {}; later ones are counted as drops, reason layer-error)",
                        name, host.nodeName(), env, e.getClass().getSimpleName(), e);
            }
            drop(env, "layer-error", e.toString());
        }
    }

    private long tracesLogged;

    /** Stack traces logged for layers that threw: one per layer and exception class. */
    public long tracesLogged() {
        return tracesLogged;
    }

    /** A list of layers, top first, to add to before a stack is built from it (the stack keeps a copy). */
    public static List<Layer> list(Layer... topFirst) {
        return new ArrayList<>(List.of(topFirst));
    }
}
