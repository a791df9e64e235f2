package io.concord.jadecompat.internal;

import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
import io.concord.core.agent.PortRange;
import io.concord.core.time.Clock;
import io.concord.layers.Platform;
import io.concord.layers.PlatformServices;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.lang.reflect.Method;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Function;

/**
 * The Concord platform under JADE's API in this JVM: one {@link Platform} (no main container;
 * the agents elect their container), started by the first {@code createMainContainer} or
 * {@code createAgentContainer}, and the threads JADE agents run on.
 */
public final class Engine {
    private static final Logger LOG = LoggerFactory.getLogger(Engine.class);
    /** How long a synchronous DF call waits for the DF's answer. */
    public static final long DF_TIMEOUT_MS = 30_000;
    /** JADE classes that concord-jade does not have: if one loads, JADE's own jar is on the class path. */
    static final String[] JADE_ONLY_CLASSES = {"jade.core.AgentContainerImpl", "jade.core.MainContainerImpl",
            "jade.core.BaseService"};
    /** Where JADE's {@code -gui} (Profile.GUI) opens Concord's console: any free port of loopback (it prints its address; a fixed one may be taken). */
    public static final String CONSOLE_ADDRESS = "127.0.0.1:0";

    private static final Clock CLOCK = Clock.system();
    private static Engine current;

    private final Platform platform;
    /** The containers of this JVM by name, in the order made (for the AMS: create-agent, query, shutdown). */
    private final java.util.Map<String, jade.wrapper.ContainerController> containers = new java.util.concurrent.ConcurrentSkipListMap<>();
    /** The JADE agents of this JVM by local name (for the AMS: their states, kill). */
    private final java.util.Map<String, jade.core.Agent> jadeAgents = new java.util.concurrent.ConcurrentHashMap<>();
    /** The local names of JADE agents of this JVM that have ended (until one of that name starts again). */
    private final java.util.Set<String> ended = java.util.concurrent.ConcurrentHashMap.newKeySet();

    private Engine(Platform platform) {
        this.platform = platform;
    }

    /**
     * The engine of this JVM, started on first use with this platform name, host and first port.
     * Later calls return the same engine (JADE's containers of one JVM share one platform here).
     */
    public static synchronized Engine start(String platformName, String host, int firstPort) {
        return start(platformName, host, firstPort, false);
    }

    /**
     * As {@link #start(String, String, int)}; with {@code gui}, Concord's web console opens on
     * {@link #CONSOLE_ADDRESS} if {@code concord-console} is on the class path (else a line says it is not).
     */
    public static synchronized Engine start(String platformName, String host, int firstPort, boolean gui) {
        if (current != null) {
            return current;
        }
        String jadeToo = jadeOnTheClassPath();
        if (jadeToo != null) {
            LOG.warn("JADE's own jar is on the class path too ({} loads): concord-jade replaces jade.jar and must not "
                    + "be used with it; remove jade.jar from the class path", jadeToo);
        }
        PortRange ports = firstPort > 0 ? new PortRange(firstPort, PortRange.DEFAULT_COUNT, PortRange.DEFAULT_WINDOW)
                : PortRange.defaults();
        // The user's platform key (Concord's zero-configuration default), so that containers of other
        // JVMs of this user that name the same platform and ports join it, as JADE's peripheral containers do.
        Platform.Builder b = Platform.builder().name(platformName).host(host).ports(ports).network(null);
        if (gui) {
            if (consoleAvailable()) {
                b.console(CONSOLE_ADDRESS).consoleOut(System.out);
            } else {
                System.out.println("concord-jade: -gui: Concord's console is not on the class path (add io.concord:concord-console "
                        + "to open it); going on without it");
            }
        }
        Platform p = b.build();
        LOG.info("concord-jade: JADE's API over Concord, platform {} on {} ports {}-{}, agents on {} threads",
                platformName, host, ports.base(), ports.base() + ports.count() - 1, virtualThreads() ? "virtual" : "platform");
        current = new Engine(p);
        return current;
    }

    /** True if Concord's web console (concord-console) is on the class path. */
    public static boolean consoleAvailable() {
        return java.util.ServiceLoader.load(io.concord.layers.ConsoleProvider.class).findFirst().isPresent();
    }

    /** The running engine, or null. */
    public static synchronized Engine current() {
        return current;
    }

    /** Stops the platform. */
    public static synchronized void shutDown() {
        if (current != null) {
            current.platform.close();
            current = null;
        }
    }

    /** The name of a JADE-only class that loads, or null if JADE's jar is not on the class path. */
    public static String jadeOnTheClassPath() {
        for (String c : JADE_ONLY_CLASSES) {
            try {
                Class.forName(c, false, Engine.class.getClassLoader());
                return c;
            } catch (ClassNotFoundException | LinkageError e) {
                // not there: as it should be
            }
        }
        return null;
    }

    /** A container of this JVM was made. */
    public void addContainer(String name, jade.wrapper.ContainerController c) {
        containers.put(name, c);
    }

    /** The container of this name, or null. */
    public jade.wrapper.ContainerController container(String name) {
        return containers.get(name);
    }

    /** Every container of this JVM. */
    public java.util.List<jade.wrapper.ContainerController> containers() {
        return new java.util.ArrayList<>(containers.values());
    }

    /** A JADE agent started (or, with {@code null}, ended) here. */
    public void jadeAgent(String localName, jade.core.Agent a) {
        if (a == null) {
            jadeAgents.remove(localName);
            ended.add(localName);
        } else {
            ended.remove(localName);
            jadeAgents.put(localName, a);
        }
    }

    /**
     * The local names of the platform's agents (those running here), in start order, without the
     * JADE agents of this JVM that were asked to end or have ended (Concord's runtime may list
     * them a little longer; JADE's AMS does not).
     */
    public java.util.List<String> liveAgentNames() {
        java.util.List<String> l = new java.util.ArrayList<>();
        for (String n : agentNames()) {
            jade.core.Agent a = jadeAgents.get(n);
            if (!ended.contains(n) && (a == null || !AgentAccess.get().ending(a))) {
                l.add(n);
            }
        }
        return l;
    }

    /** The JADE agent of this local name running in this JVM, or null. */
    public jade.core.Agent jadeAgent(String localName) {
        return jadeAgents.get(localName);
    }

    /** The JADE agents running in this JVM. */
    public java.util.List<jade.core.Agent> jadeAgents() {
        return new java.util.ArrayList<>(jadeAgents.values());
    }

    /** The local names of the platform's agents (those running here), in start order. */
    public java.util.List<String> agentNames() {
        java.util.List<String> l = new java.util.ArrayList<>();
        for (AID a : platform.runtime().agents()) {
            String n = a.name().contains("@") ? a.name().substring(0, a.name().lastIndexOf('@')) : a.name();
            l.add(Names.decode(n));
        }
        return l;
    }

    /** The platform's name. */
    public String platformName() {
        return platform.name();
    }

    /** Starts a Concord agent for a JADE agent; returns its AID. */
    public AID startHost(String localName, Host host, Object[] args) {
        return platform.startAgent(Names.encodeLocal(localName), host, args == null ? new Object[0] : args);
    }

    /** True if a Concord agent of this name runs here. */
    public boolean hosts(String localName) {
        AID a = AID.local(Names.encodeLocal(localName), platform.name());
        return platform.runtime().agents().contains(a);
    }

    /**
     * Asks the platform's services for an agent and waits for the answer, off the loop (a JADE
     * agent's own thread), as JADE's synchronous DF calls do.
     */
    public <T> T call(Agent host, Function<PlatformServices, CompletableFuture<T>> request)
            throws ExecutionException, TimeoutException, InterruptedException {
        CompletableFuture<T> f = new CompletableFuture<>();
        platform.runtime().execute(() -> {
            try {
                request.apply(Platform.of(host)).whenComplete((v, e) -> {
                    if (e != null) {
                        f.completeExceptionally(e);
                    } else {
                        f.complete(v);
                    }
                });
            } catch (RuntimeException e) {
                f.completeExceptionally(e);
            }
        });
        return f.get(DF_TIMEOUT_MS, TimeUnit.MILLISECONDS);
    }

    /** Wall-clock time in epoch milliseconds (Concord's clock). */
    public static long nowMs() {
        return CLOCK.epochMillis();
    }

    /** Monotonic time in nanoseconds (Concord's clock). */
    public static long nowNs() {
        return CLOCK.nanoTime();
    }

    /** True if JADE agents get virtual threads here (Java 21 and later). */
    public static boolean virtualThreads() {
        return Runtime.version().feature() >= 21;
    }

    /**
     * A new thread for a JADE agent: a virtual thread on Java 21 and later (found by reflection,
     * so that this compiles for Java 17), else a platform thread. Not started.
     */
    public static Thread newAgentThread(String name, Runnable body) {
        if (virtualThreads()) {
            try {
                Object builder = Thread.class.getMethod("ofVirtual").invoke(null);
                Class<?> builderType = Class.forName("java.lang.Thread$Builder");
                builder = builderType.getMethod("name", String.class).invoke(builder, name);
                Method unstarted = builderType.getMethod("unstarted", Runnable.class);
                return (Thread) unstarted.invoke(builder, body);
            } catch (ReflectiveOperationException | RuntimeException e) {
                LOG.debug("no virtual threads ({}); a platform thread instead", e.toString());
            }
        }
        Thread t = new Thread(body, name);
        t.setDaemon(false);
        return t;
    }
}
