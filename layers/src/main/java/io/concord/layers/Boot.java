package io.concord.layers;

import io.concord.core.acl.AID;
import io.concord.core.agent.Agent;
import io.concord.core.agent.PortRange;
import io.concord.core.net.Transport;
import io.concord.layers.platform.ContainerLayer;
import io.concord.layers.platform.Gateway;
import io.concord.layers.platform.NetworkConfig;
import io.concord.layers.platform.Role;
import io.concord.layers.security.PlatformKey;

import java.io.IOException;
import java.io.PrintStream;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.ServiceLoader;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * The command line, in the style of JADE's {@code jade.Boot}: starts agents on this host's
 * platform; they find the others by themselves.
 *
 * <pre>
 * java -cp app.jar io.concord.layers.Boot -agents "seller1:org.example.Seller(42);buyer:org.example.Buyer"
 *      [-name concord] [-ports 7001-7200] [-profile class7|class3|closed] [-transport udp|tcp]
 *      [-host 127.0.0.1] [-seeds host[:port],...] [-discovery-port 7000] [-http [host:]port]
 *      [-console [host:]port] [-conf platform.properties] [-watch]
 * </pre>
 *
 * A configuration file holds the same settings as Java properties ({@code name}, {@code ports},
 * {@code profile}, {@code transport}, {@code host}, {@code agents}, {@code watch}); the command line
 * overrides it. Each agent class extends {@link Agent} and has a public no-argument constructor;
 * its arguments arrive as strings in {@code getArguments()}.
 */
public final class Boot {

    /** A bad command line or configuration, with what to do about it. */
    public static final class BootException extends RuntimeException {
        BootException(String message) {
            super(message);
        }

        BootException(String message, Throwable cause) {
            super(message, cause);
        }
    }

    /** One agent to start: {@code name:class(arg,arg)}. */
    public record AgentSpec(String name, String className, List<String> args) {
    }

    private Boot() {
    }

    public static void main(String[] args) {
        Platform p;
        try {
            p = start(args, System.out);
        } catch (BootException e) {
            System.err.println("concord: " + e.getMessage());
            System.exit(2);
            return;
        }
        Runtime.getRuntime().addShutdownHook(new Thread(p::close, "concord-shutdown"));
    }

    /**
     * Parses the arguments, starts the platform's runtime and the agents; returns the platform.
     *
     * @throws BootException saying what was wrong and what to do
     */
    public static Platform start(String[] args, PrintStream out) {
        Map<String, String> s = settings(args);
        if (s.containsKey("help")) {
            out.println(usage());
            throw new BootException("usage printed");
        }
        List<AgentSpec> specs = parseAgents(s.getOrDefault("agents", ""));
        Platform.Builder b = Platform.builder().name(s.getOrDefault("name", "concord"))
                .host(s.getOrDefault("host", "127.0.0.1"))
                .ports(range(s.getOrDefault("ports", PortRange.DEFAULT_BASE + "-" + (PortRange.DEFAULT_BASE + PortRange.DEFAULT_COUNT - 1))))
                .profile(profile(s.getOrDefault("profile", "class7")))
                .transport(transport(s.getOrDefault("transport", "udp")));
        if (s.containsKey("key")) {
            try {
                b.platformKey(PlatformKey.load(Path.of(s.get("key").trim())));
            } catch (IllegalStateException | UncheckedIOException e) {
                throw new BootException("-key: " + e.getMessage(), e);
            }
        }
        try {
            NetworkConfig net = NetworkConfig.defaults();
            if (s.containsKey("discovery-port")) {
                net = net.withPort(Integer.parseInt(s.get("discovery-port").trim()));
            }
            if (s.containsKey("seeds") && !s.get("seeds").isBlank()) {
                net = net.withSeeds(List.of(s.get("seeds").split(",")));
            }
            b.network(net);
        } catch (IllegalArgumentException e) {
            throw new BootException("-seeds is written host[:port],... and -discovery-port a port number: " + e.getMessage(), e);
        }
        String acc = null;
        if (s.containsKey("http")) {
            String[] hostPort = hostPort(s.get("http"), s.getOrDefault("host", "127.0.0.1"));
            b.gateway(httpGateway(hostPort, s));
            acc = "http://" + hostPort[0] + ":" + hostPort[1] + "/acc";
        }
        if (s.containsKey("http-expose")) {
            try {
                b.httpExpose(s.get("http-expose"));
            } catch (IllegalArgumentException e) {
                throw new BootException("-http-expose: " + e.getMessage(), e);
            }
        }
        if (s.containsKey("console")) {
            b.console(s.get("console")).consoleOut(out);
        }
        List<Agent> agents = new ArrayList<>();
        for (AgentSpec spec : specs) {
            agents.add(instantiate(spec));
        }
        Platform p;
        try {
            p = b.build();
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw new BootException(e.getMessage(), e);
        }
        if (acc != null) {
            out.println(accLine(acc, p.name()));
        }
        boolean watch = Boolean.parseBoolean(s.getOrDefault("watch", "false"));
        try {
            for (int i = 0; i < specs.size(); i++) {
                AgentSpec spec = specs.get(i);
                AID aid = p.startAgent(spec.name(), agents.get(i), spec.args().toArray());
                out.println("started " + aid.name() + " at " + aid.addresses().get(0) + " (" + spec.className() + ")");
                if (watch) {
                    watch(p, aid, out);
                }
            }
        } catch (IllegalArgumentException | IllegalStateException e) {
            p.close();
            throw new BootException(e.getMessage(), e);
        }
        return p;
    }

    /** Prints each change of the agent's role and of its container. */
    private static void watch(Platform p, AID aid, PrintStream out) {
        p.runtime().execute(() -> {
            ContainerLayer c = Platform.containerLayer(p.runtime(), aid);
            String[] last = {""};
            Consumer<ContainerLayer> print = l -> {
                String now = l.role() + " " + l.containerName() + " " + l.agents().size() + " " + l.globalAgents().size();
                if (!now.equals(last[0]) && l.role() != Role.SEEKING && l.containerName() != null) {
                    last[0] = now;
                    int here = l.agents().size();
                    int elsewhere = l.globalAgents().size();
                    out.println(aid.localName() + ": " + (l.role() == Role.CONTAINER
                            ? "I am the container (term " + l.term() + ")"
                            : "container is " + l.containerName() + " (term " + l.term() + ")")
                            + ", " + here + (here == 1 ? " agent" : " agents") + " here"
                            + (elsewhere > 0 ? ", " + elsewhere + " on other hosts" : ""));
                }
            };
            c.addListener(print);
            print.accept(c);
        });
    }

    /** The options that take a value; all but {@code conf} may also stand in a configuration file, as may {@code watch}. */
    private static final List<String> VALUED = List.of("agents", "name", "ports", "profile", "transport", "host", "conf",
            "seeds", "discovery-port", "http", "http-platforms", "http-hosts", "http-expose", "key", "console");

    static Map<String, String> settings(String[] args) {
        Map<String, String> cli = new LinkedHashMap<>();
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (!a.startsWith("-") || a.length() < 2) {
                throw new BootException("unexpected argument '" + a + "'; options start with '-'. " + usage());
            }
            String key = a.replaceFirst("^--?", "").toLowerCase(Locale.ROOT);
            if (key.equals("help") || key.equals("h") || key.equals("watch")) {
                cli.put(key.equals("h") ? "help" : key, "true");
            } else if (VALUED.contains(key)) {
                if (i + 1 >= args.length) {
                    throw new BootException("-" + key + " needs a value. " + usage());
                }
                if (cli.put(key, args[++i]) != null) {
                    throw new BootException("-" + key + " is given twice; give each option once (several agents go in one -agents, "
                            + "separated by ';')");
                }
            } else {
                throw new BootException("unknown option '" + a + "'. " + usage());
            }
        }
        Map<String, String> all = new LinkedHashMap<>();
        String conf = cli.get("conf");
        List<String> inFile = new ArrayList<>(VALUED);
        inFile.remove("conf");
        inFile.add("watch");
        if (conf != null) {
            Properties props = new Properties();
            try (Reader r = Files.newBufferedReader(Path.of(conf), StandardCharsets.UTF_8)) {
                props.load(r);
            } catch (IOException e) {
                throw new BootException("cannot read the configuration file " + conf + ": " + e.getMessage(), e);
            }
            for (String k : props.stringPropertyNames()) {
                String key = k.toLowerCase(Locale.ROOT);
                if (!inFile.contains(key)) {
                    throw new BootException("unknown setting '" + k + "' in " + conf + "; known: " + String.join(", ", inFile));
                }
                all.put(key, props.getProperty(k).trim());
            }
        }
        all.putAll(cli);
        return all;
    }

    /**
     * Parses {@code name:class(arg,arg);name:class}.
     *
     * @throws BootException naming the bad part
     */
    public static List<AgentSpec> parseAgents(String text) {
        List<AgentSpec> out = new ArrayList<>();
        int depth = 0;
        int start = 0;
        for (int i = 0; i <= text.length(); i++) {
            char c = i < text.length() ? text.charAt(i) : ';';
            if (c == '(') {
                depth++;
            } else if (c == ')') {
                depth--;
                if (depth < 0) {
                    throw new BootException("an unmatched ')' in -agents \"" + text + "\"");
                }
            } else if (c == ';' && depth == 0) {
                String one = text.substring(start, Math.min(i, text.length())).trim();
                if (!one.isEmpty()) {
                    out.add(parseAgent(one));
                }
                start = i + 1;
            }
        }
        if (depth != 0) {
            throw new BootException("an unclosed '(' in -agents \"" + text + "\"");
        }
        return out;
    }

    private static AgentSpec parseAgent(String one) {
        int colon = one.indexOf(':');
        if (colon < 1 || colon == one.length() - 1) {
            throw new BootException("an agent is written name:class or name:class(arguments), got '" + one + "'");
        }
        String name = one.substring(0, colon).trim();
        String rest = one.substring(colon + 1).trim();
        List<String> args = new ArrayList<>();
        int open = rest.indexOf('(');
        String cls = rest;
        if (open >= 0) {
            if (!rest.endsWith(")")) {
                throw new BootException("the arguments of '" + name + "' must end with ')', got '" + rest + "'");
            }
            cls = rest.substring(0, open).trim();
            String inner = rest.substring(open + 1, rest.length() - 1).trim();
            if (!inner.isEmpty()) {
                for (String a : inner.split(",", -1)) {
                    args.add(a.trim());
                }
            }
        }
        if (!cls.matches("[A-Za-z_$][\\w$]*(\\.[A-Za-z_$][\\w$]*)*")) {
            throw new BootException("'" + cls + "' is not a Java class name (agent '" + name + "')");
        }
        return new AgentSpec(name, cls, args);
    }

    private static Agent instantiate(AgentSpec spec) {
        Class<?> c;
        try {
            c = Class.forName(spec.className());
        } catch (ClassNotFoundException e) {
            throw new BootException("agent '" + spec.name() + "': class " + spec.className()
                    + " is not on the class path; add its jar with -cp", e);
        }
        if (!Agent.class.isAssignableFrom(c)) {
            throw new BootException("agent '" + spec.name() + "': " + spec.className() + " does not extend "
                    + Agent.class.getName());
        }
        try {
            return (Agent) c.getDeclaredConstructor().newInstance();
        } catch (NoSuchMethodException e) {
            throw new BootException("agent '" + spec.name() + "': " + spec.className()
                    + " needs a public constructor without parameters", e);
        } catch (ReflectiveOperationException e) {
            throw new BootException("agent '" + spec.name() + "': cannot create " + spec.className() + ": "
                    + (e.getCause() != null ? e.getCause() : e), e);
        }
    }

    /**
     * The line that tells a JADE user what to write: the ACC's address, and whether JADE on other
     * machines can reach it.
     */
    static String accLine(String acc, String platform) {
        boolean loopback = acc.startsWith("http://127.") || acc.startsWith("http://localhost:");
        return "JADE bridge: JADE agents reach the agents of this platform as <name>@" + platform + " at " + acc
                + " (new AID(\"<name>@" + platform + "\", AID.ISGUID).addAddresses(\"" + acc + "\"))"
                + (loopback ? "; this is a loopback address, reachable by JADE on this machine only: for JADE on other "
                + "machines give -host <this machine's LAN address> (or -http <LAN address>:<port>)" : "");
    }

    /** {@code -http 7779} or {@code -http host:7779}, the host defaulting to {@code -host}. */
    private static String[] hostPort(String spec, String host) {
        String h = host;
        String p = spec.trim();
        int colon = p.lastIndexOf(':');
        if (colon > 0) {
            h = p.substring(0, colon);
            p = p.substring(colon + 1);
        }
        try {
            int port = Integer.parseInt(p);
            if (port < 1 || port > 65535) {
                throw new NumberFormatException();
            }
        } catch (NumberFormatException e) {
            throw new BootException("-http is written port or host:port with a port from 1 to 65535, got '" + spec + "'");
        }
        return new String[]{h, p};
    }

    /** The JADE bridge's HTTP MTP, from concord-jade-bridge. */
    private static Supplier<Gateway> httpGateway(String[] hostPort,
                                                                                            Map<String, String> settings) {
        String h = hostPort[0];
        int port = Integer.parseInt(hostPort[1]);
        GatewayProvider http = null;
        for (GatewayProvider g : ServiceLoader.load(GatewayProvider.class)) {
            if (g.kind().equals("http")) {
                http = g;
            }
        }
        if (http == null) {
            throw new BootException("-http needs the JADE bridge: add concord-jade-bridge to the class path");
        }
        GatewayProvider provider = http;
        String fh = h;
        int fp = port;
        Map<String, String> own = new HashMap<>();
        for (String k : List.of("http-platforms", "http-hosts")) {
            if (settings.containsKey(k)) {
                own.put(k, settings.get(k));
            }
        }
        return () -> provider.create(fh, fp, own);
    }

    private static PortRange range(String s) {
        try {
            return PortRange.parse(s);
        } catch (IllegalArgumentException e) {
            throw new BootException(e.getMessage(), e);
        }
    }

    private static Profile profile(String s) {
        return switch (s.toLowerCase(Locale.ROOT).replace("_", "").replace("-", "")) {
            case "class7" -> Profile.CLASS_7;
            case "class3" -> Profile.CLASS_3;
            case "closed" -> Profile.CLOSED;
            default -> throw new BootException("unknown profile '" + s + "'; use class7 (default), class3 or closed");
        };
    }

    private static Transport transport(String s) {
        return switch (s.toLowerCase(Locale.ROOT)) {
            case "udp" -> Transport.UDP;
            case "tcp" -> Transport.TCP;
            default -> throw new BootException("unknown transport '" + s + "'; use udp (default) or tcp");
        };
    }

    static String usage() {
        return "Usage: java -cp <class path> io.concord.layers.Boot -agents \"name:pkg.Class(arg,...);...\" "
                + "[-name concord] [-ports 7001-7200] [-profile class7|class3|closed] [-transport udp|tcp] "
                + "[-host 127.0.0.1] [-seeds host[:port],...] [-discovery-port 7000] [-http [host:]port] [-http-platforms name,...] [-http-hosts address,...] [-http-expose status,sniff,kill] [-key platform.key] [-console [host:]port] [-conf file.properties] [-watch]";
    }
}
