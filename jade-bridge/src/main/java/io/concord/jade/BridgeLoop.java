package io.concord.jade;

import io.concord.core.net.Channels;
import io.concord.core.time.Clock;
import io.concord.layers.platform.GatewayContext;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.SelectableChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.PriorityQueue;
import java.util.concurrent.ConcurrentLinkedQueue;

/**
 * Where the HTTP MTP's sockets are served. On a platform whose network lends its selector
 * ({@link GatewayContext#channels()}), that is the agents' own loop: a request is read, parsed and
 * handed to its agent, and an agent's message to a JADE agent written, by the thread that runs the
 * agents, with no hand-off. Elsewhere (the test kit's virtual network, or a context of the tests'
 * own) it is a selector thread of the bridge's own.
 */
interface BridgeLoop {

    /** Registers a non-blocking channel. Loop only. */
    SelectionKey register(SelectableChannel channel, int ops, Channels.Ready ready) throws IOException;

    /** Runs a task on the loop. Any thread. */
    void execute(Runnable task);

    /** True on the loop's thread. */
    boolean inLoop();

    /** Runs a task now if called on the loop, else hands it to the loop. Any thread. */
    default void run(Runnable task) {
        if (inLoop()) {
            task.run();
        } else {
            execute(task);
        }
    }

    /** Runs a task on the loop after {@code ms}. Loop only. */
    void after(long ms, Runnable task);

    /** Stops a thread of the bridge's own, after the tasks already given to it; nothing for the platform's loop. Any thread. */
    void close();

    /**
     * The platform's loop, if it lends its selector; else a new thread of the bridge's own, whose
     * timers run by {@code clock}. Call on the loop.
     */
    static BridgeLoop of(GatewayContext ctx, String threadName, Clock clock) {
        Channels channels = ctx.channels();
        return channels == null ? new Own(threadName, clock) : new Platform(ctx, channels, Thread.currentThread());
    }

    /** The agents' loop. */
    final class Platform implements BridgeLoop {
        private final GatewayContext ctx;
        private final Channels channels;
        private final Thread loop;

        Platform(GatewayContext ctx, Channels channels, Thread loop) {
            this.ctx = ctx;
            this.channels = channels;
            this.loop = loop;
        }

        @Override
        public SelectionKey register(SelectableChannel channel, int ops, Channels.Ready ready) throws IOException {
            return channels.register(channel, ops, ready);
        }

        @Override
        public void execute(Runnable task) {
            ctx.execute(task);
        }

        @Override
        public boolean inLoop() {
            return Thread.currentThread() == loop;
        }

        @Override
        public void after(long ms, Runnable task) {
            ctx.after(ms, task);
        }

        @Override
        public void close() {
            // the platform's loop is not the bridge's to stop
        }
    }

    /** A selector and a thread of the bridge's own. */
    final class Own implements BridgeLoop {
        private static final Logger LOG = LoggerFactory.getLogger(Own.class);
        private final Selector selector;
        private final ConcurrentLinkedQueue<Runnable> tasks = new ConcurrentLinkedQueue<>();
        private final PriorityQueue<Timer> timers = new PriorityQueue<>();
        private final Thread thread;
        private final Clock clock;
        private volatile boolean running = true;
        private long timerSeq;

        private record Timer(long dueNs, long seq, Runnable task) implements Comparable<Timer> {
            @Override
            public int compareTo(Timer o) {
                return dueNs != o.dueNs ? Long.compare(dueNs, o.dueNs) : Long.compare(seq, o.seq);
            }
        }

        /** A selector thread whose timers ({@link #after}) run by {@code clock}. */
        Own(String threadName, Clock clock) {
            this.clock = clock;
            try {
                selector = Selector.open();
            } catch (IOException e) {
                throw new UncheckedIOException("cannot open a selector for the HTTP MTP", e);
            }
            thread = new Thread(this::run, threadName);
            thread.setDaemon(true);
            thread.start();
        }

        @Override
        public SelectionKey register(SelectableChannel channel, int ops, Channels.Ready ready) throws IOException {
            return channel.register(selector, ops, ready);
        }

        @Override
        public void execute(Runnable task) {
            tasks.add(task);
            selector.wakeup();
        }

        @Override
        public boolean inLoop() {
            return Thread.currentThread() == thread;
        }

        @Override
        public void after(long ms, Runnable task) {
            timers.add(new Timer(clock.nanoTime() + ms * 1_000_000L, timerSeq++, task));
        }

        @Override
        public void close() {
            running = false;
            selector.wakeup();
            if (Thread.currentThread() != thread) {
                try {
                    thread.join(5_000);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }

        private void run() {
            try {
                while (running) {
                    Timer first = timers.peek();
                    long waitMs = first == null ? 1_000 : Math.max(0, (first.dueNs() - clock.nanoTime() + 999_999) / 1_000_000);
                    if (!tasks.isEmpty() || waitMs == 0) {
                        selector.selectNow();
                    } else {
                        selector.select(waitMs);
                    }
                    runTasks();
                    long now = clock.nanoTime();
                    for (SelectionKey k : selector.selectedKeys()) {
                        if (k.isValid()) {
                            ((Channels.Ready) k.attachment()).onReady(k, now);
                        }
                    }
                    selector.selectedKeys().clear();
                    while ((first = timers.peek()) != null && first.dueNs() <= now) {
                        timers.poll().task().run();
                    }
                }
                runTasks(); // what was given before close: closing the server and the connections
            } catch (IOException | RuntimeException e) {
                LOG.error("the HTTP MTP's thread stopped: {}", e.toString(), e);
            } finally {
                for (SelectionKey k : selector.keys()) {
                    try {
                        k.channel().close();
                    } catch (IOException ignored) {
                        // closing anyway
                    }
                }
                try {
                    selector.close();
                } catch (IOException ignored) {
                    // closing anyway
                }
            }
        }

        private void runTasks() {
            Runnable t;
            while ((t = tasks.poll()) != null) {
                t.run();
            }
        }
    }
}
