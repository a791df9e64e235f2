package io.concord.core.agent;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.concurrent.TimeUnit;

/**
 * Gives a behaviour a thread of its own, for work that blocks: I/O, long computations,
 * {@link Agent#blockingReceive}. The wrapped behaviour's steps run on that thread; its
 * {@code block()} parks the thread until a message arrives for the agent, its timeout passes or it
 * is restarted. When it is done, the wrapper ends on the agent's loop.
 *
 * <p>Messages sent from the thread are handed to the loop, so that each agent's stack stays
 * single-threaded. Use sparingly: a thread hand-off costs far more than a message.
 */
public final class ThreadedBehaviourFactory {
    private static final Logger LOG = LoggerFactory.getLogger(ThreadedBehaviourFactory.class);

    /** Wraps a behaviour so that it runs on its own thread once added to an agent. */
    public Behaviour wrap(Behaviour b) {
        return new Wrapper(b);
    }

    /** The scheduling half that runs on the loop: starts the thread, waits for it to end. */
    private static final class Wrapper extends Behaviour {
        private final Behaviour inner;
        private Runner runner;
        private volatile boolean innerDone;
        private int exitValue;

        Wrapper(Behaviour inner) {
            this.inner = inner;
        }

        @Override
        public void action() {
            if (runner == null) {
                inner.attach(myAgent);
                runner = new Runner(this);
                inner.runner = runner;
                Thread t = new Thread(runner, "concord-threaded-" + myAgent.getLocalName() + "-"
                        + inner.getClass().getSimpleName());
                t.setDaemon(true);
                runner.thread = t;
                myAgent.threadedStarted(runner);
                t.start();
            }
            if (!innerDone) {
                block();
            }
        }

        @Override
        public boolean done() {
            return innerDone;
        }

        @Override
        public int onEnd() {
            return exitValue;
        }

        @Override
        void restartOnMessage() {
            // Messages wake the thread, not the wrapper.
            if (runner != null) {
                runner.signal();
            } else {
                super.restartOnMessage();
            }
        }
    }

    /** The thread of a wrapped behaviour. */
    static final class Runner implements Runnable {
        private final Wrapper wrapper;
        private final Object lock = new Object();
        private Thread thread;
        private long signals;
        private long wakeDeadlineNs = Long.MAX_VALUE;
        private volatile boolean stopRequested;

        Runner(Wrapper wrapper) {
            this.wrapper = wrapper;
        }

        void wakeAfterMs(long ms) {
            synchronized (lock) {
                wakeDeadlineNs = wrapper.myAgent.runtime().clock().nanoTime() + TimeUnit.MILLISECONDS.toNanos(Math.max(0, ms));
            }
        }

        void signal() {
            synchronized (lock) {
                signals++;
                lock.notifyAll();
            }
        }

        void stop() {
            stopRequested = true;
            signal();
        }

        boolean isRunnerThread() {
            return Thread.currentThread() == thread;
        }

        @Override
        public void run() {
            Behaviour b = wrapper.inner;
            Agent agent = wrapper.myAgent;
            try {
                // Step first, then ask done(): a one-shot behaviour is "done" before it has run.
                while (!stopRequested) {
                    long seen;
                    synchronized (lock) {
                        seen = signals;
                        wakeDeadlineNs = Long.MAX_VALUE;
                    }
                    b.step();
                    if (b.done()) {
                        break;
                    }
                    if (b.isRunnable()) {
                        continue;
                    }
                    synchronized (lock) {
                        while (signals == seen && !stopRequested) {
                            long left = wakeDeadlineNs - agent.runtime().clock().nanoTime();
                            if (wakeDeadlineNs != Long.MAX_VALUE && left <= 0) {
                                break;
                            }
                            lock.wait(wakeDeadlineNs == Long.MAX_VALUE ? 0 : Math.max(1, left / 1_000_000L));
                        }
                    }
                    b.markRunnable();
                }
                if (!stopRequested) {
                    wrapper.exitValue = b.onEnd();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } catch (RuntimeException e) {
                LOG.error("threaded behaviour {} of {} failed", b.getClass().getName(), agent.getLocalName(), e);
            } finally {
                wrapper.innerDone = true;
                agent.threadedEnded(this);
                agent.runtime().execute(wrapper::restart);
            }
        }
    }
}
