package jade.core.behaviours;

import io.concord.jadecompat.internal.Engine;
import jade.core.Agent;
import jade.core.NotFoundException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.ArrayList;
import java.util.List;

/**
 * JADE's way to give a behaviour a thread of its own, for work that blocks (I/O, long
 * computations, {@code Thread.sleep}): {@link #wrap} returns a behaviour to add to the agent in its
 * place. The wrapped behaviour's actions run on that thread, one after the other, until it is
 * done; its {@code block()} parks the thread until a message arrives for the agent, it is
 * restarted, or its timeout passes. The agent's other behaviours go on meanwhile. Its thread is a
 * virtual thread on Java 21 and later, as the agents' are (Concord's own agents have
 * {@code io.concord.core.agent.ThreadedBehaviourFactory} for the same).
 */
public class ThreadedBehaviourFactory {
    private static final Logger LOG = LoggerFactory.getLogger(ThreadedBehaviourFactory.class);
    /** How often a parked thread looks whether its agent has ended. */
    private static final long LIVENESS_MS = 200;

    private final List<ThreadedBehaviourWrapper> wrappers = new ArrayList<>();

    public ThreadedBehaviourFactory() {
    }

    /** A behaviour that runs {@code b} on a thread of its own once added to an agent. */
    public Behaviour wrap(Behaviour b) {
        ThreadedBehaviourWrapper w = new ThreadedBehaviourWrapper(b);
        synchronized (this) {
            wrappers.add(w);
        }
        return w;
    }

    /** How many wrapped behaviours have not ended yet. */
    public synchronized int size() {
        return wrappers.size();
    }

    /** Stops every wrapped behaviour's thread (interrupting it). */
    public void interrupt() {
        for (ThreadedBehaviourWrapper w : getWrappers()) {
            w.stop();
        }
    }

    /** Waits until every wrapped behaviour has ended, at most {@code timeout} ms (0: for ever); true if they have. */
    public synchronized boolean waitUntilEmpty(long timeout) {
        long deadline = Engine.nowMs() + timeout;
        while (!wrappers.isEmpty()) {
            long left = timeout <= 0 ? 0 : deadline - Engine.nowMs();
            if (timeout > 0 && left <= 0) {
                return false;
            }
            try {
                wait(left);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return wrappers.isEmpty();
            }
        }
        return true;
    }

    /** Stops the thread of this wrapped behaviour (or of its wrapper) and returns it. */
    public Thread interrupt(Behaviour b) throws NotFoundException {
        ThreadedBehaviourWrapper w = find(b);
        if (w == null) {
            throw new NotFoundException("no threaded behaviour " + b.getBehaviourName());
        }
        w.stop();
        return w.thread;
    }

    /** Holds this wrapped behaviour's thread before its next action, until {@link #resume}. */
    public void suspend(Behaviour b) {
        ThreadedBehaviourWrapper w = find(b);
        if (w != null) {
            w.suspended = true;
        }
    }

    /** Lets a suspended wrapped behaviour go on. */
    public void resume(Behaviour b) {
        ThreadedBehaviourWrapper w = find(b);
        if (w != null) {
            w.suspended = false;
            w.signal();
        }
    }

    /** The thread of this wrapped behaviour (or of its wrapper), or null if it has none (yet, or any more). */
    public Thread getThread(Behaviour b) {
        ThreadedBehaviourWrapper w = find(b);
        return w == null ? null : w.thread;
    }

    /** The wrappers whose behaviours have not ended. */
    public synchronized ThreadedBehaviourWrapper[] getWrappers() {
        return wrappers.toArray(new ThreadedBehaviourWrapper[0]);
    }

    private synchronized ThreadedBehaviourWrapper find(Behaviour b) {
        for (ThreadedBehaviourWrapper w : wrappers) {
            if (w == b || w.inner == b) {
                return w;
            }
        }
        return null;
    }

    private synchronized void ended(ThreadedBehaviourWrapper w) {
        wrappers.remove(w);
        notifyAll();
    }

    /** The behaviour the agent schedules in place of a wrapped one: it starts the thread and waits for it to end. */
    public class ThreadedBehaviourWrapper extends Behaviour {
        private static final long serialVersionUID = 1L;
        private final Behaviour inner;
        private final Object monitor = new Object();
        private volatile Thread thread;
        private volatile boolean innerDone;
        private volatile boolean stopped;
        private volatile boolean suspended;
        private long signals;
        private int exitValue;

        ThreadedBehaviourWrapper(Behaviour inner) {
            super(inner.myAgent);
            this.inner = inner;
        }

        /** The wrapped behaviour. */
        public Behaviour getBehaviour() {
            return inner;
        }

        /** Its thread, or null before it started. */
        public Thread getThread() {
            return thread;
        }

        @Override
        public void action() {
            if (thread == null) {
                inner.setAgent(myAgent);
                inner.wakeUp = this::signal;
                thread = Engine.newAgentThread(myAgent.getLocalName() + "-threaded-" + inner.getBehaviourName(), this::run);
                thread.start();
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

        /** A message for the agent: the wrapped behaviour's thread looks again. */
        @Override
        public void handleRestartEvent() {
            inner.handleRestartEvent();
            signal();
        }

        void signal() {
            synchronized (monitor) {
                signals++;
                monitor.notifyAll();
            }
        }

        void stop() {
            stopped = true;
            Thread t = thread;
            if (t != null) {
                t.interrupt();
            }
            signal();
        }

        private void run() {
            try {
                while (!stopped && myAgent.getState() != Agent.AP_DELETED) {
                    if (suspended) {
                        park();
                        continue;
                    }
                    inner.actionWrapper();
                    if (inner.done()) {
                        exitValue = inner.onEnd();
                        break;
                    }
                    while (!inner.isRunnable() && !stopped && myAgent.getState() != Agent.AP_DELETED) {
                        park();
                    }
                }
            } catch (InterruptedException e) {
                // interrupt(): the behaviour ends where it is, as in JADE
            } catch (RuntimeException | Error e) {
                if (!stopped) {
                    LOG.error("threaded behaviour {} of {} threw", inner.getBehaviourName(), myAgent.getName(), e);
                }
            } finally {
                innerDone = true;
                ended(this);
                restart();
            }
        }

        private void park() throws InterruptedException {
            synchronized (monitor) {
                long seen = signals;
                while (signals == seen && !stopped && !(inner.isRunnable() && !suspended)) {
                    monitor.wait(LIVENESS_MS);
                    if (myAgent.getState() == Agent.AP_DELETED) {
                        return;
                    }
                }
            }
        }
    }
}
