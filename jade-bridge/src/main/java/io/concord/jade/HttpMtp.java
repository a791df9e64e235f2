package io.concord.jade;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.codec.AclParseException;
import io.concord.core.codec.StringAclCodec;
import io.concord.core.proto.MtsFailure;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.Gateway;
import io.concord.layers.platform.GatewayContext;
import io.concord.layers.platform.ServiceDescription;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The FIPA HTTP MTP (SC00084) as a {@link Gateway}: the container serves {@code http://host:port/acc},
 * accepts messages posted by JADE (or any FIPA platform) and hands them to the platform's agents by
 * name; it posts the platform agents' messages to foreign agents at their {@code http://} addresses.
 * JADE's quirks are followed: quoted boundary, the envelope part first and the payload last, the
 * mandatory {@code intended-receiver}, {@code Connection: close}, local-time dates, UTF-8 declared
 * in {@code payload-encoding}. Requests to {@code df@platform} and {@code ams@platform} in
 * {@code fipa-sl0} are answered here as JADE's DF and AMS answer them.
 */
public final class HttpMtp implements Gateway {
    private static final Logger LOG = LoggerFactory.getLogger(HttpMtp.class);
    static final int MAX_BODY = 1 << 20;
    static final String ONTOLOGY = "FIPA-Agent-Management";

    private final String host;
    private final int port;
    private final String advertisedHost;
    private HttpServer server;
    private ExecutorService out;
    private volatile GatewayContext context;
    private final Map<String, ForeignEntry> foreignRegistrations = new LinkedHashMap<>();
    private final AtomicLong received = new AtomicLong();
    private final AtomicLong rejected = new AtomicLong();

    /** An agent of another platform registered in this platform's DF. */
    record ForeignEntry(AID aid, List<ServiceDescription> services) {
    }

    /**
     * @param host the address to bind (and to advertise, unless it is 0.0.0.0)
     * @param port the port of the ACC
     */
    public HttpMtp(String host, int port) {
        this(host, port, host.equals("0.0.0.0") ? "127.0.0.1" : host);
    }

    public HttpMtp(String host, int port, String advertisedHost) {
        this.host = host;
        this.port = port;
        this.advertisedHost = advertisedHost;
    }

    @Override
    public List<String> addresses() {
        return List.of("http://" + advertisedHost + ":" + port + "/acc");
    }

    /** Requests received and accepted, and rejected with a 4xx, since start. */
    public long received() {
        return received.get();
    }

    public long rejected() {
        return rejected.get();
    }

    @Override
    public void start(GatewayContext ctx) {
        this.context = ctx;
        // The JDK's server leaves Nagle's algorithm on unless told otherwise, so a response could wait
        // for the client's delayed ACK; the setting is read when the first server of the JVM starts.
        if (System.getProperty("sun.net.httpserver.nodelay") == null) {
            System.setProperty("sun.net.httpserver.nodelay", "true");
        }
        try {
            server = HttpServer.create(new InetSocketAddress(host, port), 64);
        } catch (IOException e) {
            throw new IllegalStateException("the HTTP MTP cannot listen on " + host + ":" + port + " (" + e.getMessage()
                    + "); choose another port for the JADE bridge", e);
        }
        server.createContext("/", this::handle);
        // A thread per busy connection: JADE sends two stray bytes after each request, so the server
        // reads the next request on a kept-alive connection while JADE is silent; one thread for
        // all would stall the others. JADE keeps at most 10 sockets open.
        server.setExecutor(Executors.newCachedThreadPool(r -> daemon(r, "concord-http-in")));
        server.start();
        out = Executors.newSingleThreadExecutor(r -> daemon(r, "concord-http-out"));
        LOG.info("HTTP MTP of platform {} at {}", ctx.platformName(), addresses());
    }

    private static Thread daemon(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }

    @Override
    public void stop() {
        if (server != null) {
            server.stop(0);
            ((ExecutorService) server.getExecutor()).shutdownNow();
            server = null;
        }
        if (out != null) {
            ExecutorService o = out;
            o.execute(() -> {
                for (Connection c : connections.values()) {
                    try {
                        c.socket().close();
                    } catch (IOException ignored) {
                        // closing anyway
                    }
                }
                connections.clear();
            });
            o.shutdown();
            out = null;
        }
    }

    @Override
    public boolean reaches(AID foreign) {
        for (String a : foreign.addresses()) {
            if (a.regionMatches(true, 0, "http://", 0, 7)) {
                return true;
            }
        }
        return false;
    }

    // ---- inbound ----------------------------------------------------------------------------------

    private void handle(HttpExchange x) throws IOException {
        try (x) {
            if (!x.getRequestMethod().equalsIgnoreCase("POST")) {
                reply(x, 405, "the ACC accepts POST only");
                return;
            }
            String type = x.getRequestHeaders().getFirst("Content-Type");
            String boundary = boundaryOf(type);
            if (boundary == null) {
                reply(x, 406, "the Content-Type must be multipart/mixed with a boundary, got " + type);
                return;
            }
            byte[] body = readLimited(x.getRequestBody());
            if (body == null) {
                reply(x, 413, "the request is larger than " + MAX_BODY + " bytes");
                return;
            }
            Inbound in;
            GatewayContext at = context;
            try {
                in = parse(new String(body, StandardCharsets.ISO_8859_1), boundary);
                if (at != null) {
                    checkForeignSender(in, at.platformName());
                }
            } catch (IllegalArgumentException e) {
                reply(x, 400, e.getMessage());
                return;
            }
            received.incrementAndGet();
            reply(x, 200, null);
            GatewayContext ctx = context;
            if (ctx != null) {
                ctx.execute(() -> deliver(ctx, in));
            }
        } catch (RuntimeException e) {
            LOG.warn("HTTP MTP request failed: {}", e.toString());
        }
    }

    private void reply(HttpExchange x, int status, String problem) throws IOException {
        if (status != 200) {
            rejected.incrementAndGet();
            LOG.debug("HTTP MTP rejected a request ({}): {}", status, problem);
        }
        byte[] b = problem == null ? new byte[0] : (problem + "\n").getBytes(StandardCharsets.UTF_8);
        // Keep-alive for good requests: JADE then reuses its sockets (it keeps up to 10 per platform).
        x.getResponseHeaders().set("Connection", status == 200 ? "Keep-Alive" : "close");
        x.getResponseHeaders().set("Content-Type", "text/plain; charset=utf-8");
        x.sendResponseHeaders(status, b.length == 0 ? -1 : b.length);
        if (b.length > 0) {
            x.getResponseBody().write(b);
        }
    }

    private static byte[] readLimited(InputStream in) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        byte[] buf = new byte[8192];
        int n;
        while ((n = in.read(buf)) > 0) {
            if (b.size() + n > MAX_BODY) {
                return null;
            }
            b.write(buf, 0, n);
        }
        return b.toByteArray();
    }

    static String boundaryOf(String contentType) {
        if (contentType == null || !contentType.toLowerCase(Locale.ROOT).startsWith("multipart/mixed")) {
            return null;
        }
        int at = contentType.toLowerCase(Locale.ROOT).indexOf("boundary=");
        if (at < 0) {
            return null;
        }
        String b = contentType.substring(at + 9).trim();
        int semi = b.indexOf(';');
        if (b.startsWith("\"")) {
            int end = b.indexOf('"', 1);
            return end > 1 ? b.substring(1, end) : null;
        }
        b = semi >= 0 ? b.substring(0, semi).trim() : b;
        return b.isEmpty() ? null : b;
    }

    /** An accepted request: its envelope and its ACL message. */
    record Inbound(FipaEnvelope envelope, AclMessage message) {
    }

    /**
     * Parses a multipart body (as ISO-8859-1 text, so bytes survive): the envelope, then the payload.
     *
     * @throws IllegalArgumentException saying what is wrong
     */
    static Inbound parse(String body, String boundary) {
        List<String> parts = new ArrayList<>();
        String delim = "--" + boundary;
        int at = body.indexOf(delim);
        if (at < 0) {
            throw new IllegalArgumentException("the body never shows the boundary " + boundary);
        }
        while (true) {
            int start = at + delim.length();
            if (body.startsWith("--", start)) {
                break; // the closing delimiter
            }
            int next = body.indexOf("\r\n" + delim, start);
            int nextLf = body.indexOf("\n" + delim, start);
            int end = next >= 0 ? next : nextLf;
            if (end < 0) {
                throw new IllegalArgumentException("a multipart part is never closed by --" + boundary);
            }
            parts.add(body.substring(start, end));
            at = body.indexOf(delim, end);
        }
        if (parts.size() < 2) {
            throw new IllegalArgumentException("a FIPA message has two parts, the envelope and the payload; got " + parts.size());
        }
        String envXml = content(parts.get(0));
        FipaEnvelope env = FipaEnvelope.parse(new String(envXml.getBytes(StandardCharsets.ISO_8859_1), StandardCharsets.UTF_8));
        if (!env.aclRepresentation().equalsIgnoreCase(FipaEnvelope.STRING_REP)) {
            throw new IllegalArgumentException("only " + FipaEnvelope.STRING_REP + " payloads are understood, got "
                    + env.aclRepresentation());
        }
        Charset cs = StandardCharsets.US_ASCII;
        if (env.payloadEncoding() != null) {
            try {
                cs = Charset.forName(env.payloadEncoding());
            } catch (RuntimeException e) {
                throw new IllegalArgumentException("an unknown payload-encoding " + env.payloadEncoding());
            }
        }
        String payload = new String(content(parts.get(1)).getBytes(StandardCharsets.ISO_8859_1), cs);
        AclMessage m;
        try {
            m = StringAclCodec.INSTANCE.decode(payload.trim());
        } catch (AclParseException e) {
            throw new IllegalArgumentException("the payload is not a FIPA string ACL message: " + e.getMessage());
        }
        if (m.getSender() == null) {
            if (env.from() == null) {
                throw new IllegalArgumentException("neither the message nor the envelope names a sender");
            }
            m.setSender(env.from());
        } else if (m.getSender().addresses().isEmpty() && env.from() != null) {
            m.setSender(env.from());
        }
        return new Inbound(env, m);
    }

    /**
     * A message that comes in over HTTP comes from outside the platform: one whose sender names an
     * agent of this platform is somebody posing as it (its own agents never use this door in).
     */
    static void checkForeignSender(Inbound in, String platform) {
        AID sender = in.message().getSender();
        if (sender != null && platform.equalsIgnoreCase(sender.platform())) {
            LOG.warn("HTTP MTP refused a message in the name of {}, an agent of this platform: over HTTP only agents of "
                    + "other platforms can send", sender.name());
            throw new IllegalArgumentException("the sender " + sender.name() + " is an agent of this platform ("
                    + platform + "); a message over HTTP must come from an agent of another platform");
        }
    }

    /** The content of a part: after its headers and the blank line. */
    private static String content(String part) {
        int crlf = part.indexOf("\r\n\r\n");
        int lf = part.indexOf("\n\n");
        int cut;
        int skip;
        if (crlf >= 0 && (lf < 0 || crlf <= lf)) {
            cut = crlf;
            skip = 4;
        } else if (lf >= 0) {
            cut = lf;
            skip = 2;
        } else {
            throw new IllegalArgumentException("a multipart part has no blank line after its headers");
        }
        return part.substring(cut + skip);
    }

    /** On the loop: to the platform's agents, or answered here (DF, AMS), or a FAILURE back. */
    private void deliver(GatewayContext ctx, Inbound in) {
        AclMessage m = in.message();
        for (AID r : in.envelope().deliverTo()) {
            String local = r.localName();
            boolean ours = ctx.platformName().equalsIgnoreCase(r.platform());
            if (ours && (local.equalsIgnoreCase("df") || local.equalsIgnoreCase("ams"))) {
                answerManagement(ctx, m, local.equalsIgnoreCase("df"));
                continue;
            }
            if (!ours || !ctx.deliver(m, r)) {
                sendOut(notFound(ctx, m, r), m.getSender());
            }
        }
    }

    /** JADE's AMS FAILURE for an unknown receiver. */
    private static AclMessage notFound(GatewayContext ctx, AclMessage original, AID receiver) {
        return MtsFailure.of(ctx.platformName(), original, receiver, "Agent not found: " + receiver.name());
    }

    // ---- FIPA-Agent-Management (fipa-sl0) ---------------------------------------------------------

    private void answerManagement(GatewayContext ctx, AclMessage m, boolean df) {
        AclMessage r = m.createReply();
        r.setSender(AID.local(df ? "df" : "ams", ctx.platformName()));
        r.setLanguage(m.getLanguage() == null ? "fipa-sl0" : m.getLanguage());
        r.setOntology(ONTOLOGY);
        Sl0.Expr action;
        try {
            if (m.getPerformative() != Performative.REQUEST) {
                throw new IllegalArgumentException("the " + (df ? "DF" : "AMS") + " takes REQUESTs, not "
                        + m.getPerformative().wireName());
            }
            Sl0.Expr outer = Sl0.parse(m.getContent() == null ? "" : m.getContent());
            if (outer.items().size() != 1 || !(outer.items().get(0) instanceof Sl0.Expr a) || !a.head().equals("action")
                    || a.items().size() != 3 || !(a.items().get(2) instanceof Sl0.Expr)) {
                throw new IllegalArgumentException("expected ((action <agent-identifier> (<function> ...)))");
            }
            action = a;
        } catch (IllegalArgumentException e) {
            r.setPerformative(Performative.NOT_UNDERSTOOD);
            r.setContent("(" + Sl0.word(m.getContent() == null ? "" : m.getContent()) + " (error " + Sl0.word(e.getMessage()) + "))");
            sendOut(r, m.getSender());
            return;
        }
        Sl0.Expr fn = (Sl0.Expr) action.items().get(2);
        try {
            String content = switch (fn.head().toLowerCase(Locale.ROOT)) {
                case "search" -> "((result " + action + " (sequence " + (df ? searchDf(ctx, fn) : searchAms(ctx)) + ")))";
                case "register" -> {
                    if (!df) {
                        throw new UnsupportedOperationException("register with the AMS");
                    }
                    register(fn);
                    yield "((done " + action + "))";
                }
                case "deregister" -> {
                    if (!df) {
                        throw new UnsupportedOperationException("deregister with the AMS");
                    }
                    deregister(fn);
                    yield "((done " + action + "))";
                }
                default -> throw new UnsupportedOperationException(fn.head());
            };
            r.setPerformative(Performative.INFORM);
            r.setContent(content);
        } catch (UnsupportedOperationException e) {
            r.setPerformative(Performative.FAILURE);
            r.setContent("(" + action + " (unsupported-function " + Sl0.word(e.getMessage()) + "))");
        } catch (IllegalArgumentException e) {
            r.setPerformative(Performative.FAILURE);
            r.setContent("(" + action + " (internal-error " + Sl0.word(e.getMessage()) + "))");
        }
        sendOut(r, m.getSender());
    }

    private String searchDf(GatewayContext ctx, Sl0.Expr fn) {
        Sl0.Expr dfd = argument(fn);
        if (dfd == null || !dfd.head().equals("df-agent-description")) {
            throw new IllegalArgumentException("search needs a df-agent-description template");
        }
        List<ServiceDescription> templates = services(dfd.slot("services"));
        long max = maxResults(fn);
        StringBuilder b = new StringBuilder();
        int n = 0;
        for (AgentEntry e : ctx.agents()) {
            if (matches(e.services(), templates) && !e.services().isEmpty() && (max < 0 || n < max)) {
                b.append(n++ == 0 ? "" : " ").append(describe(new AID(e.name(), addresses().toArray(new String[0])), e.services()));
            }
        }
        for (ForeignEntry f : foreignRegistrations.values()) {
            if (matches(f.services(), templates) && (max < 0 || n < max)) {
                b.append(n++ == 0 ? "" : " ").append(describe(f.aid(), f.services()));
            }
        }
        return b.toString();
    }

    private String searchAms(GatewayContext ctx) {
        StringBuilder b = new StringBuilder();
        for (AgentEntry e : ctx.agents()) {
            b.append(b.length() == 0 ? "" : " ").append("(ams-agent-description :name ")
                    .append(aid(new AID(e.name(), addresses().toArray(new String[0])))).append(" :state active)");
        }
        return b.toString();
    }

    /** The function's first argument, if it is an expression (the df-agent-description). */
    private static Sl0.Expr argument(Sl0.Expr fn) {
        return fn.items().size() > 1 && fn.items().get(1) instanceof Sl0.Expr e ? e : null;
    }

    private static long maxResults(Sl0.Expr fn) {
        for (Object o : fn.items()) {
            if (o instanceof Sl0.Expr e && e.head().equals("search-constraints")) {
                String v = e.text("max-results");
                if (v != null) {
                    try {
                        return Long.parseLong(v);
                    } catch (NumberFormatException x) {
                        throw new IllegalArgumentException("a bad :max-results " + v);
                    }
                }
            }
        }
        return -1;
    }

    private static boolean matches(List<ServiceDescription> have, List<ServiceDescription> templates) {
        for (ServiceDescription t : templates) {
            boolean any = false;
            for (ServiceDescription s : have) {
                any |= s.matches(t);
            }
            if (!any) {
                return false;
            }
        }
        return true;
    }

    private void register(Sl0.Expr fn) {
        Sl0.Expr dfd = argument(fn);
        if (dfd == null || !(dfd.slot("name") instanceof Sl0.Expr name)) {
            throw new IllegalArgumentException("register needs a df-agent-description with a :name");
        }
        AID who = aidOf(name);
        foreignRegistrations.put(who.name().toLowerCase(Locale.ROOT), new ForeignEntry(who, services(dfd.slot("services"))));
    }

    private void deregister(Sl0.Expr fn) {
        Sl0.Expr dfd = argument(fn);
        if (dfd == null || !(dfd.slot("name") instanceof Sl0.Expr name)) {
            throw new IllegalArgumentException("deregister needs a df-agent-description with a :name");
        }
        if (foreignRegistrations.remove(aidOf(name).name().toLowerCase(Locale.ROOT)) == null) {
            throw new IllegalArgumentException("not-registered");
        }
    }

    private static AID aidOf(Sl0.Expr e) {
        if (!e.head().equals("agent-identifier") || e.text("name") == null) {
            throw new IllegalArgumentException("expected (agent-identifier :name ...)");
        }
        List<String> urls = new ArrayList<>();
        if (e.slot("addresses") instanceof Sl0.Expr seq) {
            for (Object o : seq.items().subList(1, seq.items().size())) {
                if (o instanceof Sl0.Atom a) {
                    urls.add(a.text());
                }
            }
        }
        return new AID(e.text("name"), urls.toArray(new String[0]));
    }

    private static List<ServiceDescription> services(Object set) {
        List<ServiceDescription> out = new ArrayList<>();
        if (set == null) {
            return out;
        }
        if (!(set instanceof Sl0.Expr s) || !s.head().equals("set")) {
            throw new IllegalArgumentException(":services must be a (set ...)");
        }
        for (Object o : s.items().subList(1, s.items().size())) {
            if (!(o instanceof Sl0.Expr sd) || !sd.head().equals("service-description")) {
                throw new IllegalArgumentException("a :services set holds service-descriptions");
            }
            Map<String, String> props = new LinkedHashMap<>();
            if (sd.slot("properties") instanceof Sl0.Expr ps) {
                for (Object p : ps.items().subList(1, ps.items().size())) {
                    if (p instanceof Sl0.Expr prop && prop.text("name") != null && prop.text("value") != null) {
                        props.put(prop.text("name"), prop.text("value"));
                    }
                }
            }
            out.add(new ServiceDescription(sd.text("type"), sd.text("name"), props, List.of(), List.of(), List.of()));
        }
        return out;
    }

    private static String describe(AID who, List<ServiceDescription> services) {
        StringBuilder b = new StringBuilder("(df-agent-description :name ").append(aid(who));
        if (!services.isEmpty()) {
            b.append(" :services (set");
            for (ServiceDescription s : services) {
                b.append(" (service-description");
                if (s.name() != null) {
                    b.append(" :name ").append(Sl0.word(s.name()));
                }
                if (s.type() != null) {
                    b.append(" :type ").append(Sl0.word(s.type()));
                }
                if (!s.properties().isEmpty()) {
                    b.append(" :properties (set");
                    s.properties().forEach((k, v) -> b.append(" (property :name ").append(Sl0.word(k))
                            .append(" :value ").append(Sl0.word(v)).append(')'));
                    b.append(')');
                }
                b.append(')');
            }
            b.append(')');
        }
        return b.append(')').toString();
    }

    private static String aid(AID a) {
        StringBuilder b = new StringBuilder("(agent-identifier :name ").append(Sl0.word(a.name()));
        if (!a.addresses().isEmpty()) {
            b.append(" :addresses (sequence");
            for (String u : a.addresses()) {
                b.append(' ').append(u);
            }
            b.append(')');
        }
        return b.append(')').toString();
    }

    // ---- outbound ---------------------------------------------------------------------------------

    @Override
    public void sendOut(AclMessage message, AID receiver) {
        GatewayContext ctx = context;
        ExecutorService ex = out;
        if (ctx == null || ex == null) {
            return;
        }
        AclMessage m = message.copy();
        AID sender = m.getSender();
        if (sender != null && ctx.platformName().equalsIgnoreCase(sender.platform())) {
            m.setSender(new AID(sender.name(), addresses().toArray(new String[0])));
        }
        String payload = StringAclCodec.INSTANCE.encodeToString(m);
        ex.execute(() -> {
            String problem = null;
            for (String url : receiver.addresses()) {
                if (!url.regionMatches(true, 0, "http://", 0, 7)) {
                    continue;
                }
                try {
                    int status = post(url, receiver, m.getSender(), payload);
                    if (status == 200) {
                        return;
                    }
                    problem = url + " answered " + status;
                } catch (IOException | RuntimeException e) {
                    problem = url + ": " + e.getMessage();
                }
            }
            String why = problem == null ? "no http address" : problem;
            LOG.debug("HTTP MTP could not reach {}: {}", receiver.name(), why);
            if (message.getPerformative() != Performative.FAILURE && sender != null
                    && ctx.platformName().equalsIgnoreCase(sender.platform())) {
                ctx.execute(() -> {
                    AclMessage f = MtsFailure.of(ctx.platformName(), message, receiver, "Foreign agent unreachable: " + why);
                    ctx.deliver(f, sender);
                });
            }
        });
    }

    // Kept-alive connections to other platforms' ACCs, by host:port; used by the out thread only.
    private final Map<String, Connection> connections = new java.util.HashMap<>();

    /** A socket and its buffered input: a response is read a buffer at a time, not a byte a system call. */
    private record Connection(Socket socket, InputStream in) {
        static Connection open(String host, int port) throws IOException {
            Socket s = new Socket();
            try {
                s.setTcpNoDelay(true); // one write, sent at once: no Nagle wait for a delayed ACK
                s.connect(new InetSocketAddress(host, port), 5_000);
                s.setSoTimeout(10_000);
                return new Connection(s, new java.io.BufferedInputStream(s.getInputStream(), 4096));
            } catch (IOException e) {
                s.close();
                throw e;
            }
        }
    }

    /** One POST, as JADE reads it, on a kept-alive connection when the peer allows; returns the status. */
    int post(String url, AID receiver, AID sender, String payload) throws IOException {
        URI u = URI.create(url);
        int p = u.getPort() < 0 ? 80 : u.getPort();
        byte[] request = request(url, u.getHost(), p, receiver, sender, payload);
        String key = u.getHost() + ":" + p;
        for (int attempt = 0; ; attempt++) {
            Connection c = connections.remove(key);
            boolean reused = c != null;
            if (c == null) {
                c = Connection.open(u.getHost(), p);
            }
            try {
                OutputStream o = c.socket().getOutputStream();
                o.write(request);
                o.flush();
                Response r = readResponse(c.in(), url);
                if (r.keepAlive()) {
                    connections.put(key, c);
                } else {
                    c.socket().close();
                }
                return r.status();
            } catch (IOException e) {
                c.socket().close();
                if (!reused || attempt > 0) {
                    throw e;
                }
                // the peer closed a kept-alive connection meanwhile: once more on a new one
            }
        }
    }

    private record Response(int status, boolean keepAlive) {
    }

    private static byte[] request(String url, String host, int port, AID receiver, AID sender, String payload) {
        byte[] acl = payload.getBytes(StandardCharsets.UTF_8);
        FipaEnvelope env = FipaEnvelope.forOne(receiver, sender, acl.length);
        byte[] rnd = new byte[16];
        java.util.concurrent.ThreadLocalRandom.current().nextBytes(rnd);
        String boundary = HexFormat.of().formatHex(rnd).substring(1);
        ByteArrayOutputStream body = new ByteArrayOutputStream(acl.length + 1024);
        body.writeBytes(("This is not part of the MIME multipart encoded message.\r\n--" + boundary
                + "\r\nContent-Type: application/xml\r\n\r\n" + env.toXml() + "\r\n--" + boundary
                + "\r\nContent-Type: application/text; charset=UTF-8\r\n\r\n").getBytes(StandardCharsets.UTF_8));
        body.writeBytes(acl);
        body.writeBytes(("\r\n--" + boundary + "--\r\n").getBytes(StandardCharsets.UTF_8));
        String head = "POST " + url + " HTTP/1.1\r\nCache-Control: no-cache\r\nMime-Version: 1.0\r\nHost: " + host
                + ":" + port + "\r\nContent-Type: multipart/mixed ; boundary=\"" + boundary + "\"\r\nContent-Length: "
                + body.size() + "\r\nConnection: Keep-Alive\r\n\r\n";
        ByteArrayOutputStream all = new ByteArrayOutputStream(head.length() + body.size());
        all.writeBytes(head.getBytes(StandardCharsets.US_ASCII));
        all.writeBytes(body.toByteArray());
        return all.toByteArray();
    }

    /**
     * Reads a response: the status line (after any blank lines), the headers, and the body when the
     * connection stays open: by Content-Length, or JADE's fixed HTML page, which has none.
     */
    private static Response readResponse(InputStream in, String url) throws IOException {
        String line;
        do {
            line = readLine(in);
            if (line == null) {
                throw new IOException("no HTTP status from " + url);
            }
        } while (line.isEmpty());
        if (!line.startsWith("HTTP/1.")) {
            throw new IOException("not an HTTP response from " + url + ": " + line);
        }
        String[] w = line.split(" ");
        int status = w.length > 1 ? Integer.parseInt(w[1]) : 500;
        boolean keepAlive = line.startsWith("HTTP/1.1");
        int length = -1;
        while ((line = readLine(in)) != null && !line.isEmpty()) {
            String l = line.toLowerCase(Locale.ROOT);
            if (l.startsWith("connection:")) {
                keepAlive = l.substring(11).trim().equals("keep-alive");
            } else if (l.startsWith("content-length:")) {
                length = Integer.parseInt(l.substring(15).trim());
            }
        }
        if (!keepAlive) {
            return new Response(status, false);
        }
        if (length >= 0) {
            in.readNBytes(length);
            return new Response(status, true);
        }
        // JADE's page: <html><body><h1>200 OK</h1></body></html>, without a length.
        StringBuilder b = new StringBuilder();
        int c;
        while (b.length() < 4096 && (c = in.read()) >= 0) {
            b.append((char) c);
            if (b.length() >= 7 && b.substring(b.length() - 7).equalsIgnoreCase("</html>")) {
                return new Response(status, true);
            }
        }
        return new Response(status, false);
    }

    private static String readLine(InputStream in) throws IOException {
        StringBuilder b = new StringBuilder();
        int c;
        while ((c = in.read()) >= 0) {
            if (c == '\n') {
                int n = b.length();
                return n > 0 && b.charAt(n - 1) == '\r' ? b.substring(0, n - 1) : b.toString();
            }
            b.append((char) c);
            if (b.length() > 8192) {
                throw new IOException("an HTTP header line longer than 8 KiB");
            }
        }
        return b.length() == 0 ? null : b.toString();
    }
}
