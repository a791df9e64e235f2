package io.concord.jade;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.codec.AclParseException;
import io.concord.core.codec.StringAclCodec;
import io.concord.core.layer.DropCounters;
import io.concord.core.acl.MtsFailure;
import io.concord.core.time.Clock;
import io.concord.layers.platform.Gateway;
import io.concord.layers.platform.GatewayContext;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
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
    /** Messages to foreign agents waiting to be posted; beyond, the sender is told FAILURE. */
    static final int OUT_QUEUE = 4096;

    private final String host;
    private final int port;
    private final String advertisedHost;
    private AccServer server;
    private volatile BridgeLoop loop;
    private MtpClient client;
    /** Messages given to the client and not done yet; any thread reads it to refuse past {@link #OUT_QUEUE}. */
    private final java.util.concurrent.atomic.AtomicInteger outQueued = new java.util.concurrent.atomic.AtomicInteger();
    private final AccServer.Limits limits;
    private final Clock clock;
    private final DropCounters drops = new DropCounters();
    private final java.util.Set<String> warned = java.util.concurrent.ConcurrentHashMap.newKeySet();
    private final ReplyLimit replyLimit;
    /** The bridge's own answers under way (their failure to be posted is told to nobody). */
    private final java.util.Set<AclMessage> ownAnswers = java.util.Collections.synchronizedSet(
            java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>()));
    /** The observation service's events (when an operator exposed it): the bridge's own answers' rate. */
    private final ReplyLimit observeLimit;
    /** Everything else the agents post to one host. */
    private final ReplyLimit agentLimit;
    private volatile GatewayContext context;
    private final AgentManagement management;
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
        this(host, port, advertisedHost, AccServer.Limits.DEFAULT, Clock.system());
    }

    /** ... with the server's limits, and the clock that times them and dates the envelopes sent. */
    HttpMtp(String host, int port, String advertisedHost, AccServer.Limits limits, Clock clock) {
        this.host = host;
        this.port = port;
        this.advertisedHost = advertisedHost;
        this.limits = limits;
        this.clock = clock;
        this.management = new AgentManagement(this::addresses, clock::epochMillis, AgentManagement.Limits.DEFAULT,
                (reason, why) -> drops.record("http", reason, why));
        this.replyLimit = new ReplyLimit(clock::nanoTime);
        this.observeLimit = new ReplyLimit(clock::nanoTime);
        this.agentLimit = new ReplyLimit(clock::nanoTime, ReplyLimit.AGENT_BURST, ReplyLimit.AGENT_RATE);
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

    /** What the bridge refused or gave up, by reason ({@code http-malformed}, {@code http-slow}, ...). Any thread. */
    public java.util.Map<String, Long> drops() {
        return drops.snapshot();
    }

    @Override
    public void start(GatewayContext ctx) {
        this.context = ctx;
        BridgeLoop l = BridgeLoop.of(ctx, "concord-http", clock);
        CompletableFuture<Void> started = new CompletableFuture<>();
        Runnable open = () -> {
            try {
                server = new AccServer(host, port, limits, new AccServer.Handler() {
                    @Override
                    public AccServer.Response handle(AccServer.Request request) {
                        return HttpMtp.this.handle(request);
                    }

                    @Override
                    public void dropped(String reason, java.net.InetAddress from, String why, boolean answered) {
                        count(reason, from, why, answered);
                    }
                }, clock::nanoTime, l);
                client = new MtpClient(l, clock::nanoTime);
                started.complete(null);
            } catch (RuntimeException e) {
                started.completeExceptionally(e);
            }
        };
        l.run(open);
        try {
            started.join();
        } catch (java.util.concurrent.CompletionException e) {
            l.close();
            Throwable c = e.getCause();
            if (c instanceof java.io.UncheckedIOException u) {
                throw new IllegalStateException("the HTTP MTP " + u.getMessage() + "; choose another port for the JADE bridge", u);
            }
            throw c instanceof RuntimeException r ? r : e;
        }
        loop = l;
        LOG.info("HTTP MTP of platform {} at {} ({})", ctx.platformName(), addresses(),
                l instanceof BridgeLoop.Platform ? "on the platform's loop" : "on a thread of its own");
    }

    @Override
    public void stop() {
        BridgeLoop l = loop;
        if (l == null) {
            return;
        }
        loop = null;
        Runnable close = () -> {
            server.close();
            client.close("the HTTP MTP stopped (its container is changing or the platform stops)");
        };
        l.run(close);
        l.close();
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

    /** The port served, once started (the one asked, or the one the system chose for port 0). */
    int boundPort() {
        AccServer s = server;
        return s == null ? port : s.port();
    }

    /** The server, once started: for tests of its limits. */
    AccServer server() {
        return server;
    }

    // ---- inbound ----------------------------------------------------------------------------------

    /** On the loop: checks a whole request and hands its message to its agent. */
    private AccServer.Response handle(AccServer.Request x) {
        if (!x.method().equals("POST")) {
            return refuse(x, 405, "http-malformed", "the ACC accepts POST only");
        }
        String from = trust.refuseFrom(x.remote().getHostAddress());
        if (from != null) {
            return refuse(x, 403, "http-untrusted", from);
        }
        String type = x.header("content-type");
        String boundary = MtpMultipart.boundaryOf(type);
        if (boundary == null) {
            return refuse(x, 406, "http-malformed", "the Content-Type must be multipart/mixed with a boundary, got " + type);
        }
        Inbound in;
        GatewayContext at = context;
        try {
            in = parse(new String(x.body(), StandardCharsets.ISO_8859_1), boundary);
            if (at != null) {
                checkForeignSender(in, at.platformName());
            }
        } catch (BadAcl e) {
            return refuse(x, 400, "http-bad-acl", e.getMessage());
        } catch (IllegalArgumentException e) {
            return refuse(x, 400, "http-malformed", e.getMessage());
        }
        String sender = trust.refuseSender(in.message().getSender());
        if (sender != null) {
            return refuse(x, 403, "http-untrusted", sender);
        }
        received.incrementAndGet();
        if (at != null) {
            BridgeLoop l = loop;
            if (l instanceof BridgeLoop.Platform) {
                deliver(at, in); // the agents' own loop: no hand-off
            } else {
                at.execute(() -> deliver(at, in));
            }
        }
        // Keep-alive for good requests: JADE then reuses its sockets (it keeps up to 10 per platform).
        return new AccServer.Response(200, null, true);
    }

    /** Counts a refused request and says why. */
    private AccServer.Response refuse(AccServer.Request x, int status, String reason, String problem) {
        count(reason, x.remote(), status + ": " + problem, true);
        return new AccServer.Response(status, problem, false);
    }

    /**
     * Counts what the ACC refused or closed, with its reason, and logs it at WARN the first time
     * for each address and reason (at most 1,024 such pairs; then at DEBUG). Server thread.
     */
    private void count(String reason, java.net.InetAddress from, String why, boolean answered) {
        if (answered) {
            rejected.incrementAndGet();
        }
        drops.increment(reason);
        String who = from.getHostAddress();
        if (warned.size() < 1024 && warned.add(who + " " + reason)) {
            LOG.warn("HTTP MTP refused a request from {} ({}): {}. Further refusals of {} for this reason are only counted",
                    who, reason, why, who);
        } else {
            LOG.debug("HTTP MTP refused a request from {} ({}): {}", who, reason, why);
        }
    }

    /** A request whose envelope is fine but whose ACL message does not parse. */
    static final class BadAcl extends IllegalArgumentException {
        BadAcl(String message) {
            super(message);
        }
    }

    /** An accepted request: its envelope and its ACL message. */
    record Inbound(FipaEnvelope envelope, AclMessage message) {
    }

    /**
     * Parses a multipart body ({@link MtpMultipart}, as ISO-8859-1 text, so bytes survive): the
     * envelope, then the payload.
     *
     * @throws IllegalArgumentException saying what is wrong
     */
    static Inbound parse(String body, String boundary) {
        MtpMultipart.Parts parts = MtpMultipart.decode(body, boundary);
        FipaEnvelope env = FipaEnvelope.parse(new String(MtpMultipart.bytes(parts.envelope()), StandardCharsets.UTF_8));
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
        String payload = new String(MtpMultipart.bytes(parts.payload()), cs);
        AclMessage m;
        try {
            m = StringAclCodec.INSTANCE.decode(payload.trim());
        } catch (AclParseException e) {
            throw new BadAcl("the payload is not a FIPA string ACL message: " + e.getMessage());
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

    /** On the loop: to the platform's agents, or answered here (DF, AMS), or a FAILURE back. */
    private void deliver(GatewayContext ctx, Inbound in) {
        AclMessage m = in.message();
        for (AID r : in.envelope().deliverTo()) {
            String local = r.localName();
            boolean ours = ctx.platformName().equalsIgnoreCase(r.platform());
            if (ours && (local.equalsIgnoreCase("df") || local.equalsIgnoreCase("ams"))) {
                answer(management.answer(ctx, m, local.equalsIgnoreCase("df")), m.getSender());
                continue;
            }
            String refused = ours ? ctx.refuses(m, r) : null;
            if (refused != null) {
                // Who may use what is the platform's policy (docs/security.md, "Who may do what").
                drops.record("http", "not-authorized", m.getSender().name() + " to " + r.name() + ": " + refused);
                answer(refusal(ctx, m, r, refused), m.getSender());
                continue;
            }
            if (!ours || !ctx.deliver(m, r)) {
                answer(notFound(ctx, m, r), m.getSender());
            }
        }
    }

    /**
     * Posts the bridge's own answer (a DF or AMS reply, a FAILURE) to the address a request names,
     * which anyone can choose: at most {@link ReplyLimit}'s rate to each host, so that the bridge
     * cannot be made to flood a third party. Loop.
     */
    private void answer(AclMessage reply, AID to) {
        String host = null;
        for (String a : to.addresses()) {
            if (a.regionMatches(true, 0, "http://", 0, 7)) {
                host = hostOf(a);
                break;
            }
        }
        if (host != null && !replyLimit.allow(host)) {
            drops.record("http", "http-reply-limit", "more answers to " + host + " than " + ReplyLimit.RATE
                    + " a second; the bridge answers requests naming that address only at that rate");
            return;
        }
        ownAnswers.add(reply);
        sendOut(reply, to);
    }

    /** A REFUSE in the receiver's name, saying what the policy said (as JADE's AMS refuses an unauthorised action). */
    private static AclMessage refusal(GatewayContext ctx, AclMessage original, AID receiver, String why) {
        AclMessage r = original.createReply().setPerformative(Performative.REFUSE);
        r.setSender(AID.local(receiver.localName(), ctx.platformName()));
        r.setContent("((unauthorised \"" + why.replace("\\", "\\\\").replace("\"", "\\\"") + "\"))");
        return r;
    }

    private static String hostOf(String url) {
        try {
            return java.net.URI.create(url).getHost();
        } catch (IllegalArgumentException e) {
            return url;
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
        if (ctx == null || loop == null) {
            return;
        }
        AclMessage m = message.copy();
        AID sender = m.getSender();
        if (sender != null && ctx.platformName().equalsIgnoreCase(sender.platform())) {
            m.setSender(new AID(sender.name(), addresses().toArray(new String[0])));
        }
        String payload;
        try {
            payload = StringAclCodec.INSTANCE.encodeForJade(m);
        } catch (IllegalArgumentException unwritable) {
            drops.record("http", "http-unwritable", unwritable.getMessage());
            if (warned.size() < 1024 && warned.add(receiver.platform() + " http-unwritable")) {
                LOG.warn("HTTP MTP did not send {}'s message to {}: {}. The sender is told FAILURE; further such "
                        + "messages to {} are only counted", sender == null ? "an agent" : sender.name(), receiver.name(),
                        unwritable.getMessage(), receiver.platform());
            }
            tellSender(ctx, message, receiver, unwritable.getMessage());
            return;
        }
        if (outQueued.incrementAndGet() > OUT_QUEUE) {
            outQueued.decrementAndGet();
            drops.record("http", "http-out-full", OUT_QUEUE + " messages already wait to be posted to foreign agents; "
                    + "the sender is told FAILURE");
            tellSender(ctx, message, receiver, "the bridge's queue to foreign platforms is full (" + OUT_QUEUE + " messages)");
            return;
        }
        List<String> urls = new ArrayList<>();
        String problem = null;
        for (String url : receiver.addresses()) {
            if (!url.regionMatches(true, 0, "http://", 0, 7)) {
                continue;
            }
            if (!trust.mayReach(receiver, url)) {
                problem = url + " is not among the JADE platforms this bridge trusts";
            } else {
                urls.add(url);
            }
        }
        if (urls.isEmpty()) {
            outQueued.decrementAndGet();
            tellSender(ctx, message, receiver, problem == null ? "no http address" : problem);
            return;
        }
        // Every post to a foreign host is bounded: the observation service's events as the bridge's
        // own answers, the agents' conversations far above any real one (an amplifier stops there).
        String host = hostOf(urls.get(0));
        ReplyLimit limit = io.concord.layers.authority.Policy.OBSERVE_ONTOLOGY.equals(m.getOntology()) ? observeLimit : agentLimit;
        if (host != null && !limit.allow(host)) {
            outQueued.decrementAndGet();
            drops.record("http", "http-out-limit", "more posts to " + host + " than " + limit.rate() + " a second");
            tellSender(ctx, message, receiver, "the bridge posts at most " + limit.rate() + " messages a second to " + host);
            return;
        }
        loop.run(() -> post(ctx, message, receiver, m, payload, urls, 0));
    }

    /**
     * The bytes of one POST of an ACL payload to a foreign ACC, as JADE writes it (the multipart
     * body of the XML envelope and the string ACL, with a random boundary), dated now by the
     * system's clock: what this bridge sends, for tools and benchmarks that speak to JADE the same way.
     */
    public static byte[] jadePost(String url, AID receiver, AID sender, String payload) {
        return MtpClient.request(url, receiver, sender, payload, Clock.system().epochMillis());
    }

    /** Posts to the receiver's next address; on failure tries the one after, and tells the sender when none is left. Loop. */
    private void post(GatewayContext ctx, AclMessage original, AID receiver, AclMessage m, String payload, List<String> urls, int at) {
        MtpClient c = client;
        String url = urls.get(at);
        byte[] request;
        try {
            request = MtpClient.request(url, receiver, m.getSender(), payload, clock.epochMillis());
        } catch (IllegalArgumentException e) {
            done(ctx, original, receiver, m, payload, urls, at, url + ": " + e.getMessage());
            return;
        }
        c.post(new MtpClient.Post(url, request, problem -> done(ctx, original, receiver, m, payload, urls, at, problem)));
    }

    private void done(GatewayContext ctx, AclMessage original, AID receiver, AclMessage m, String payload, List<String> urls,
                      int at, String problem) {
        if (problem == null) {
            outQueued.decrementAndGet();
            ownAnswers.remove(original);
            return;
        }
        if (at + 1 < urls.size() && loop != null) {
            post(ctx, original, receiver, m, payload, urls, at + 1);
            return;
        }
        outQueued.decrementAndGet();
        LOG.debug("HTTP MTP could not reach {}: {}", receiver.name(), problem);
        ctx.execute(() -> tellSender(ctx, original, receiver, problem));
    }

    /**
     * The FIPA FAILURE "Foreign agent unreachable" to the sender of a message that was not posted,
     * if the sender is an agent of this platform and the message is not itself a FAILURE. On the loop.
     */
    private void tellSender(GatewayContext ctx, AclMessage message, AID receiver, String why) {
        if (ownAnswers.remove(message)) {
            return;   // the bridge's own answer (a REFUSE in the receiver's name): nobody here waits for it
        }
        AID sender = message.getSender();
        if (message.getPerformative() != Performative.FAILURE && sender != null
                && ctx.platformName().equalsIgnoreCase(sender.platform())) {
            ctx.deliver(MtsFailure.of(ctx.platformName(), message, receiver, "Foreign agent unreachable: " + why), sender);
        }
    }

    /** Messages given to the client and not yet posted or given up. Any thread. */
    int outQueued() {
        return outQueued.get();
    }
}
