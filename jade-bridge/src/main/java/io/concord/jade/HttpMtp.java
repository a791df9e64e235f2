package io.concord.jade;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.codec.AclParseException;
import io.concord.core.codec.StringAclCodec;
import io.concord.core.proto.MtsFailure;
import io.concord.layers.platform.Gateway;
import io.concord.layers.platform.GatewayContext;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
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

    private final String host;
    private final int port;
    private final String advertisedHost;
    private HttpServer server;
    private ExecutorService out;
    private volatile GatewayContext context;
    private final AgentManagement management = new AgentManagement(this::addresses);
    private final MtpClient client = new MtpClient();
    private volatile Trust trust = Trust.ANY;
    private final AtomicLong received = new AtomicLong();
    private final AtomicLong rejected = new AtomicLong();

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

    /**
     * Which JADE platforms the bridge talks to: their names (the part of an agent's name after
     * {@code @}, as JADE writes it: {@code 10.200.0.2:1099/JADE}) and the addresses their requests
     * come from and their ACCs are at. Empty sets trust any. A request from elsewhere, or in the name
     * of an agent of another platform, gets 403; a message to an agent of another platform, or at
     * another address, is answered with the FIPA FAILURE and never posted.
     */
    public record Trust(java.util.Set<String> platforms, java.util.Set<String> hosts) {
        public static final Trust ANY = new Trust(java.util.Set.of(), java.util.Set.of());

        public Trust {
            platforms = lower(platforms);
            hosts = lower(hosts);
        }

        private static java.util.Set<String> lower(java.util.Collection<String> in) {
            java.util.Set<String> out = new java.util.TreeSet<>();
            for (String x : in) {
                if (!x.isBlank()) {
                    out.add(x.trim().toLowerCase(java.util.Locale.ROOT));
                }
            }
            return java.util.Set.copyOf(out);
        }

        /** Why a request from that address is refused, or {@code null}. */
        String refuseFrom(String remoteHost) {
            if (hosts.isEmpty() || remoteHost != null && hosts.contains(remoteHost.toLowerCase(java.util.Locale.ROOT))) {
                return null;
            }
            return "requests from " + remoteHost + " are not trusted: this bridge talks only to " + hosts;
        }

        /** Why a message in that sender's name is refused, or {@code null}. */
        String refuseSender(AID sender) {
            if (platforms.isEmpty() || sender != null && platforms.contains(sender.platform().toLowerCase(java.util.Locale.ROOT))) {
                return null;
            }
            return "the platform " + (sender == null ? "?" : sender.platform()) + " is not trusted: this bridge talks only to "
                    + platforms;
        }

        /** True if a message may go to that agent at that URL. */
        boolean mayReach(AID receiver, String url) {
            if (!platforms.isEmpty() && !platforms.contains(receiver.platform().toLowerCase(java.util.Locale.ROOT))) {
                return false;
            }
            if (hosts.isEmpty()) {
                return true;
            }
            try {
                String h = java.net.URI.create(url).getHost();
                return h != null && hosts.contains(h.toLowerCase(java.util.Locale.ROOT));
            } catch (IllegalArgumentException e) {
                return false;
            }
        }
    }

    /** Restricts the bridge to these JADE platforms and addresses (see {@link Trust}); returns this. */
    public HttpMtp trust(Trust t) {
        this.trust = java.util.Objects.requireNonNull(t, "trust");
        return this;
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
            o.execute(client::close);
            o.shutdown();
            out = null;
        }
    }

    @Override
    public boolean reaches(AID foreign) {
        for (String a : foreign.addresses()) {
            if (a.regionMatches(true, 0, "http://", 0, 7) && trust.mayReach(foreign, a)) {
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
            java.net.InetSocketAddress remote = x.getRemoteAddress();
            String from = trust.refuseFrom(remote == null ? null : remote.getAddress().getHostAddress());
            if (from != null) {
                reply(x, 403, from);
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
            String sender = trust.refuseSender(in.message().getSender());
            if (sender != null) {
                reply(x, 403, sender);
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
                sendOut(management.answer(ctx, m, local.equalsIgnoreCase("df")), m.getSender());
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
                if (!trust.mayReach(receiver, url)) {
                    problem = url + " is not among the JADE platforms this bridge trusts";
                    continue;
                }
                try {
                    int status = client.post(url, receiver, m.getSender(), payload);
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
}
