package io.concord.layers.authority;

import io.concord.core.acl.AclMessage;

import java.util.ArrayList;
import java.util.Collection;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

/**
 * Who may do what: the one place that decides, for every service and message kind of the
 * platform, which principal may use it. The services consult it (the observation service, the
 * container's gateway, the DF and AMS front ends, the control agent's resume, the Medical agent's
 * transports, the console); none decides on its own. Anything not in the table is refused (default
 * deny). The table is written out in {@code docs/security.md} ("Who may do what"), and a test
 * compares the two.
 *
 * <p>A policy is immutable. {@link #defaults()} is the table as documented; {@link #exposing}
 * opens services to agents of other platforms, named one by one (an operator's choice:
 * {@code -http-expose status,sniff} or {@code Platform.Builder.httpExpose}).
 */
public final class Policy {

    /** Who asks. */
    public enum Principal {
        /** An agent of this platform's lists, its frames authenticated by its own signed identity (or in the same runtime). */
        MEMBER("a member agent"),
        /** Holds the platform key but is not (yet) an agent of the lists: reaches only discovery, never a service. */
        KEY_HOLDER("a key holder"),
        /** An agent of another platform, arriving over the HTTP MTP or another gateway. */
        FOREIGN("an agent of another platform"),
        /** Whoever reaches the console's HTTP port (with its token where one is needed). */
        CONSOLE_CLIENT("the console's HTTP client"),
        /** A person with an operator key configured for the ward, whose order is signed with it. */
        OPERATOR("an operator");

        private final String said;

        Principal(String said) {
            this.said = said;
        }

        /** The principal in a sentence ("an agent of another platform"). */
        public String said() {
            return said;
        }
    }

    /** What is asked for. */
    public enum Service {
        /** The platform protocol (discovery, lists, maintenance, relays): the container layer's own words. */
        PLATFORM_MESSAGE("platform", "platform messages (discovery, lists, election, relays)"),
        /** Any other message to an agent: the agents' own conversations. */
        AGENT_MESSAGE("agents", "messages to the platform's agents (their own conversations)"),
        /** The DF front end: register, deregister, search (FIPA-Agent-Management). */
        DF("df", "the DF: register, deregister, search"),
        /** The AMS front end: search. */
        AMS("ams", "the AMS: search"),
        /** The observation service's {@code QUERY-REF status}. */
        OBSERVE_STATUS("status", "observation: QUERY-REF status"),
        /** The observation service's {@code SUBSCRIBE sniff}. */
        OBSERVE_SNIFF("sniff", "observation: SUBSCRIBE sniff"),
        /** The observation service's {@code REQUEST kill}. */
        OBSERVE_KILL("kill", "observation: REQUEST kill"),
        /** A held chair's resume ({@code resume-request}, the console's Resume). */
        CHAIR_RESUME("resume", "the chair's resume (after an e-stop, a reboot, a refusal)"),
        /** The Medical agent's {@code transport-request}. */
        TRANSPORT_REQUEST("transport", "the Medical agent's transport requests"),
        /** A transport's cancel (only its giver, or an operator). */
        TRANSPORT_CANCEL("cancel", "a transport's cancel"),
        /** The console's pages, lists and event streams. */
        CONSOLE_READ("console-read", "the console's pages and event streams"),
        /** The console's actions on agents: start, kill, send, record. */
        CONSOLE_ACTION("console-action", "the console's actions: start, kill, send, transport, cancel, stop all, resume, record");

        private final String key;
        private final String said;

        Service(String key, String said) {
            this.key = key;
            this.said = said;
        }

        /** The name used in configuration ({@code -http-expose status,sniff}). */
        public String key() {
            return key;
        }

        /** The service in a few words. */
        public String said() {
            return said;
        }

        /** The service named {@code key} ({@link #key()}), or an error listing the names. */
        public static Service named(String key) {
            String k = key.trim().toLowerCase(Locale.ROOT);
            for (Service s : values()) {
                if (s.key.equals(k)) {
                    return s;
                }
            }
            List<String> names = new ArrayList<>();
            for (Service s : EXPOSABLE) {
                names.add(s.key);
            }
            throw new IllegalArgumentException("no service '" + key.trim() + "' to expose; the services are " + String.join(", ", names));
        }
    }

    /** What the table says for one principal and one service. */
    public record Decision(boolean allowed, String reason) {
        /** The reason, or the empty string when allowed. */
        @Override
        public String reason() {
            return reason;
        }
    }

    /** The services an operator may open to agents of other platforms. */
    public static final Set<Service> EXPOSABLE = Set.copyOf(EnumSet.of(Service.OBSERVE_STATUS, Service.OBSERVE_SNIFF,
            Service.OBSERVE_KILL));

    /** The ontology of the observation service (ObserverLayer's). */
    public static final String OBSERVE_ONTOLOGY = "concord-observe";

    private static final Map<Service, EnumSet<Principal>> DEFAULTS = new EnumMap<>(Service.class);

    static {
        DEFAULTS.put(Service.PLATFORM_MESSAGE, EnumSet.of(Principal.MEMBER));
        DEFAULTS.put(Service.AGENT_MESSAGE, EnumSet.of(Principal.MEMBER, Principal.FOREIGN));
        DEFAULTS.put(Service.DF, EnumSet.of(Principal.MEMBER, Principal.FOREIGN));
        DEFAULTS.put(Service.AMS, EnumSet.of(Principal.MEMBER, Principal.FOREIGN));
        DEFAULTS.put(Service.OBSERVE_STATUS, EnumSet.of(Principal.MEMBER));
        DEFAULTS.put(Service.OBSERVE_SNIFF, EnumSet.of(Principal.MEMBER));
        DEFAULTS.put(Service.OBSERVE_KILL, EnumSet.of(Principal.MEMBER));
        DEFAULTS.put(Service.CHAIR_RESUME, EnumSet.of(Principal.OPERATOR));
        DEFAULTS.put(Service.TRANSPORT_REQUEST, EnumSet.of(Principal.MEMBER, Principal.OPERATOR));
        DEFAULTS.put(Service.TRANSPORT_CANCEL, EnumSet.of(Principal.MEMBER, Principal.OPERATOR));
        DEFAULTS.put(Service.CONSOLE_READ, EnumSet.of(Principal.CONSOLE_CLIENT, Principal.OPERATOR));
        DEFAULTS.put(Service.CONSOLE_ACTION, EnumSet.of(Principal.CONSOLE_CLIENT, Principal.OPERATOR));
    }

    /** Conditions that the table's cells carry, said in the docs' table. */
    private static final Map<Service, String> CONDITIONS = Map.of(
            Service.AGENT_MESSAGE, "a foreign agent: only over a gateway the platform serves (`-http`), under the bridge's trust rules",
            Service.DF, "a foreign agent registers only within the foreign registration limits, with lease times honoured",
            Service.CHAIR_RESUME, "an operator's order signed with a key configured for the ward, fresh and not seen before, "
                    + "carried by a member (a `resume-request`) or the console",
            Service.TRANSPORT_CANCEL, "a member only for the transports it asked for; an operator any, by an order signed with a key "
                    + "configured for the ward (`cancel-request :order`), its patient never left on board",
            Service.CONSOLE_ACTION, "from the console's own page (header `X-Concord-Console: 1`), with its token off loopback");

    private static final Policy DEFAULTS_POLICY = new Policy(EnumSet.noneOf(Service.class), true);

    private final Set<Service> exposed;
    private final boolean checks;

    private Policy(Set<Service> exposed, boolean checks) {
        this.exposed = Set.copyOf(exposed);
        this.checks = checks;
    }

    /** The table as documented: nothing beyond it. */
    public static Policy defaults() {
        return DEFAULTS_POLICY;
    }

    /**
     * The defaults, with these services also open to agents of other platforms (an operator's
     * configuration). Only {@link #EXPOSABLE} services can be: a platform message, a chair's resume
     * or a console action never can.
     *
     * @throws IllegalArgumentException for a service that cannot be exposed, saying which can
     */
    public static Policy exposing(Collection<Service> services) {
        for (Service s : services) {
            if (!EXPOSABLE.contains(Objects.requireNonNull(s))) {
                throw new IllegalArgumentException(s.key() + " cannot be exposed to agents of other platforms; these can: "
                        + exposableNames());
            }
        }
        return services.isEmpty() ? DEFAULTS_POLICY : new Policy(EnumSet.copyOf(services), true);
    }

    /** As {@link #exposing(Collection)}, from names ({@code status,sniff}). */
    public static Policy exposing(String commaSeparated) {
        List<Service> l = new ArrayList<>();
        for (String s : commaSeparated.split(",")) {
            if (!s.isBlank()) {
                l.add(Service.named(s));
            }
        }
        return exposing(l);
    }

    private static String exposableNames() {
        List<String> n = new ArrayList<>();
        for (Service s : Service.values()) {
            if (EXPOSABLE.contains(s)) {
                n.add(s.key());
            }
        }
        return String.join(", ", n);
    }

    /**
     * A policy that allows everything: only for the tests that show each refusal's defence, by
     * watching the attack succeed without it. Reached only through a builder's
     * {@code withoutDefences(Defence.AUTHORITY)}, for the stacks and agents that builder makes.
     */
    public static Policy allowingEverything() {
        return new Policy(EnumSet.noneOf(Service.class), false);
    }

    /** The services open to agents of other platforms beyond the defaults. */
    public Set<Service> exposed() {
        return exposed;
    }

    /** Whether this policy checks at all (false only for a test's {@link #allowingEverything()}). */
    public boolean checks() {
        return checks;
    }

    /** Whether {@code who} may use {@code what}. */
    public boolean allows(Principal who, Service what) {
        return decide(who, what).allowed();
    }

    /** The table's answer for {@code who} and {@code what}, with the reason of a refusal. */
    public Decision decide(Principal who, Service what) {
        if (!checks) {
            return new Decision(true, "");
        }
        EnumSet<Principal> may = DEFAULTS.get(what);
        if ((may != null && may.contains(who)) || (who == Principal.FOREIGN && exposed.contains(what))) {
            return new Decision(true, "");
        }
        String hint = who == Principal.FOREIGN && EXPOSABLE.contains(what)
                ? " (an operator may open it: -http-expose " + what.key() + ")" : "";
        String whoMay = may == null || may.isEmpty() ? "nobody" : said(may);
        return new Decision(false, who.said() + " may not use " + what.said() + "; only " + whoMay + " may" + hint);
    }

    private static String said(Set<Principal> ps) {
        List<String> l = new ArrayList<>();
        for (Principal p : ps) {
            l.add(p.said());
        }
        return String.join(" or ", l);
    }

    /**
     * Who sent a message that reached an agent through its stack: an agent of this platform (the
     * sender's name ends in {@code @platform}; the identification procedure has bound it to the
     * frame's authenticated source, and the membership gate to the lists) or an agent of another
     * platform (over a gateway, which refuses a sender of this platform). No sender: foreign.
     */
    public static Principal principalOf(AclMessage m, String platform) {
        return m.getSender() != null && platform != null && platform.equalsIgnoreCase(m.getSender().platform())
                ? Principal.MEMBER : Principal.FOREIGN;
    }

    /**
     * The service a message asks for at an agent's stack: the observation service's words by their
     * ontology and content, the platform protocol by its ontologies, else the agent's own business.
     */
    public static Service serviceOf(AclMessage m) {
        String onto = m.getOntology();
        if (onto == null) {
            return Service.AGENT_MESSAGE;
        }
        if (onto.equals(OBSERVE_ONTOLOGY)) {
            return switch (m.getPerformative()) {
                case SUBSCRIBE, CANCEL -> Service.OBSERVE_SNIFF;
                case QUERY_REF -> Service.OBSERVE_STATUS;
                case REQUEST -> Service.OBSERVE_KILL;   // kill, or words the service will not understand
                default -> Service.AGENT_MESSAGE;   // an answer to the agent's own question
            };
        }
        if (onto.startsWith("concord-") && PLATFORM_ONTOLOGIES.contains(onto)) {
            return Service.PLATFORM_MESSAGE;
        }
        return Service.AGENT_MESSAGE;
    }

    /** The platform protocol's ontologies (the container layer's words). */
    public static final Set<String> PLATFORM_ONTOLOGIES = Set.of("concord-discovery", "concord-lal", "concord-maintenance",
            "concord-services", "concord-network");

    /** The table as Markdown rows ({@code | service | member | key holder | foreign | console client | operator | condition |}). */
    public static List<String> table() {
        List<String> rows = new ArrayList<>();
        for (Service s : Service.values()) {
            StringBuilder b = new StringBuilder("| ").append(s.said()).append(" (`").append(s.key()).append("`) |");
            EnumSet<Principal> may = DEFAULTS.get(s);
            for (Principal p : Principal.values()) {
                boolean yes = may.contains(p);
                b.append(' ').append(yes ? "yes" : p == Principal.FOREIGN && EXPOSABLE.contains(s) ? "no (exposable)" : "no").append(" |");
            }
            b.append(' ').append(CONDITIONS.getOrDefault(s, "")).append(" |");
            rows.add(b.toString());
        }
        return rows;
    }
}
