package io.concord.testkit;

import io.concord.core.layer.DropCounters;
import io.concord.core.layer.Envelope;
import io.concord.core.layer.Layer;
import io.concord.core.layer.LayerStack;
import io.concord.core.layer.StackEvent;
import io.concord.core.layer.StackHost;
import io.concord.core.layer.Tracer;
import io.concord.core.time.Clock;
import io.concord.core.time.internal.DeadlineTimerWheel;
import io.concord.core.time.ManualClock;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Drives one layer (or a few) from a test, on the test's thread, with time frozen and advanced by
 * hand: Netty's {@code EmbeddedChannel} for Concord layers. What leaves the bottom is queued in
 * {@link #pollDown()}, what leaves the top in {@link #pollUp()}.
 */
public final class LayerHarness implements StackHost {
    private final ManualClock clock;
    private final DeadlineTimerWheel wheel;
    private final Map<Long, Runnable> tasksByWheelId = new HashMap<>();
    private final ArrayDeque<Envelope> down = new ArrayDeque<>();
    /** The lane of each envelope in {@link #down}, as it left: kept only while the envelope waits to be polled. */
    private final ArrayDeque<Integer> downLanes = new ArrayDeque<>();
    private final ArrayDeque<Envelope> up = new ArrayDeque<>();
    private final List<StackEvent> events = new ArrayList<>();
    private final DropCounters drops = new DropCounters();
    private final TraceRecorder trace = new TraceRecorder();
    private final LayerStack stack;
    private final String name;
    private java.util.function.Predicate<io.concord.core.net.Address> inMemory = a -> false;
    private boolean tracing = true;
    private boolean inboxFull;
    private boolean backpressure;
    private final io.concord.core.net.Address localAddress;
    private final Map<Class<?>, Object> capabilities;
    private final java.util.SplittableRandom random;

    /** A started stack of the given layers, top first, named {@code "harness"}. */
    public LayerHarness(Layer... topFirst) {
        this("harness", new ManualClock(), topFirst);
    }

    public LayerHarness(String name, ManualClock clock, Layer... topFirst) {
        this(new Builder().name(name).clock(clock), topFirst);
    }

    private LayerHarness(Builder b, Layer... topFirst) {
        this.name = b.name;
        this.clock = b.clock;
        this.localAddress = b.localAddress;
        this.capabilities = Map.copyOf(b.capabilities);
        this.random = new java.util.SplittableRandom(b.seed);
        this.wheel = DeadlineTimerWheel.forAgents(clock.nanoTime());
        this.stack = new LayerStack(List.of(topFirst), this, up::add, e -> {
            down.add(e);
            downLanes.add(e.lane());
        }, events::add);
        stack.start();
    }

    /** A harness with a name, an address, a seed and capabilities of its own (for layers that need them). */
    public static Builder builder() {
        return new Builder();
    }

    public static final class Builder {
        private String name = "harness";
        private ManualClock clock = new ManualClock();
        private io.concord.core.net.Address localAddress;
        private final Map<Class<?>, Object> capabilities = new HashMap<>();
        private long seed = 1;

        /** The node's name, {@code local@platform} for a platform's layers. */
        public Builder name(String name) {
            this.name = name;
            return this;
        }

        public Builder clock(ManualClock clock) {
            this.clock = clock;
            return this;
        }

        public Builder localAddress(io.concord.core.net.Address a) {
            this.localAddress = a;
            return this;
        }

        /** Offers the layers a capability (see {@link StackHost#capability}). */
        public <T> Builder offer(Class<T> type, T capability) {
            capabilities.put(type, capability);
            return this;
        }

        /** The seed of the harness's random source (1 by default). */
        public Builder seed(long seed) {
            this.seed = seed;
            return this;
        }

        /** Builds and starts the stack, top first. */
        public LayerHarness build(Layer... topFirst) {
            return new LayerHarness(this, topFirst);
        }
    }

    /** Says which destinations the stack is to take for agents of its own runtime (none by default). */
    public void setInMemory(java.util.function.Predicate<io.concord.core.net.Address> inMemory) {
        this.inMemory = inMemory;
    }

    @Override
    public boolean inMemoryTo(io.concord.core.net.Address to) {
        return inMemory.test(to);
    }

    /**
     * Turns tracing off (it is on, into {@link #trace()}), as in a runtime without a tracer: for
     * benchmarks, where building every drop's trace line would be measured too.
     */
    public void setTracing(boolean on) {
        this.tracing = on;
    }

    /** Says whether the agent's mailbox is over half full, as a runtime would ({@link StackHost#inboxFull}). */
    public void setInboxFull(boolean full) {
        this.inboxFull = full;
    }

    @Override
    public boolean inboxFull() {
        return inboxFull;
    }

    @Override
    public void backpressure(boolean on) {
        this.backpressure = on;
    }

    /** True while a layer asks to pause the agent's behaviours ({@link StackHost#backpressure}), as flow control does. */
    public boolean backpressured() {
        return backpressure;
    }

    /** Sends an envelope into the top of the stack. */
    public void sendDown(Envelope env) {
        stack.sendDown(env);
    }

    /** Passes an envelope into the bottom of the stack. */
    public void receiveUp(Envelope env) {
        stack.receiveUp(env);
    }

    /** Fires a control event into the stack (from the top if it goes down, from the bottom if up). */
    public void fireEvent(StackEvent event) {
        stack.fireEvent(event);
    }

    /** The next envelope that left the bottom, or {@code null}. */
    public Envelope pollDown() {
        downLanes.poll();
        return down.poll();
    }

    /** The next envelope that left the top, or {@code null}. */
    public Envelope pollUp() {
        return up.poll();
    }

    /** The lane of every envelope that left the bottom and waits to be polled, as it left (an envelope sent twice shows both). */
    public List<Integer> downLanes() {
        // Only those not polled yet: a list of every lane ever sent grew by one a frame for as long
        // as the harness lived (the stack benchmark's millions of frames).
        return List.copyOf(downLanes);
    }

    public int downCount() {
        return down.size();
    }

    public int upCount() {
        return up.size();
    }

    /** Events that left either end. */
    public List<StackEvent> events() {
        return events;
    }

    /** Moves time forward and runs the layers' timers that fall due, in order. */
    public void advanceMs(long ms) {
        clock.advanceMs(ms);
        wheel.poll(clock.nanoTime(), (now, id) -> {
            Runnable r = tasksByWheelId.remove(id);
            if (r != null) {
                r.run();
            }
        });
    }

    public void stop() {
        stack.stop();
    }

    public ManualClock manualClock() {
        return clock;
    }

    public TraceRecorder trace() {
        return trace;
    }

    @Override
    public String nodeName() {
        return name;
    }

    @Override
    public io.concord.core.net.Address localAddress() {
        return localAddress;
    }

    @Override
    public <T> T capability(Class<T> type) {
        return type.cast(capabilities.get(type));
    }

    @Override
    public java.util.random.RandomGenerator random() {
        return random;
    }

    /** A harness's secrets come from its seeded random source: a test replays. */
    @Override
    public void secretBytes(byte[] out) {
        random.nextBytes(out);
    }

    @Override
    public Clock clock() {
        return clock;
    }

    @Override
    public long nowNs() {
        return clock.nanoTime();
    }

    @Override
    public long schedule(long deadlineNs, Runnable task) {
        long id = wheel.schedule(deadlineNs);
        tasksByWheelId.put(id, task);
        return id;
    }

    @Override
    public boolean cancel(long timerId) {
        tasksByWheelId.remove(timerId);
        return wheel.cancel(timerId);
    }

    @Override
    public Tracer tracer() {
        return tracing ? trace : Tracer.NONE;
    }

    /** Stack traces its stack has logged for layers that threw. */
    public long tracesLogged() {
        return stack.tracesLogged();
    }

    @Override
    public DropCounters drops() {
        return drops;
    }
}
