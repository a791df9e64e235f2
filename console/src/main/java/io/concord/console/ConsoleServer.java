package io.concord.console;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.LongSupplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The console's HTTP side: {@link HttpLoop}'s selector thread reads every request whole without
 * blocking and under its limits, then hands it to a fixed pool of workers: one per open event
 * stream (at most the hub's limit) and four for everything else. No handler touches an agent:
 * reads come from the hub's last events, the writes (a view's action, start, kill, send) are handed to the loop.
 */
final class ConsoleServer {
    static final long KEEPALIVE_MS = 2_000;
    private static final Set<String> TOPICS = Set.of("platform", "safety", "sniff", "mail");
    /** What a GET (and a HEAD) may ask for, besides the files under /api/recordings/ and /api/bench/. */
    private static final Set<String> PAGES = Set.of("/", "/index.html", "/app.js", "/style.css", "/api/events", "/api/platform",
            "/api/safety", "/api/mail", "/api/views", "/api/bench", "/api/drops", "/api/recordings", "/favicon.ico");
    /**
     * A host name (labels of letters, digits and '-'), an IPv4 address or a bracketed IPv6 one,
     * and an optional port of digits: nothing else (no user, no second colon, no path).
     */
    private static final Pattern HOST = Pattern.compile(
            "((?:[a-z0-9](?:[a-z0-9-]{0,61}[a-z0-9])?)(?:\\.[a-z0-9](?:[a-z0-9-]{0,61}[a-z0-9])?)*|\\[[0-9a-f:.]{2,45}\\])(?::([0-9]{1,5}))?",
            Pattern.CASE_INSENSITIVE);

    private final HttpLoop http;
    private final ExecutorService pool;
    private final String token;
    private final boolean open;
    private final Hub hub;
    private final Console console;
    private final ObjectMapper json = new ObjectMapper();
    private volatile boolean stopping;

    ConsoleServer(InetSocketAddress at, String token, boolean open, Hub hub, Console console) throws IOException {
        this(at, token, open, hub, console, HttpLoop.Limits.DEFAULT, System::nanoTime);
    }

    /** With the limits and the clock given: the tests' way to shorten a limit or move the time. */
    ConsoleServer(InetSocketAddress at, String token, boolean open, Hub hub, Console console, HttpLoop.Limits limits,
                  LongSupplier nanos) throws IOException {
        this.token = token;
        this.open = open;
        this.hub = hub;
        this.console = console;
        AtomicInteger n = new AtomicInteger();
        this.pool = Executors.newFixedThreadPool(console.config().maxBrowsers() + 4, r -> {
            Thread t = new Thread(r, "concord-console-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        try {
            this.http = new HttpLoop(at, limits, nanos, pool, this::handle);
        } catch (IOException e) {
            pool.shutdownNow();
            throw e;
        }
    }

    void start() {
        http.start();
    }

    void stop() {
        stopping = true;
        http.stop();
        pool.shutdownNow();
    }

    InetSocketAddress address() {
        return http.address();
    }

    /** What the server refused or closed, by reason: {@code http-<status>}, {@code http-slow}, {@code http-slow-reader}, {@code http-connections}. */
    Map<String, Long> refusals() {
        return http.refusals();
    }

    /** Closes the connections past their time by the server's clock; returns once done. For tests. */
    void sweep() throws Exception {
        http.sweep().get(10, TimeUnit.SECONDS);
    }

    /** Connections open. For tests. */
    int connections() {
        return http.connections();
    }

    private void handle(HttpLoop.Exchange x) throws IOException {
        try {
            route(x);
        } catch (RuntimeException e) {
            if (!x.answered()) {
                answer(x, 500, "text/plain", "the console failed on this request: " + e);
            }
        }
    }

    private void route(HttpLoop.Exchange x) throws IOException {
        String raw = x.rawPath();
        String rawQuery = x.rawQuery();
        Map<String, String> q;
        try {
            q = query(rawQuery);
        } catch (IllegalArgumentException e) {
            refuse(x, 400, "a malformed query: " + e.getMessage());
            return;
        }
        if (!authorized(x, q)) {
            x.setHeader("WWW-Authenticate", "Bearer realm=\"concord-console\"");
            refuse(x, 401, "this console is open on a network address: every request needs its token "
                    + "(?token=..., the Authorization: Bearer header, or the concord-token cookie), printed when it started");
            return;
        }
        String host = x.header("Host");
        if (!open && !loopbackHost(host)) {
            refuse(x, 403, "this console answers only to the names of the loopback address (Host: 127.0.0.1, localhost or [::1], "
                    + "with a port or without, nothing else)");
            return;
        }
        if (open && host != null && hostName(host) == null) {
            refuse(x, 400, "the Host header is not a host name and an optional port");
            return;
        }
        String method = x.method();
        String path = raw;
        boolean get = method.equals("GET") || method.equals("HEAD");
        if (method.equals("POST")) {
            if (path.startsWith("/api/views/")) {
                act(x, path.substring("/api/views/".length()));
            } else if (path.startsWith("/api/agents/")) {
                agentAction(x, path.substring("/api/agents/".length()));
            } else if (path.equals("/api/record/start") || path.equals("/api/record/stop")) {
                record(x, path.endsWith("start"));
            } else if (page(path)) {
                x.setHeader("Allow", "GET, HEAD");
                refuse(x, 405, path + " answers GET and HEAD; only an action may be posted: a view's at /api/views/{view}/{action}, "
                        + "the console's at /api/agents/start, /api/agents/kill, /api/agents/send, /api/record/start and /api/record/stop");
            } else {
                noSuchPage(x, path);
            }
            return;
        }
        if (action(path)) {
            x.setHeader("Allow", "POST");
            refuse(x, 405, path + " is an action: POST it, with the header X-Concord-Console: 1");
            return;
        }
        if (!get) {
            if (page(path)) {
                x.setHeader("Allow", "GET, HEAD");
                refuse(x, 405, path + " answers GET and HEAD");
            } else {
                noSuchPage(x, path);
            }
            return;
        }
        switch (path) {
            case "/", "/index.html" -> resource(x, "index.html", "text/html; charset=utf-8", q);
            case "/app.js" -> resource(x, "app.js", "text/javascript; charset=utf-8", q);
            case "/style.css" -> resource(x, "style.css", "text/css; charset=utf-8", q);
            case "/api/events" -> events(x, q);
            case "/api/platform", "/api/safety", "/api/mail" -> last(x, path.substring(5));
            case "/api/views" -> views(x);
            case "/api/bench" -> benchList(x);
            case "/api/drops" -> answer(x, 200, "application/json", json.writeValueAsString(console.drops()));
            case "/api/recordings" -> recordings(x);
            case "/favicon.ico" -> answer(x, 204, "image/x-icon", new byte[0]);   // none: not a 404 each page load
            default -> {
                if (path.startsWith("/api/recordings/")) {
                    recordingFile(x, path.substring("/api/recordings/".length()));
                } else if (path.startsWith("/api/bench/")) {
                    benchFile(x, path.substring("/api/bench/".length()));
                } else {
                    noSuchPage(x, path);
                }
            }
        }
    }

    private void noSuchPage(HttpLoop.Exchange x, String path) throws IOException {
        refuse(x, 404, "no such page: " + path + "; the console serves /, /api/events, /api/platform, "
                + "/api/safety, /api/mail, /api/views, /api/bench, /api/recordings");
    }

    /** A path a GET may ask for. */
    private static boolean page(String path) {
        return PAGES.contains(path) || path.startsWith("/api/recordings/") || path.startsWith("/api/bench/");
    }

    /** A path of an action there is: a view's, the console's, a recording's start and stop. */
    private boolean action(String path) {
        if (path.equals("/api/record/start") || path.equals("/api/record/stop")) {
            return true;
        }
        if (path.startsWith("/api/agents/")) {
            return ConsoleAgent.ACTIONS.contains(path.substring("/api/agents/".length()));
        }
        if (path.startsWith("/api/views/")) {
            String rest = path.substring("/api/views/".length());
            int slash = rest.indexOf('/');
            return slash > 0 && console.views().stream()
                    .anyMatch(v -> v.id().equals(rest.substring(0, slash)) && v.actions().contains(rest.substring(slash + 1)));
        }
        return false;
    }

    private boolean authorized(HttpLoop.Exchange x, Map<String, String> q) {
        if (token == null) {
            return true;
        }
        String given = q.get("token");
        String auth = x.header("Authorization");
        if (given == null && auth != null && auth.startsWith("Bearer ")) {
            given = auth.substring(7).trim();
        }
        if (given == null) {
            String cookies = x.header("Cookie");
            if (cookies != null) {
                for (String c : cookies.split(";")) {
                    String t = c.trim();
                    if (t.startsWith("concord-token=")) {
                        given = t.substring("concord-token=".length());
                    }
                }
            }
        }
        return given != null && MessageDigest.isEqual(given.getBytes(StandardCharsets.UTF_8), token.getBytes(StandardCharsets.UTF_8));
    }

    /**
     * The name of a {@code Host} header, in lower case, or {@code null} unless it is a host name
     * (or an IPv4 address, or a bracketed IPv6 one) and an optional port of digits, nothing else.
     */
    static String hostName(String host) {
        if (host == null) {
            return null;
        }
        Matcher m = HOST.matcher(host);
        if (!m.matches() || (m.group(2) != null && Integer.parseInt(m.group(2)) > 65535)) {
            return null;
        }
        return m.group(1).toLowerCase(Locale.ROOT);
    }

    /**
     * On loopback, a page of another site cannot reach the console through a name it controls (DNS
     * rebinding): the Host must parse ({@link #hostName}) and name 127.0.0.1, localhost or [::1].
     */
    static boolean loopbackHost(String host) {
        String h = hostName(host);
        return h != null && (h.equals("127.0.0.1") || h.equals("localhost") || h.equals("[::1]"));
    }

    private void resource(HttpLoop.Exchange x, String name, String type, Map<String, String> q) throws IOException {
        try (InputStream in = ConsoleServer.class.getResourceAsStream("web/" + name)) {
            if (in == null) {
                refuse(x, 404, "the console's " + name + " is missing from its jar");
                return;
            }
            byte[] b = in.readAllBytes();
            if (token != null && q.containsKey("token")) {
                x.addHeader("Set-Cookie", "concord-token=" + token + "; Path=/; HttpOnly; SameSite=Strict");
            }
            x.setHeader("Content-Security-Policy", "default-src 'self'; img-src 'self' data:; style-src 'self'");
            answer(x, 200, type, b);
        }
    }

    private void last(HttpLoop.Exchange x, String topic) throws IOException {
        String json = hub.last(topic);
        answer(x, 200, "application/json", json == null ? "null" : json);
    }

    private void views(HttpLoop.Exchange x) throws IOException {
        ArrayNode a = json.createArrayNode();
        for (ConsoleView v : console.views()) {
            ObjectNode o = a.addObject().put("id", v.id()).put("title", v.title());
            ArrayNode acts = o.putArray("actions");
            v.actions().forEach(acts::add);
        }
        answer(x, 200, "application/json", a.toString());
    }

    private void events(HttpLoop.Exchange x, Map<String, String> q) throws IOException {
        Set<String> topics = new LinkedHashSet<>();
        for (String t : q.getOrDefault("topics", "platform").split(",")) {
            String s = t.trim();
            if (s.isEmpty()) {
                continue;
            }
            boolean view = s.startsWith("view-") && console.views().stream().anyMatch(v -> ("view-" + v.id()).equals(s));
            if (!TOPICS.contains(s) && !view) {
                refuse(x, 400, "no such topic '" + s + "'; topics are platform, safety, sniff, mail and view-{id} of /api/views");
                return;
            }
            topics.add(s);
        }
        Set<String> sniff = new LinkedHashSet<>();
        for (String a : q.getOrDefault("sniff", "").split(",")) {
            if (!a.isBlank()) {
                if (a.length() > 256) {
                    refuse(x, 400, "an agent name in sniff is longer than 256 characters");
                    return;
                }
                sniff.add(a.trim());
            }
        }
        if (sniff.size() > ConsoleAgent.MAX_SNIFFED) {
            refuse(x, 400, "at most " + ConsoleAgent.MAX_SNIFFED + " agents may be sniffed at once, got " + sniff.size());
            return;
        }
        String conv = q.get("conversation");
        Hub.Client c = hub.open(topics, sniff, conv == null || conv.isBlank() ? null : conv);
        if (c == null) {
            refuse(x, 503, "too many browsers have the console open (" + console.config().maxBrowsers() + "); close one");
            return;
        }
        if (x.method().equals("HEAD")) {
            hub.close(c);
            x.setHeader("Cache-Control", "no-store");
            answer(x, 200, "text/event-stream; charset=utf-8", new byte[0]);
            return;
        }
        try {
            x.setHeader("Content-Type", "text/event-stream; charset=utf-8");
            x.setHeader("Cache-Control", "no-store");
            x.setHeader("X-Content-Type-Options", "nosniff");
            x.startStream(200);
            boolean on = x.send(": concord console\n\n".getBytes(StandardCharsets.UTF_8));
            while (on && !stopping && !c.closed) {
                String e = c.take(KEEPALIVE_MS);
                // Waits while the browser is behind: its own queue in the hub fills and drops (counted), the agents never wait.
                on = x.send((e == null ? ": keep-alive\n\n" : e).getBytes(StandardCharsets.UTF_8));
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            hub.close(c);
            x.endStream();
        }
    }

    private void act(HttpLoop.Exchange x, String rest) throws IOException {
        if (!fromThePage(x)) {
            return;
        }
        int slash = rest.indexOf('/');
        ConsoleView view = null;
        String action = slash < 0 ? "" : rest.substring(slash + 1);
        for (ConsoleView v : console.views()) {
            if (slash > 0 && v.id().equals(rest.substring(0, slash))) {
                view = v;
            }
        }
        if (view == null || !view.actions().contains(action)) {
            refuse(x, 404, "no such action: " + rest + "; see /api/views");
            return;
        }
        ConsoleView v = view;
        onLoop(x, params -> v.act(action, params));
    }

    /** Starting, killing and messaging agents (JADE's RMA and DummyAgent): the same guards as a view's action. */
    private void agentAction(HttpLoop.Exchange x, String action) throws IOException {
        if (!fromThePage(x)) {
            return;
        }
        if (!ConsoleAgent.ACTIONS.contains(action)) {
            refuse(x, 404, "no such action: " + action + "; the console's are " + ConsoleAgent.ACTIONS);
            return;
        }
        onLoop(x, params -> console.agentAction(action, params));
    }

    private boolean fromThePage(HttpLoop.Exchange x) throws IOException {
        if (!"1".equals(x.header("X-Concord-Console"))) {
            refuse(x, 403, "an action must carry the header X-Concord-Console: 1 (the page sends it; another site's form cannot)");
            return false;
        }
        return true;
    }

    /** An action's form parameters (the server took at most the limit's bytes, 4 KiB), or null once refused (400 malformed). */
    private Map<String, String> form(HttpLoop.Exchange x) throws IOException {
        try {
            return query(new String(x.body(), StandardCharsets.UTF_8));
        } catch (IllegalArgumentException e) {
            refuse(x, 400, "malformed form parameters: " + e.getMessage());
            return null;
        }
    }

    /** Reads the form, runs the action on the agents' loop, answers what it said (or 400 with why). */
    private void onLoop(HttpLoop.Exchange x, java.util.function.Function<Map<String, String>, String> action) throws IOException {
        Map<String, String> params = form(x);
        if (params == null) {
            return;
        }
        java.net.InetSocketAddress client = x.remote();
        params.put(ConsoleView.CLIENT, client == null ? "" : client.getAddress().getHostAddress() + ":" + client.getPort());
        CompletableFuture<String> done = new CompletableFuture<>();
        console.platform().runtime().execute(() -> {
            try {
                done.complete(action.apply(params));
            } catch (RuntimeException e) {
                done.completeExceptionally(e);
            }
        });
        try {
            String said = done.get(10, TimeUnit.SECONDS);
            answer(x, 200, "application/json", json.createObjectNode().put("ok", true).put("message", said).toString());
        } catch (java.util.concurrent.ExecutionException e) {
            if (e.getCause() instanceof IllegalArgumentException) {
                refuse(x, 400, e.getCause().getMessage());
            } else {
                answer(x, 500, "text/plain", "the action failed: " + e.getCause());
            }
        } catch (java.util.concurrent.TimeoutException e) {
            answer(x, 503, "text/plain", "the agents did not take the action within 10 s");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Starts or stops a recording: the same guards as an action; {@code name} names the file. */
    private void record(HttpLoop.Exchange x, boolean start) throws IOException {
        if (!fromThePage(x)) {
            return;
        }
        Map<String, String> params = form(x);
        if (params == null) {
            return;
        }
        try {
            String said = start ? "recording to " + console.startRecording(params.get("name")).getFileName() : console.stopRecording();
            answer(x, 200, "application/json", json.createObjectNode().put("ok", true)
                    .put("message", said == null ? "no recording was under way" : start ? said : "recorded " + said).toString());
        } catch (IllegalArgumentException e) {
            refuse(x, 400, e.getMessage());
        }
    }

    private void recordings(HttpLoop.Exchange x) throws IOException {
        Path dir = console.config().recordings();
        ObjectNode o = json.createObjectNode();
        Path now = console.recording();
        o.put("recording", now == null ? null : now.getFileName().toString());
        ArrayNode a = o.putArray("files");
        if (Files.isDirectory(dir)) {
            try (var s = Files.list(dir)) {
                for (Path p : s.sorted().toList()) {
                    String n = p.getFileName().toString();
                    if (Console.recordingName(n) && Files.isRegularFile(p)) {
                        a.addObject().put("name", n).put("bytes", Files.size(p));
                    }
                }
            }
        }
        answer(x, 200, "application/json", o.toString());
    }

    private void recordingFile(HttpLoop.Exchange x, String name) throws IOException {
        if (!Console.recordingName(name)) {
            refuse(x, 400, "a recording is named by its file name (letters, digits, . _ -, ending in .jsonl), got '" + name + "'");
            return;
        }
        Path p = console.config().recordings().resolve(name);
        if (!Files.isRegularFile(p)) {
            refuse(x, 404, "no such recording: " + name + "; see /api/recordings");
            return;
        }
        answer(x, 200, "application/x-ndjson; charset=utf-8", Files.readAllBytes(p));
    }

    private void benchList(HttpLoop.Exchange x) throws IOException {
        Path dir = console.config().reports();
        ArrayNode a = json.createArrayNode();
        if (dir != null && Files.isDirectory(dir)) {
            try (var s = Files.list(dir)) {
                s.map(p -> p.getFileName().toString()).filter(ConsoleServer::benchName).sorted().forEach(a::add);
            }
        }
        answer(x, 200, "application/json", a.toString());
    }

    static boolean benchName(String n) {
        return n.matches("[A-Za-z0-9][A-Za-z0-9._-]{0,100}") && (n.endsWith(".md") || n.endsWith(".png") || n.endsWith(".svg"));
    }

    private void benchFile(HttpLoop.Exchange x, String name) throws IOException {
        Path dir = console.config().reports();
        if (!benchName(name) || name.contains("..")) {
            refuse(x, 400, "a report is named by its file name (letters, digits, . _ -; .md, .png or .svg), got '" + name + "'");
            return;
        }
        Path p = dir == null ? null : dir.resolve(name);
        if (p == null || !Files.isRegularFile(p)) {
            refuse(x, 404, "no such report: " + name);
            return;
        }
        String type = name.endsWith(".md") ? "text/markdown; charset=utf-8" : name.endsWith(".png") ? "image/png" : "image/svg+xml";
        answer(x, 200, type, Files.readAllBytes(p));
    }

    /** Parses {@code a=1&b=2}; every key once, at most 32 of them. */
    static Map<String, String> query(String raw) {
        Map<String, String> m = new LinkedHashMap<>();
        if (raw == null || raw.isEmpty()) {
            return m;
        }
        String[] parts = raw.split("&");
        if (parts.length > 32) {
            throw new IllegalArgumentException("more than 32 parameters");
        }
        for (String p : parts) {
            if (p.isEmpty()) {
                continue;
            }
            int eq = p.indexOf('=');
            String k = URLDecoder.decode(eq < 0 ? p : p.substring(0, eq), StandardCharsets.UTF_8);
            String v = eq < 0 ? "" : URLDecoder.decode(p.substring(eq + 1), StandardCharsets.UTF_8);
            if (m.put(k, v) != null) {
                throw new IllegalArgumentException("'" + k + "' given twice");
            }
        }
        return m;
    }

    private void refuse(HttpLoop.Exchange x, int code, String why) throws IOException {
        http.count("http-" + code);
        answer(x, code, "text/plain; charset=utf-8", why + "\n");
    }

    private static void answer(HttpLoop.Exchange x, int code, String type, String body) throws IOException {
        answer(x, code, type, body.getBytes(StandardCharsets.UTF_8));
    }

    private static void answer(HttpLoop.Exchange x, int code, String type, byte[] body) throws IOException {
        x.setHeader("Content-Type", type);
        x.setHeader("X-Content-Type-Options", "nosniff");
        x.respond(code, body);
    }
}
