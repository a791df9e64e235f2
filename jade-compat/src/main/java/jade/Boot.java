package jade;

import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.core.Runtime;
import jade.util.leap.Properties;
import jade.wrapper.AgentContainer;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * JADE's command line over Concord: {@code java jade.Boot [options] [-agents "name:pkg.Class(arg1,arg2);..."]}.
 * What has a meaning here is mapped ({@code -name}, {@code -host}/{@code -local-host}, {@code -port}/
 * {@code -local-port}: the first of the agents' ports, {@code -container}, {@code -gui}: Concord's web
 * console if it is on the class path, {@code -agents}); what has none ({@code -services}, {@code -mtps},
 * {@code -nomtp}, ...) is named on standard output as ignored, and the rest goes on.
 */
public class Boot {
    /** JADE's default name for a properties file given with {@code -conf}. */
    public static final String DEFAULT_FILENAME = "leap.properties";

    /** Options that take a value. */
    private static final List<String> WITH_VALUE = List.of("agents", "host", "port", "local-host", "local-port", "name",
            "platform-id", "services", "mtps", "mtp", "container-name", "conf", "main-host", "main-port", "jade_mtp_http_port",
            "detect-main", "accept-foreign-agents", "backupmain", "smaddrs", "nomobility", "icps", "owner", "file-dir");

    /** What each ignored option would do in JADE, and why not here. */
    private static final Map<String, String> IGNORED = Map.of(
            "services", "Concord's platform services are built in (DF, AMS, messaging, the safety stack)",
            "mtps", "agents reach JADE platforms through concord-jade-bridge's HTTP MTP, not through a JADE MTP",
            "mtp", "agents reach JADE platforms through concord-jade-bridge's HTTP MTP, not through a JADE MTP",
            "nomtp", "there is no JADE MTP to leave out",
            "detect-main", "there is no main container to detect: the agents elect their container",
            "conf", "Concord reads no JADE properties file; give the options on the command line",
            "backupmain", "there is no main container: the agents elect their container, and a new one after a failure",
            "jade_mtp_http_port", "agents reach JADE platforms through concord-jade-bridge's HTTP MTP");

    public Boot() {
    }

    /** Starts a container (here: this JVM's part of a Concord platform) and the agents the command line names. */
    public static void main(String[] args) {
        Properties p;
        try {
            p = parseCmdLineArgs(args);
        } catch (IllegalArgumentException e) {
            System.out.println("jade.Boot: " + e.getMessage());
            printUsage();
            System.exit(2);
            return;
        }
        if (p.getProperty("help") != null) {
            printUsage();
            return;
        }
        Profile profile = new ProfileImpl();
        for (Map.Entry<String, String> ignored : new TreeMap<>(IGNORED).entrySet()) {
            if (p.getProperty(ignored.getKey()) != null) {
                System.out.println("jade.Boot: -" + ignored.getKey() + " is ignored: " + ignored.getValue());
            }
        }
        for (String key : p.stringPropertyNames()) {
            if (!IGNORED.containsKey(key) && !List.of("agents", "host", "port", "local-host", "local-port", "main-host", "main-port",
                    "name", "platform-id", "container", "container-name", "gui", "help").contains(key)) {
                System.out.println("jade.Boot: -" + key + " is ignored: concord-jade does not know it");
            }
        }
        String host = first(p, "local-host", "host", "main-host");
        if (host != null) {
            profile.setParameter(Profile.LOCAL_HOST, host);
            profile.setParameter(Profile.MAIN_HOST, host);
        }
        String port = first(p, "local-port", "port", "main-port");
        if (port != null) {
            profile.setParameter(Profile.LOCAL_PORT, port);
            profile.setParameter(Profile.MAIN_PORT, port);
        }
        String name = first(p, "name", "platform-id");
        if (name != null) {
            profile.setParameter(Profile.PLATFORM_ID, name);
        }
        if (p.getProperty("container-name") != null) {
            profile.setParameter(Profile.CONTAINER_NAME, p.getProperty("container-name"));
        }
        profile.setParameter(Profile.GUI, p.getProperty("gui") != null ? "true" : "false");
        boolean peripheral = p.getProperty("container") != null;
        if (peripheral) {
            System.out.println("jade.Boot: -container: a container that joins the platform of this name and ports "
                    + "(there is no main container here; the agents elect theirs)");
        }
        AgentContainer c = peripheral ? Runtime.instance().createAgentContainer(profile)
                : Runtime.instance().createMainContainer(profile);
        String agents = p.getProperty("agents");
        if (agents == null) {
            return;
        }
        for (String[] spec : agentSpecs(agents)) {
            try {
                c.createNewAgent(spec[0], spec[1], arguments(spec[2])).start();
            } catch (Exception e) {
                System.out.println("jade.Boot: could not start agent " + spec[0] + " (" + spec[1] + "): " + e.getMessage());
            }
        }
    }

    private static String first(Properties p, String... keys) {
        for (String k : keys) {
            if (p.getProperty(k) != null) {
                return p.getProperty(k);
            }
        }
        return null;
    }

    /**
     * Reads JADE's command line into properties, one per option (without its dash); a flag gets
     * {@code "true"}. Bare words at the end are agent specifications, as in JADE's older syntax.
     *
     * @throws IllegalArgumentException if an option that needs a value has none
     */
    public static Properties parseCmdLineArgs(String[] args) throws IllegalArgumentException {
        Properties p = new Properties();
        List<String> bare = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a.equals("-help") || a.equals("-h") || a.equals("-?")) {
                p.setProperty("help", "true");
            } else if (a.startsWith("-") && a.length() > 1) {
                String key = a.substring(1);
                if (WITH_VALUE.contains(key)) {
                    if (i + 1 >= args.length) {
                        throw new IllegalArgumentException("-" + key + " needs a value");
                    }
                    p.setProperty(key, args[++i]);
                } else {
                    p.setProperty(key, "true");
                }
            } else {
                bare.add(a);
            }
        }
        if (!bare.isEmpty()) {
            String more = String.join(";", bare);
            String agents = p.getProperty("agents");
            p.setProperty("agents", agents == null ? more : agents + ";" + more);
        }
        return p;
    }

    /** {@code name:pkg.Class(a,b);other:pkg.Other} as {name, class, argument text or null} triples. */
    static List<String[]> agentSpecs(String agents) {
        List<String[]> specs = new ArrayList<>();
        StringBuilder cur = new StringBuilder();
        int depth = 0;
        for (char ch : (agents + ";").toCharArray()) {
            if (ch == '(') {
                depth++;
            } else if (ch == ')') {
                depth--;
            }
            if (ch == ';' && depth == 0) {
                String spec = cur.toString().trim();
                cur.setLength(0);
                if (spec.isEmpty()) {
                    continue;
                }
                int colon = spec.indexOf(':');
                if (colon <= 0) {
                    throw new IllegalArgumentException("an agent is given as name:class(arguments), not as " + spec);
                }
                String rest = spec.substring(colon + 1).trim();
                int open = rest.indexOf('(');
                String cls = open < 0 ? rest : rest.substring(0, open).trim();
                String argText = open < 0 ? null : rest.substring(open + 1, rest.lastIndexOf(')'));
                specs.add(new String[] {spec.substring(0, colon).trim(), cls, argText});
            } else {
                cur.append(ch);
            }
        }
        return specs;
    }

    private static Object[] arguments(String text) {
        if (text == null) {
            return new Object[0];
        }
        List<String> args = new ArrayList<>();
        // As JADE's Boot: split at every comma, each argument trimmed, quotes kept as written
        for (String a : text.split(",")) {
            String t = a.trim();
            if (!t.isEmpty()) {
                args.add(t);
            }
        }
        return args.toArray();
    }

    /** JADE's options as concord-jade reads them. */
    public static void printUsage() {
        System.out.println("Usage: java jade.Boot [options] [-agents \"name:pkg.Class(arg1,arg2);...\"]");
        System.out.println("  -name <platform>      the platform's name (default <host>:<port>/JADE)");
        System.out.println("  -host, -local-host    the address agents bind (default 127.0.0.1)");
        System.out.println("  -port, -local-port    the first of the 200 ports the agents take one each");
        System.out.println("  -container            a container joining the platform of that name and ports");
        System.out.println("  -container-name <n>   the container's name");
        System.out.println("  -gui                  Concord's web console (its address printed), if concord-console is on the class path");
        System.out.println("  -agents <list>        agents to start, ';'-separated");
        System.out.println("  ignored here, with a line saying so: -services, -mtps, -mtp, -nomtp, -detect-main, -conf, -backupmain");
    }
}
