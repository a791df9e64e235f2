package io.concord.layers.platform;

import io.concord.core.acl.AclMessage;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The content of platform messages: plain text a sniffer shows, one command line of
 * {@code word key=value ...} then one line per agent entry. Fields are separated by spaces, and
 * every field is percent-escaped, so names and service properties may hold any character. See
 * {@code docs/wire-format.md}, "Platform messages".
 *
 * <pre>
 * entry    = name SP address SP startMs SP services
 * services = "-" | service *("," service)
 * service  = item *(";" item)      item = "t=" type | "n=" name | "p." key "=" value
 *                                         | "o=" ontology | "l=" language | "r=" protocol
 * </pre>
 */
final class Lines {
    private Lines() {
    }

    /** A platform message that says it is from another agent than its sender (whom the frame authenticated). */
    static final class NotTheSender extends IllegalArgumentException {
        NotTheSender(String message) {
            super(message);
        }
    }

    /** A parsed content: the command word, its parameters, and the entries that follow. */
    record Content(String command, Map<String, String> params, List<AgentEntry> entries) {
        String param(String key) {
            String v = params.get(key);
            if (v == null) {
                throw new IllegalArgumentException("the '" + command + "' message has no " + key + "=");
            }
            return v;
        }

        /**
         * The first entry, which must be the sender's own (every platform message that says who it
         * is from starts with it).
         *
         * @throws IllegalArgumentException if it is missing
         * @throws NotTheSender if it names another agent
         */
        AgentEntry senderEntry(AclMessage m) {
            if (entries.isEmpty()) {
                throw new IllegalArgumentException("a '" + command + "' message must carry its sender's entry first");
            }
            return spokenBy(entries.get(0), m);
        }

        /**
         * An entry that says who the message is from ({@code null} if absent), which must be its sender.
         *
         * @throws NotTheSender if it names another agent
         */
        AgentEntry spokenBy(AgentEntry e, AclMessage m) {
            if (e != null && !e.name().equals(m.getSender().name())) {
                throw new NotTheSender("a '" + command + "' message from " + m.getSender().name() + " in the name of " + e.name());
            }
            return e;
        }

        long longParam(String key) {
            try {
                return Long.parseLong(param(key));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("the '" + command + "' message has a bad " + key + "=: " + params.get(key));
            }
        }
    }

    static String escape(String s) {
        StringBuilder b = null;
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c <= ' ' || c == '%' || c == ',' || c == ';' || c == '=' || c == 127) {
                if (b == null) {
                    b = new StringBuilder(s.length() + 8).append(s, 0, i);
                }
                for (byte x : String.valueOf(c).getBytes(StandardCharsets.UTF_8)) {
                    b.append('%').append(Character.toUpperCase(Character.forDigit((x >> 4) & 15, 16)))
                            .append(Character.toUpperCase(Character.forDigit(x & 15, 16)));
                }
            } else if (b != null) {
                b.append(c);
            }
        }
        return b == null ? s : b.toString();
    }

    static String unescape(String s) {
        if (s.indexOf('%') < 0) {
            return s;
        }
        byte[] utf = s.getBytes(StandardCharsets.UTF_8);
        ByteArrayOutputStream out = new ByteArrayOutputStream(utf.length);
        for (int i = 0; i < utf.length; i++) {
            if (utf[i] == '%') {
                if (i + 2 >= utf.length) {
                    throw new IllegalArgumentException("a cut-off escape in '" + s + "'");
                }
                int hi = Character.digit(utf[i + 1], 16);
                int lo = Character.digit(utf[i + 2], 16);
                if (hi < 0 || lo < 0) {
                    throw new IllegalArgumentException("a bad escape in '" + s + "'");
                }
                out.write(hi * 16 + lo);
                i += 2;
            } else {
                out.write(utf[i]);
            }
        }
        return out.toString(StandardCharsets.UTF_8);
    }

    static void appendEntry(StringBuilder b, AgentEntry e) {
        b.append(escape(e.name())).append(' ').append(escape(e.address())).append(' ').append(e.startMs()).append(' ');
        appendServices(b, e.services());
    }

    static void appendServices(StringBuilder b, List<ServiceDescription> services) {
        if (services.isEmpty()) {
            b.append('-');
            return;
        }
        for (int i = 0; i < services.size(); i++) {
            if (i > 0) {
                b.append(',');
            }
            appendService(b, services.get(i));
        }
    }

    static void appendService(StringBuilder b, ServiceDescription s) {
        int start = b.length();
        if (s.type() != null) {
            item(b, start, "t=", s.type());
        }
        if (s.name() != null) {
            item(b, start, "n=", s.name());
        }
        s.properties().forEach((k, v) -> item(b, start, "p." + escape(k) + "=", v));
        s.ontologies().forEach(v -> item(b, start, "o=", v));
        s.languages().forEach(v -> item(b, start, "l=", v));
        s.protocols().forEach(v -> item(b, start, "r=", v));
        if (b.length() == start) {
            b.append("*");
        }
    }

    private static void item(StringBuilder b, int start, String key, String value) {
        if (b.length() > start) {
            b.append(';');
        }
        b.append(key).append(escape(value));
    }

    static List<ServiceDescription> parseServices(String field) {
        if (field.equals("-")) {
            return List.of();
        }
        List<ServiceDescription> out = new ArrayList<>();
        for (String svc : field.split(",", -1)) {
            out.add(parseService(svc));
        }
        return out;
    }

    static ServiceDescription parseService(String svc) {
        String type = null;
        String name = null;
        Map<String, String> props = new TreeMap<>();
        List<String> ont = new ArrayList<>();
        List<String> lang = new ArrayList<>();
        List<String> proto = new ArrayList<>();
        if (!svc.equals("*")) {
            for (String item : svc.split(";", -1)) {
                int eq = item.indexOf('=');
                if (eq < 1) {
                    throw new IllegalArgumentException("a service item needs key=value, got '" + item + "'");
                }
                String k = item.substring(0, eq);
                String v = unescape(item.substring(eq + 1));
                switch (k) {
                    case "t" -> type = v;
                    case "n" -> name = v;
                    case "o" -> ont.add(v);
                    case "l" -> lang.add(v);
                    case "r" -> proto.add(v);
                    default -> {
                        if (!k.startsWith("p.") || k.length() < 3) {
                            throw new IllegalArgumentException("unknown service item '" + k + "'");
                        }
                        props.put(unescape(k.substring(2)), v);
                    }
                }
            }
        }
        return new ServiceDescription(type, name, props, ont, lang, proto);
    }

    /**
     * Entries read, shared by every agent of this JVM: each agent holds the whole list, and the
     * agents of one host read the same lines; one object per line instead of one per agent (at
     * 5,000 simulated agents, 25 million entries would not fit in 14 GB). Entries are immutable.
     * Bounded: emptied when it grows past {@link #MAX_SHARED}.
     */
    private static final ConcurrentHashMap<String, AgentEntry> SHARED = new ConcurrentHashMap<>();
    static final int MAX_SHARED = 200_000;

    static AgentEntry parseEntry(String line) {
        AgentEntry known = SHARED.get(line);
        if (known != null) {
            return known;
        }
        AgentEntry e = parseEntryAfresh(line);
        if (SHARED.size() >= MAX_SHARED) {
            SHARED.clear();
        }
        SHARED.put(line, e);
        return e;
    }

    private static AgentEntry parseEntryAfresh(String line) {
        String[] f = line.split(" ", -1);
        if (f.length != 4) {
            throw new IllegalArgumentException("an agent entry has 4 fields (name address start services), got "
                    + f.length + " in '" + line + "'");
        }
        long start;
        try {
            start = Long.parseLong(f[2]);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("a bad start time '" + f[2] + "'");
        }
        String name = unescape(f[0]);
        if (name.isEmpty() || name.indexOf('@') < 1) {
            throw new IllegalArgumentException("an agent name must be local@platform, got '" + name + "'");
        }
        return new AgentEntry(name, unescape(f[1]), start, parseServices(f[3]));
    }

    /** Builds a content: the command line, then the entries. */
    static String content(String command, Map<String, ?> params, List<AgentEntry> entries) {
        StringBuilder b = new StringBuilder(64 + entries.size() * 64);
        b.append(command);
        params.forEach((k, v) -> b.append(' ').append(k).append('=').append(escape(String.valueOf(v))));
        for (AgentEntry e : entries) {
            b.append('\n');
            appendEntry(b, e);
        }
        return b.toString();
    }

    static Map<String, Object> params(Object... kv) {
        Map<String, Object> m = new LinkedHashMap<>();
        for (int i = 0; i < kv.length; i += 2) {
            m.put((String) kv[i], kv[i + 1]);
        }
        return m;
    }

    /**
     * Parses a content.
     *
     * @throws IllegalArgumentException saying what is wrong
     */
    static Content parse(String text) {
        if (text == null || text.isEmpty()) {
            throw new IllegalArgumentException("an empty platform message");
        }
        String[] lines = text.split("\n", -1);
        String[] head = lines[0].split(" ", -1);
        Map<String, String> params = new LinkedHashMap<>();
        for (int i = 1; i < head.length; i++) {
            int eq = head[i].indexOf('=');
            if (eq < 1) {
                throw new IllegalArgumentException("a parameter needs key=value, got '" + head[i] + "'");
            }
            params.put(head[i].substring(0, eq), unescape(head[i].substring(eq + 1)));
        }
        List<AgentEntry> entries = new ArrayList<>(lines.length - 1);
        for (int i = 1; i < lines.length; i++) {
            entries.add(parseEntry(lines[i]));
        }
        return new Content(head[0], params, entries);
    }
}
