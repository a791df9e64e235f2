package jade.core;

import io.concord.core.acl.AclMessage;
import io.concord.jadecompat.internal.Convert;
import io.concord.jadecompat.internal.DfLink;
import io.concord.jadecompat.internal.Engine;
import io.concord.jadecompat.internal.Host;
import jade.core.behaviours.Behaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.wrapper.AgentContainer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.Iterator;
import java.util.LinkedList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * JADE's agent, over Concord. Each agent has a thread of its own (virtual on Java 21 and later),
 * on which {@link #setup()}, its behaviours (one {@code action()} at a time, round robin) and
 * {@link #takeDown()} run, as in JADE: it may block ({@link #blockingReceive}, {@link #doWait},
 * {@code Thread.sleep}) without holding up any other agent. Underneath, a Concord agent of the
 * same name holds its port and stack on Concord's loop and hands it the messages it receives.
 */
public class Agent implements Runnable, jade.util.leap.Serializable {
    private static final long serialVersionUID = 1L;
    private static final Logger LOG = LoggerFactory.getLogger(Agent.class);

    public static final int AP_MIN = 0;
    public static final int AP_INITIATED = 1;
    public static final int AP_ACTIVE = 2;
    public static final int AP_IDLE = 3;
    public static final int AP_SUSPENDED = 4;
    public static final int AP_WAITING = 5;
    public static final int AP_DELETED = 6;
    public static final int AP_MAX = 13;
    public static final int D_MIN = 9;
    public static final int D_ACTIVE = 10;
    public static final int D_SUSPENDED = 20;
    public static final int D_RETIRED = 30;
    public static final int D_UNKNOWN = 40;
    public static final int D_MAX = 41;
    public static final String MSG_QUEUE_CLASS = "jade_core_Agent_msgQueueClass";

    /**
     * Guards the queue, the behaviours, the timers and the wake-up count: a lock, not a monitor, so
     * that a virtual thread waiting on it does not hold on to its carrier thread.
     */
    private final transient ReentrantLock lock = new ReentrantLock();
    private final transient Condition changed = lock.newCondition();
    private final transient ArrayDeque<ACLMessage> queue = new ArrayDeque<>();
    private final transient List<Behaviour> behaviours = new ArrayList<>();
    private final transient Map<Behaviour, Long> timers = new IdentityHashMap<>();
    private final transient CountDownLatch started = new CountDownLatch(1);
    private final transient CountDownLatch ended = new CountDownLatch(1);
    private transient long wakeups;
    private transient jade.content.ContentManager contentManager;
    private transient boolean restartAll;
    private transient int next;
    private transient int queueSize;
    private volatile int state = AP_INITIATED;
    private volatile boolean deleteRequested;

    private transient LinkedList<Object> o2aQueue;
    private transient int o2aMax;

    private AID aid;
    private Object[] arguments;
    private transient Host host;
    /** This agent's DF subscriptions, translated between JADE's SL and Concord's DF. */
    private final transient DfLink dfLink = new DfLink();
    private transient Engine engine;
    private transient AgentContainer container;
    private transient Thread thread;

    static {
        io.concord.jadecompat.internal.AgentAccess.install(new io.concord.jadecompat.internal.AgentAccess() {
            @Override
            public void start(Agent a, Engine e, AgentContainer c, String localName) {
                a.startOn(e, c, localName);
            }

            @Override
            public void awaitEnd(Agent a, long timeoutMs) throws InterruptedException {
                a.awaitEnd(timeoutMs);
            }

            @Override
            public Host host(Agent a) {
                return a.host;
            }

            @Override
            public Engine engine(Agent a) {
                return a.engine;
            }

            @Override
            public boolean onOwnThread(Agent a) {
                return Thread.currentThread() == a.thread;
            }

            @Override
            public boolean ending(Agent a) {
                return a.deleteRequested || a.state == AP_DELETED;
            }
        });
    }

    public Agent() {
    }

    // ---- life cycle --------------------------------------------------------------------------

    /** The agent's content manager (one per agent, created on first use), as in JADE. */
    public jade.content.ContentManager getContentManager() {
        lock.lock();
        try {
            if (contentManager == null) {
                contentManager = new jade.content.ContentManager();
            }
            return contentManager;
        } finally {
            lock.unlock();
        }
    }

    /** Adds behaviours and whatever else the agent needs; runs on the agent's thread. */
    protected void setup() {
        // JADE documents an empty default: an agent that overrides nothing does nothing.
    }

    /** Cleans up (deregister from the DF, ...); runs on the agent's thread after {@link #doDelete()}. */
    protected void takeDown() {
        // JADE documents an empty default.
    }

    /** Called before the agent moves; agents do not move here (no mobility), so it is never called. */
    protected void beforeMove() {
        // A documented no-op in JADE, and never reached here: concord-jade has no agent mobility.
    }

    /** Called before the agent moves; agents do not move here (no mobility), so it is never called. */
    protected void afterMove() {
        // A documented no-op in JADE, and never reached here: concord-jade has no agent mobility.
    }

    /** Called before the agent moves; agents do not move here (no cloning), so it is never called. */
    protected void beforeClone() {
        // A documented no-op in JADE, and never reached here: concord-jade has no agent cloning.
    }

    /** Called before the agent moves; agents do not move here (no cloning), so it is never called. */
    protected void afterClone() {
        // A documented no-op in JADE, and never reached here: concord-jade has no agent cloning.
    }

    /**
     * Starts the agent on an engine (for {@code jade.wrapper}): its Concord agent binds its port
     * and joins the platform, then its thread runs {@link #setup()} and its behaviours. Returns once
     * the agent is reachable and its thread runs.
     */
    final void startOn(Engine e, AgentContainer c, String localName) {
        this.engine = e;
        this.container = c;
        this.host = new Host(this::deliver);
        io.concord.core.acl.AID concordAid = e.startHost(localName, host, arguments);
        this.aid = new AID(io.concord.jadecompat.internal.Names.decode(concordAid.name()), AID.ISGUID);
        e.jadeAgent(localName, this);
        this.thread = Engine.newAgentThread(localName, this);
        thread.start();
        try {
            started.await();
        } catch (InterruptedException ex) {
            Thread.currentThread().interrupt();
        }
    }

    /** The agent's thread body: setup, the behaviours until {@link #doDelete()}, takeDown. */
    @Override
    public final void run() {
        Thread.currentThread().setContextClassLoader(getClass().getClassLoader());
        state = AP_ACTIVE;
        started.countDown();
        try {
            setup();
        } catch (RuntimeException | Error ex) {
            LOG.error("setup() of {} threw; the agent is deleted", getName(), ex);
            deleteRequested = true;
        }
        try {
            schedule();
            try {
                takeDown();
            } catch (RuntimeException ex) {
                LOG.error("takeDown() of {} threw", getName(), ex);
            }
        } finally {
            state = AP_DELETED;
            engine.jadeAgent(getLocalName(), null);
            io.concord.jadecompat.internal.Topics.ended(getLocalName());
            host.doDelete();
            ended.countDown();
        }
    }

    /** JADE's scheduler: one action of each runnable behaviour in turn; idle waits for a message, a restart or a timer. */
    private void schedule() {
        while (!deleteRequested) {
            long seen;
            boolean restart;
            List<Behaviour> due = new ArrayList<>();
            lock.lock();
            try {
                seen = wakeups;
                restart = restartAll;
                restartAll = false;
                long now = Engine.nowNs();
                for (Iterator<Map.Entry<Behaviour, Long>> it = timers.entrySet().iterator(); it.hasNext(); ) {
                    Map.Entry<Behaviour, Long> t = it.next();
                    if (t.getValue() <= now) {
                        due.add(t.getKey());
                        it.remove();
                    }
                }
            } finally {
                lock.unlock();
            }
            if (restart) {
                for (Behaviour b : snapshot()) {
                    b.handleRestartEvent();
                }
            }
            for (Behaviour b : due) {
                b.restart();
            }
            Behaviour b = nextRunnable();
            if (b == null) {
                idle(seen);
                continue;
            }
            try {
                b.actionWrapper();
                if (b.done()) {
                    b.onEnd();
                    removeBehaviour(b);
                }
            } catch (RuntimeException | Error ex) {
                // As in JADE: an exception no behaviour caught ends the agent (takeDown still runs).
                LOG.error("behaviour {} of {} threw; the agent is deleted, as JADE does", b.getBehaviourName(), getName(), ex);
                removeBehaviour(b);
                deleteRequested = true;
            }
        }
    }

    private List<Behaviour> snapshot() {
        lock.lock();
        try {
            return new ArrayList<>(behaviours);
        } finally {
            lock.unlock();
        }
    }

    private Behaviour nextRunnable() {
        lock.lock();
        try {
            int n = behaviours.size();
            for (int i = 0; i < n; i++) {
                int j = (next + i) % n;
                Behaviour b = behaviours.get(j);
                if (b.isRunnable()) {
                    next = (j + 1) % Math.max(1, n);
                    return b;
                }
            }
            return null;
        } finally {
            lock.unlock();
        }
    }

    /** Waits until something happened since {@code seen}, or the next timer is due. */
    private void idle(long seen) {
        lock.lock();
        try {
            while (wakeups == seen && !deleteRequested) {
                long wait = 0;
                if (!timers.isEmpty()) {
                    long first = Long.MAX_VALUE;
                    for (long t : timers.values()) {
                        first = Math.min(first, t);
                    }
                    long leftNs = first - Engine.nowNs();
                    if (leftNs <= 0) {
                        return;
                    }
                    wait = Math.max(1, (leftNs + 999_999) / 1_000_000);
                }
                try {
                    awaitMs(wait);
                } catch (InterruptedException ex) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
        } finally {
            lock.unlock();
        }
    }

    /** Waits on the agent's condition for up to {@code ms} milliseconds (0 or less: until signalled). Lock held. */
    private void awaitMs(long ms) throws InterruptedException {
        if (ms <= 0) {
            changed.await();
        } else {
            changed.await(ms, java.util.concurrent.TimeUnit.MILLISECONDS);
        }
    }

    private void wake() {
        lock.lock();
        try {
            wakeups++;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** A message arrived (on Concord's loop): queue it, restart every behaviour, wake the thread. */
    private void deliver(AclMessage m) {
        ACLMessage j = dfLink.incoming(Convert.toJade(m), getDefaultDF());
        j.setPostTimeStamp();
        lock.lock();
        try {
            if (queueSize > 0 && queue.size() >= queueSize) {
                queue.poll();
            }
            queue.add(j);
            restartAll = true;
            wakeups++;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** Deletes the agent: its behaviours stop, {@link #takeDown()} runs, it leaves the platform. */
    public void doDelete() {
        deleteRequested = true;
        wake();
    }

    /** Waits until the agent has ended (for {@code jade.wrapper}). */
    final void awaitEnd(long timeoutMs) throws InterruptedException {
        ended.await(timeoutMs, java.util.concurrent.TimeUnit.MILLISECONDS);
    }

    /** Blocks the agent's thread until {@link #doWake()} or a message arrives. */
    public void doWait() {
        doWait(0);
    }

    /** Blocks the agent's thread until {@link #doWake()}, a message, or {@code millis} pass (0: no limit). */
    public void doWait(long millis) {
        long deadline = millis > 0 ? Engine.nowNs() + millis * 1_000_000L : Long.MAX_VALUE;
        lock.lock();
        try {
            long seen = wakeups;
            state = AP_WAITING;
            try {
                while (wakeups == seen && !deleteRequested) {
                    long left = deadline - Engine.nowNs();
                    if (deadline != Long.MAX_VALUE && left <= 0) {
                        break;
                    }
                    awaitMs(deadline == Long.MAX_VALUE ? 0 : Math.max(1, left / 1_000_000));
                }
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
            } finally {
                if (state == AP_WAITING) {
                    state = AP_ACTIVE;
                }
            }
        } finally {
            lock.unlock();
        }
    }

    /** Wakes the agent from {@link #doWait()}. */
    public void doWake() {
        wake();
    }

    /** Suspension is not supported by concord-jade. */
    public void doSuspend() {
        throw new UnsupportedOperationException("doSuspend is not supported by concord-jade yet");
    }

    /** Suspension is not supported by concord-jade. */
    public void doActivate() {
        throw new UnsupportedOperationException("doActivate is not supported by concord-jade yet");
    }

    /** Mobility is not supported by concord-jade. */
    public void doMove(Location destination) {
        throw new UnsupportedOperationException("agent mobility is not supported by concord-jade");
    }

    /** Cloning is not supported by concord-jade. */
    public void doClone(Location destination, String newName) {
        throw new UnsupportedOperationException("agent cloning is not supported by concord-jade");
    }

    /** The agent's life-cycle state ({@link #AP_ACTIVE}, {@link #AP_WAITING}, ...). */
    public int getState() {
        return state;
    }

    /** The agent's life-cycle state as an object (its name: {@code Active}, {@code Waiting}, ...). */
    public AgentState getAgentState() {
        return AgentState.getInstance(state);
    }

    /**
     * The helper of a platform service: {@code jade.core.messaging.TopicManagement} (topics) is
     * supported; any other service throws a {@link ServiceException} saying so.
     */
    public ServiceHelper getHelper(String serviceName) throws ServiceException {
        if (jade.core.messaging.TopicManagementHelper.SERVICE_NAME.equals(serviceName)) {
            ServiceHelper h = new io.concord.jadecompat.internal.Topics();
            h.init(this);
            return h;
        }
        throw new ServiceException("the service " + serviceName + " is not supported by concord-jade (topics are: "
                + jade.core.messaging.TopicManagementHelper.SERVICE_NAME + ")");
    }

    // ---- identity ----------------------------------------------------------------------------

    public final AID getAID() {
        return aid;
    }

    /** An AID for another agent of this platform, by local name. */
    public final AID getAID(String localName) {
        return new AID(localName, AID.ISLOCALNAME);
    }

    public final String getLocalName() {
        return aid == null ? null : aid.getLocalName();
    }

    public final String getName() {
        return aid == null ? null : aid.getName();
    }

    /** The platform's name. */
    public final String getHap() {
        return aid == null ? null : aid.getHap();
    }

    /** The AMS of this platform. */
    public final AID getAMS() {
        return new AID("ams", AID.ISLOCALNAME);
    }

    /** The DF of this platform. */
    public AID getDefaultDF() {
        return new AID("df", AID.ISLOCALNAME);
    }

    /** Where the agent lives: its container. */
    public Location here() {
        try {
            return container == null ? null : new ContainerID(container.getContainerName(), null);
        } catch (jade.wrapper.ControllerException e) {
            throw new IllegalStateException(e);
        }
    }

    public final void setArguments(Object[] args) {
        this.arguments = args == null ? null : args.clone();
    }

    /** The arguments given when the agent was created, or null. */
    public Object[] getArguments() {
        return arguments;
    }

    /** The container this agent was created in. */
    public AgentContainer getContainerController() {
        return container;
    }

    // ---- behaviours --------------------------------------------------------------------------

    /** Schedules a behaviour (from any thread). */
    public void addBehaviour(Behaviour b) {
        b.setAgent(this);
        lock.lock();
        try {
            behaviours.add(b);
        } finally {
            lock.unlock();
        }
        b.restart();
    }

    /** Takes a behaviour out of the schedule. */
    public void removeBehaviour(Behaviour b) {
        lock.lock();
        try {
            int i = indexOf(b);
            if (i >= 0) {
                behaviours.remove(i);
                if (next > i) {
                    next--;
                }
            }
            timers.remove(b);
        } finally {
            lock.unlock();
        }
    }

    private int indexOf(Behaviour b) {
        for (int i = 0; i < behaviours.size(); i++) {
            if (behaviours.get(i) == b) {
                return i;
            }
        }
        return -1;
    }

    /** Restarts a blocked behaviour after {@code millis} (what {@code Behaviour.block(millis)} asks for). */
    public void restartLater(Behaviour b, long millis) {
        lock.lock();
        try {
            timers.put(b, Engine.nowNs() + millis * 1_000_000L);
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** Forgets a behaviour's pending timed restart. */
    public void removeTimer(Behaviour b) {
        lock.lock();
        try {
            timers.remove(b);
        } finally {
            lock.unlock();
        }
    }

    /** A behaviour was restarted: the scheduler looks again. */
    public void notifyRestarted(Behaviour b) {
        wake();
    }

    // ---- messages ----------------------------------------------------------------------------

    /** Sends a message; the sender is set to this agent if it is not set. */
    public final void send(ACLMessage msg) {
        ACLMessage m = msg;
        if (m.getSender() == null) {
            m = (ACLMessage) msg.clone();
            m.setSender(aid);
        }
        if (io.concord.jadecompat.internal.Ams.handles(m)) {
            io.concord.jadecompat.internal.Ams.serve(this, engine, m);
            return;
        }
        java.util.List<AID> notTopics = io.concord.jadecompat.internal.Topics.deliver(engine, m);
        if (notTopics != null) {
            if (notTopics.isEmpty()) {
                return;
            }
            m = (ACLMessage) m.clone();
            m.clearAllReceiver();
            for (AID r : notTopics) {
                m.addReceiver(r);
            }
        }
        host.send(Convert.toConcord(dfLink.outgoing(m, getDefaultDF())));
    }

    /** The first message in the queue, or null. Never blocks. */
    public final ACLMessage receive() {
        lock.lock();
        try {
            return queue.poll();
        } finally {
            lock.unlock();
        }
    }

    /** The first message the template matches, or null. Never blocks. */
    public final ACLMessage receive(MessageTemplate pattern) {
        lock.lock();
        try {
            return take(pattern);
        } finally {
            lock.unlock();
        }
    }

    private ACLMessage take(MessageTemplate pattern) {
        for (Iterator<ACLMessage> it = queue.iterator(); it.hasNext(); ) {
            ACLMessage m = it.next();
            if (pattern == null || pattern.match(m)) {
                it.remove();
                return m;
            }
        }
        return null;
    }

    /** Waits for a message; blocks this agent's thread only. */
    public final ACLMessage blockingReceive() {
        return blockingReceive(null, 0);
    }

    /** Waits for a message for at most {@code millis} (0: no limit); null on timeout. */
    public final ACLMessage blockingReceive(long millis) {
        return blockingReceive(null, millis);
    }

    /** Waits for a message the template matches. */
    public final ACLMessage blockingReceive(MessageTemplate pattern) {
        return blockingReceive(pattern, 0);
    }

    /** Waits for a message the template matches, for at most {@code millis} (0: no limit); null on timeout. */
    public final ACLMessage blockingReceive(MessageTemplate pattern, long millis) {
        long deadline = millis > 0 ? Engine.nowNs() + millis * 1_000_000L : Long.MAX_VALUE;
        lock.lock();
        try {
            while (true) {
                ACLMessage m = take(pattern);
                if (m != null) {
                    return m;
                }
                if (deleteRequested) {
                    return null;
                }
                long left = deadline - Engine.nowNs();
                if (deadline != Long.MAX_VALUE && left <= 0) {
                    return null;
                }
                try {
                    awaitMs(deadline == Long.MAX_VALUE ? 0 : Math.max(1, left / 1_000_000));
                } catch (InterruptedException ex) {
                    Thread.currentThread().interrupt();
                    return null;
                }
            }
        } finally {
            lock.unlock();
        }
    }

    /** Puts a message back at the head of the queue. */
    public final void putBack(ACLMessage msg) {
        lock.lock();
        try {
            queue.addFirst(msg);
            restartAll = true;
            wakeups++;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** Hands a message to this agent as if it had arrived. */
    public final void postMessage(ACLMessage msg) {
        lock.lock();
        try {
            queue.add(msg);
            restartAll = true;
            wakeups++;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** Messages waiting. */
    public int getCurQueueSize() {
        lock.lock();
        try {
            return queue.size();
        } finally {
            lock.unlock();
        }
    }

    /** The queue's limit (0: none); when full, the oldest message is dropped, as in JADE. */
    public void setQueueSize(int newSize) {
        if (newSize < 0) {
            throw new IllegalArgumentException("Invalid MsgQueue size");
        }
        lock.lock();
        try {
            queueSize = newSize;
        } finally {
            lock.unlock();
        }
    }

    public int getQueueSize() {
        lock.lock();
        try {
            return queueSize;
        } finally {
            lock.unlock();
        }
    }

    // ---- O2A ---------------------------------------------------------------------------------

    /** Lets other threads hand objects to this agent ({@link #putO2AObject}); {@code queueSize} 0 means no limit. */
    public void setEnabledO2ACommunication(boolean enabled, int queueSize) {
        lock.lock();
        try {
            if (enabled) {
                if (o2aQueue == null) {
                    o2aQueue = new LinkedList<>();
                }
                o2aMax = queueSize;
            } else {
                o2aQueue = null;
            }
        } finally {
            lock.unlock();
        }
    }

    /**
     * Hands an object to this agent from another thread; every behaviour is restarted, as for a
     * message. Ignored if O2A is not enabled (as JADE does); with {@code blocking}, waits until the
     * agent has taken it.
     */
    public void putO2AObject(Object o, boolean blocking) throws InterruptedException {
        lock.lock();
        try {
            if (o2aQueue == null) {
                LOG.warn("{}: O2A object dropped, O2A communication is not enabled", getName());
                return;
            }
            if (o2aMax > 0 && o2aQueue.size() >= o2aMax) {
                o2aQueue.removeFirst();
            }
            o2aQueue.add(o);
            restartAll = true;
            wakeups++;
            changed.signalAll();
            if (blocking) {
                while (o2aQueue != null && o2aQueue.contains(o) && !deleteRequested) {
                    changed.await();
                }
            }
        } finally {
            lock.unlock();
        }
    }

    /** The first object handed to this agent by another thread, or null. */
    public Object getO2AObject() {
        lock.lock();
        try {
            if (o2aQueue == null || o2aQueue.isEmpty()) {
                return null;
            }
            Object o = o2aQueue.removeFirst();
            changed.signalAll();
            return o;
        } finally {
            lock.unlock();
        }
    }

    /** The thread body is {@link #run()}; JADE's {@code join} waits for it to end. */
    public void join() {
        try {
            ended.await();
        } catch (InterruptedException ex) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public String toString() {
        return getName() == null ? getClass().getSimpleName() : getName();
    }
}
