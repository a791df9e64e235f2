package io.concord.layers;

import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
import io.concord.core.agent.AgentOptions;
import io.concord.core.agent.AgentRuntime;
import io.concord.core.agent.PortRange;
import io.concord.core.layer.Layer;
import io.concord.core.net.Transport;
import io.concord.layers.defence.Defence;
import io.concord.layers.observe.ObserverLayer;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.authority.Policy;
import io.concord.layers.platform.Gateway;
import io.concord.layers.platform.NetworkConfig;
import io.concord.layers.platform.PlatformConfig;
import io.concord.layers.security.PlatformKey;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.function.Supplier;

/**
 * A platform with no main container, embedded in a Java program. Each agent started here gets
 * the container layer on top of its safety stack and a port of the range by port-binding
 * discovery; the agents of this JVM, and of any other JVM on the host that uses the same platform
 * name, port range and key, find each other and elect a container by themselves.
 *
 * <pre>{@code
 * try (Platform p = Platform.builder().name("shop").build()) {
 *     p.startAgent("seller1", new Seller(), 42);
 *     p.startAgent("buyer", new Buyer());
 *     ...
 * }
 * }</pre>
 *
 * <p><b>Loops.</b> A platform runs its agents on one event loop (one thread) unless
 * {@link Builder#loops(int)} asks for more: then each agent is owned by one loop for life (its
 * behaviours, timers and stack run only there), placed round-robin or where
 * {@link #startAgentOn} puts it. An agent's application messages to another agent of this
 * platform on this JVM's loops are handed over in memory, on one loop with no thread switch, across two loops through the
 * receiver's loop's queue (a {@link io.concord.core.agent.LoopGroup}); platform, service and
 * observed messages take the stacks, as they do on one loop. {@link #runtime()} is the first
 * loop's; an agent's own is {@code agent.runtime()}.
 */
public final class Platform implements AutoCloseable {
    private final AgentRuntime runtime;
    private final List<AgentRuntime> loops;
    private final java.util.concurrent.atomic.AtomicInteger nextLoop = new java.util.concurrent.atomic.AtomicInteger();
    private final boolean ownsRuntime;
    private final PortRange ports;
    private final Supplier<List<Layer>> stack;
    private final Transport transport;
    private volatile AutoCloseable console;
    private final Policy policy;

    private Platform(Builder b, List<AgentRuntime> loops, boolean owns) {
        this.runtime = loops.get(0);
        this.loops = List.copyOf(loops);
        this.ownsRuntime = owns;
        this.ports = b.ports;
        this.transport = b.transport;
        Supplier<List<Layer>> safety = b.safety != null ? b.safety : defaultSafety(b);
        PlatformConfig config = b.config;
        NetworkConfig network = b.network;
        Supplier<Gateway> gateways = b.gateway;
        Set<Defence> off = b.off;
        Policy policy = off.contains(Defence.AUTHORITY) ? Policy.allowingEverything() : b.policy;
        this.policy = policy;
        this.stack = () -> {
            List<Layer> l = new ArrayList<>();
            l.add(new ObserverLayer(policy));
            l.add(new ContainerLayer(config, network, gateways == null ? null : gateways.get(), off, policy));
            l.addAll(safety.get());
            return l;
        };
    }

    private static Supplier<List<Layer>> defaultSafety(Builder b) {
        SafetyStack.Builder sb = SafetyStack.builder().profile(b.profile).transport(b.transport);
        if (b.key != null) {
            sb.platformKey(b.key);
        }
        sb.withoutDefences(b.off.toArray(Defence[]::new));
        return sb.build();
    }

    public static Builder builder() {
        return new Builder();
    }

    /** Settings, checked at {@link #build()}. */
    public static final class Builder {
        private String name = "concord";
        private boolean named;
        private String host = "127.0.0.1";
        private PortRange ports = PortRange.defaults();
        private Profile profile = Profile.CLASS_7;
        private Transport transport = Transport.UDP;
        private PlatformConfig config = PlatformConfig.defaults();
        private NetworkConfig network = NetworkConfig.defaults();
        private Supplier<Gateway> gateway;
        private Supplier<List<Layer>> safety;
        private Set<Defence> off = Set.of();
        private Policy policy = Policy.defaults();
        private AgentRuntime runtime;
        private PlatformKey key;
        private String console;
        private PrintStream consoleOut = System.out;
        private int loops = 1;

        private Builder() {
        }

        /**
         * Runs the agents on {@code n} event loops (threads) of this JVM, 1 to 256; 1 by default.
         * {@code loops(Platform.CORES)} puts every core to work. Agents are placed round-robin
         * ({@link Platform#startAgentOn} chooses); each stays on its loop for life. Not with
         * {@link #runtime(AgentRuntime)}: a runtime of the caller's is one loop.
         */
        public Builder loops(int n) {
            if (n < 1 || n > 256) {
                throw new IllegalArgumentException("loops(" + n + "): a platform runs on 1 to 256 loops (Platform.CORES is "
                        + CORES + " here)");
            }
            this.loops = n;
            return this;
        }

        /**
         * Serves the web console on {@code [host:]port} (127.0.0.1 unless a host is given; on any
         * other address every request needs the token it prints). Needs {@code concord-console}
         * on the class path.
         */
        public Builder console(String hostPort) {
            this.console = Objects.requireNonNull(hostPort, "console");
            return this;
        }

        /** Where the console prints its address; standard output by default. */
        public Builder consoleOut(PrintStream out) {
            this.consoleOut = Objects.requireNonNull(out, "consoleOut");
            return this;
        }

        /** The platform name, the part after {@code @}; agents of one platform must agree on it. */
        public Builder name(String n) {
            this.name = Objects.requireNonNull(n, "name");
            this.named = true;
            return this;
        }

        /** The address agents bind to; 127.0.0.1 by default. */
        public Builder host(String h) {
            this.host = Objects.requireNonNull(h, "host");
            return this;
        }

        /** The port range of the port-binding discovery; 7001-7200 by default. */
        public Builder ports(PortRange r) {
            this.ports = Objects.requireNonNull(r, "ports");
            return this;
        }

        /** The safety profile; class 7 by default. */
        public Builder profile(Profile p) {
            this.profile = Objects.requireNonNull(p, "profile");
            return this;
        }

        /**
         * The platform key; by default the user's {@code ~/.concord/platform.key}, which all of
         * one user's platforms share whatever their names. Give a platform its own key when its
         * agents must not reach the user's other platforms.
         */
        public Builder platformKey(PlatformKey k) {
            this.key = Objects.requireNonNull(k, "platformKey");
            return this;
        }

        public Builder transport(Transport t) {
            this.transport = Objects.requireNonNull(t, "transport");
            return this;
        }

        /** The container layer's timing. */
        public Builder config(PlatformConfig c) {
            this.config = Objects.requireNonNull(c, "config");
            return this;
        }

        /**
         * Network discovery between hosts: the discovery port, seeds, broadcast; {@code null} keeps
         * the platform to this host.
         */
        public Builder network(NetworkConfig n) {
            this.network = n;
            return this;
        }

        /** Seeds to contact by unicast besides broadcast ({@code host} or {@code host:port}). */
        public Builder seeds(String... hostPorts) {
            this.network = (network == null ? NetworkConfig.defaults() : network).withSeeds(List.of(hostPorts));
            return this;
        }

        /**
         * A way to foreign platforms (the JADE bridge's HTTP MTP): one per agent, started by the
         * agent that is container.
         */
        public Builder gateway(Supplier<Gateway> g) {
            this.gateway = g;
            return this;
        }

        /**
         * Opens services to agents of other platforms (over the HTTP MTP) beyond the defaults,
         * named one by one: {@code status}, {@code sniff}, {@code kill} (the observation service).
         * By default they reach only
         * the agents' own conversations, the DF and the AMS (docs/security.md, "Who may do what").
         *
         * @throws IllegalArgumentException for a name that is not a service, or one that cannot be opened
         */
        public Builder httpExpose(String... services) {
            this.policy = Policy.exposing(String.join(",", services));
            return this;
        }

        /**
         * Builds this platform's stacks without some defences: only for the threat tests, which
         * show each threat reaching an agent without its defence. It reaches only the stacks of
         * this platform (the container layer's, and the default safety layers').
         */
        public Builder withoutDefences(Defence... defences) {
            this.off = Set.copyOf(List.of(defences));
            return this;
        }

        /** The safety layers under the container layer, instead of the profile's defaults. */
        public Builder safetyStack(Supplier<List<Layer>> s) {
            this.safety = Objects.requireNonNull(s, "safetyStack");
            return this;
        }

        /**
         * Runs the platform's agents on a runtime the caller made and drives (a simulation, or a
         * runtime shared with other work); its platform name is used ({@link #build} refuses a
         * different {@link #name}).
         */
        public Builder runtime(AgentRuntime rt) {
            this.runtime = Objects.requireNonNull(rt, "runtime");
            return this;
        }

        /**
         * @throws IllegalArgumentException naming the bad setting
         */
        public Platform build() {
            ConsoleProvider consoles = null;
            if (console != null) {
                consoles = ServiceLoader.load(ConsoleProvider.class).findFirst().orElseThrow(() -> new IllegalStateException(
                        "the console needs concord-console on the class path (io.concord:concord-console)"));
            }
            if (runtime != null && named && !name.equals(runtime.platformName())) {
                throw new IllegalArgumentException("the platform is named '" + name + "' but runs on a runtime of platform '"
                        + runtime.platformName() + "': a platform on a runtime of your own takes the runtime's name; name the"
                        + " runtime (AgentRuntime.builder().platformName(\"" + name + "\"), or Simulation.platformName(\"" + name
                        + "\") before newRuntime), or leave name(...) out");
            }
            if (runtime != null && loops > 1) {
                throw new IllegalArgumentException("loops(" + loops + ") with runtime(...): a runtime of your own is one loop; "
                        + "leave runtime(...) out to let the platform make its loops, or loops(...) out to run on yours");
            }
            Platform p;
            if (runtime != null) {
                p = new Platform(this, List.of(runtime), false);
            } else {
                List<AgentRuntime> made = new ArrayList<>();
                io.concord.core.agent.LoopGroup group = loops > 1 ? new io.concord.core.agent.LoopGroup() : null;
                for (int i = 0; i < loops; i++) {
                    made.add(AgentRuntime.builder().platformName(name).host(host).transport(transport).group(group).build());
                }
                p = new Platform(this, made, true);
                made.forEach(AgentRuntime::start);
            }
            if (consoles != null) {
                try {
                    p.console = consoles.start(p, console, consoleOut);
                } catch (RuntimeException e) {
                    p.close();
                    throw e;
                }
            }
            return p;
        }
    }

    /**
     * Starts an agent: it binds the first free port of the range, discovers the others and joins
     * the platform. Thread-safe.
     *
     * @throws IllegalStateException if the port range is full (the message says how to widen it)
     */
    public AID startAgent(String localName, Agent agent, Object... args) {
        return startAgentOn(Math.floorMod(nextLoop.getAndIncrement(), loops.size()), localName, agent, args);
    }

    /**
     * As {@link #startAgent}, on loop {@code loop} (0 to {@link #loops()} - 1): agents that talk
     * most to each other go on one loop, where their messages are handed over in memory.
     */
    public AID startAgentOn(int loop, String localName, Agent agent, Object... args) {
        if (loop < 0 || loop >= loops.size()) {
            throw new IllegalArgumentException("loop " + loop + ": this platform runs " + loops.size() + " loop(s), 0 to "
                    + (loops.size() - 1));
        }
        AgentOptions o = AgentOptions.defaults().withPortRange(ports).withStack(stack).withTransport(transport);
        return loops.get(loop).startAgentWith(localName, agent, o, args);
    }

    /** The cores of this machine, for {@link Builder#loops(int)}. */
    public static final int CORES = Runtime.getRuntime().availableProcessors();

    /** How many loops run this platform's agents here. */
    public int loops() {
        return loops.size();
    }

    /** The runtime of each loop, the first being {@link #runtime()}. */
    public List<AgentRuntime> runtimes() {
        return loops;
    }

    /** Who may do what on this platform (what its builder exposed to agents of other platforms). */
    public Policy policy() {
        return policy;
    }

    /** The console this platform serves ({@link Builder#console}), or {@code null}. */
    public AutoCloseable console() {
        return console;
    }

    /** The runtime that runs this platform's agents here (with several loops, the first loop's). */
    public AgentRuntime runtime() {
        return runtime;
    }

    public String name() {
        return runtime.platformName();
    }

    public PortRange ports() {
        return ports;
    }

    /** The container layer of an agent of this JVM, or {@code null} if it has none. Loop thread. */
    public static ContainerLayer containerLayer(AgentRuntime rt, AID aid) {
        return rt.layer(aid, ContainerLayer.class);
    }

    /** The platform services of an agent: white and yellow pages, its role. */
    public static PlatformServices of(Agent agent) {
        ContainerLayer c = containerLayer(agent.runtime(), agent.getAID());
        if (c == null) {
            throw new IllegalStateException(agent.getName() + " was not started on a Platform (it has no container layer)");
        }
        return new PlatformServices(agent, c);
    }

    /** Stops every agent of this JVM (they leave the platform cleanly) and the runtime if it made it. */
    @Override
    public void close() {
        AutoCloseable c = console;
        console = null;
        if (c != null) {
            try {
                c.close();
            } catch (Exception e) {
                // the console's server is stopping anyway
            }
        }
        if (ownsRuntime) {
            for (int i = loops.size() - 1; i >= 0; i--) {
                loops.get(i).close();
            }
        }
    }
}
